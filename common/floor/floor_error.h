#pragma once
// Failures of a floor import that are no single file's fault (a floor too large to import,
// no task left): bad input all the same, exit code 2 in the CLI. Faults in a file are
// pddl::ParseError at FILE:LINE:COL instead.

#include <stdexcept>
#include <string>

namespace envdesign::floor {

class FloorError : public std::runtime_error {
public:
    explicit FloorError(const std::string &message) : std::runtime_error(message) {}
};

} // namespace envdesign::floor
