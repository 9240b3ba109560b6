#pragma once
// A spec file and the PDDL files it names -> one spec_t to send (the client library, the
// bridge). This part of the spec module is built apart (envdesign_spec_files: pddl's file
// reader, nlohmann::json, no protobuf) so that the shared client library links it without
// the design engine: a small scanner finds the path fields of the text format (robot_domain,
// human_domain, task.problem, task.human_problem) and nlohmann::json those of a JSON spec.
// The coordinator checks everything else exactly as a local run does (spec_message.h).

#include "envdesign/spec_t.hpp"

#include <string>
#include <vector>

namespace envdesign::spec {

struct NamedPath {
    std::string field; // "robot_domain", "task[1].problem"
    std::string path;  // as written
    int line = 1;
    int column = 1;
};

// The path fields of a spec's text; `json` picks the format.
std::vector<NamedPath> named_paths(const std::string &text, bool json);

// Throws pddl::ParseError ("FILE:LINE:COL: error: ...", the position of the field naming the
// file) when the spec or a file it names cannot be read.
envdesign::spec_t bundle_spec(const std::string &spec_path);

} // namespace envdesign::spec
