#pragma once
// Errors in input files, reported as "FILE:LINE:COL: error: MESSAGE" like a compiler does.

#include <stdexcept>
#include <string>

namespace envdesign::pddl {

struct Location {
    std::string file;
    int line = 0; // 1-based; 0 when unknown (the file as a whole: it cannot be opened)
    int column = 0;

    // "FILE:LINE:COL", or "FILE" alone when the line is not known.
    std::string to_string() const {
        if (line <= 0)
            return file;
        return file + ":" + std::to_string(line) + ":" + std::to_string(column);
    }
};

// Thrown for anything wrong with an input file: syntax, undefined names, unsupported PDDL.
class ParseError : public std::runtime_error {
public:
    ParseError(const Location &where, const std::string &message)
        : std::runtime_error(where.to_string() + ": error: " + message), location_(where),
          message_(message) {}

    const Location &location() const { return location_; }
    const std::string &message() const { return message_; }

private:
    Location location_;
    std::string message_;
};

} // namespace envdesign::pddl
