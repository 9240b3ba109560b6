#pragma once
// A spec file and the PDDL files it names -> one spec_t to send. The client does not link
// the design engine: a small scanner finds the path fields of the text format (robot_domain,
// human_domain, task.problem, task.human_problem) and nlohmann::json those of a JSON spec.
// The coordinator checks everything else exactly as a local run does.

#include "envdesign/spec_t.hpp"

#include <stdexcept>
#include <string>
#include <vector>

namespace envdesign::client {

// A problem with the spec on the client's side: "FILE:LINE:COL: error: ...".
class SpecError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

struct NamedPath {
    std::string field; // "robot_domain", "task[1].problem"
    std::string path;  // as written
    int line = 1;
    int column = 1;
};

// The path fields of a spec's text; `json` picks the format.
std::vector<NamedPath> named_paths(const std::string &text, bool json);

// Throws SpecError when the spec or a file it names cannot be read.
envdesign::spec_t bundle_spec(const std::string &spec_path);

} // namespace envdesign::client
