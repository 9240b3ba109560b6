#pragma once
// Where each key of a JSON document is written, for error messages about spec files in
// protobuf's JSON mapping (protobuf's JSON parser keeps no positions).

#include "pddl/parse_error.h"

#include <map>
#include <string>

namespace envdesign::spec {

// Maps "task[1].human_problem"-style paths to the position of the key (or, for array
// elements, of the element). Keys are converted to snake_case, so "humanProblem" and
// "human_problem" give the same path. `text` must be well-formed JSON that passed
// check_json_limits (the walk recurses once per level).
std::map<std::string, pddl::Location> index_json_positions(const std::string &text,
                                                           const std::string &file);

// Arrays and objects nested deeper than this are rejected before any recursive reader sees
// them (protobuf's JSON parser stops at 100 too).
inline constexpr int MAX_JSON_DEPTH = 100;

// Throws pddl::ParseError at the offending character when `text` nests arrays and objects
// more than MAX_JSON_DEPTH deep or has a number beyond the range of a double. A linear,
// non-recursive scan: run it before any parser so that hostile input fails cleanly.
void check_json_limits(const std::string &text, const std::string &file);

// lowerCamelCase -> snake_case ("addPrecondition" -> "add_precondition").
std::string snake_case(const std::string &name);

} // namespace envdesign::spec
