#pragma once
// Reading a design problem file into its protobuf message (proto/design_problem.proto), with
// the position of every field kept for messages. Text format (*.textproto, *.txtpb, *.pbtxt
// and anything not ending in .json) goes through protobuf's TextFormat::Parser, which records
// a ParseInfoTree; JSON (*.json) goes through protobuf's JSON parser, and a small scan of the
// JSON text records where each key is (the JSON parser keeps no positions).
//
// Example:
//   SpecFile spec = read_spec_file("examples/restaurant/c-two-tasks-t10.textproto");
//   pddl::Location where = spec.at("modification[1].edit[0].remove_init");
//   // where.to_string() == "examples/.../c-two-tasks-t10.textproto:14:10"

#include "pddl/parse_error.h"
#include "spec/proto/design_problem.pb.h"

#include <memory>
#include <string>

namespace envdesign::spec {

// Where each field of one spec file is written.
class SpecLocations {
public:
    virtual ~SpecLocations();
    // `path` names a field from the top message: "task[1].probability",
    // "modification[0].edit[2].add_precondition.literal". A field that is not written
    // falls back to the nearest enclosing one, and the root to line 1, column 1.
    virtual pddl::Location locate(const std::string &path) const = 0;
};

struct SpecFile {
    std::string path;
    proto::DesignProblem message;
    std::unique_ptr<SpecLocations> locations;

    pddl::Location at(const std::string &field_path) const { return locations->locate(field_path); }
};

// Throws pddl::ParseError "PATH:LINE:COL: error: ..." when the file cannot be read ("PATH:
// error: ...", no line), is not well-formed, or names a field or enum value the message does
// not have (with the nearest name: spec_suggestions.h).
SpecFile read_spec_file(const std::string &path);

// The same from text already in memory; `path` is used for messages and the format is
// chosen by its extension.
SpecFile read_spec_text(const std::string &text, const std::string &path);

} // namespace envdesign::spec
