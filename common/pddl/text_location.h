#pragma once
// The FILE:LINE:COL of a byte of a text, for parsers (JSON) that report byte offsets.

#include "pddl/parse_error.h"

#include <cstddef>
#include <string>

namespace envdesign::pddl {

inline Location location_of_byte(const std::string &text, std::size_t byte,
                                 const std::string &file) {
    Location where{file, 1, 1};
    for (std::size_t i = 0; i < byte && i < text.size(); ++i) {
        if (text[i] == '\n') {
            ++where.line;
            where.column = 1;
        } else {
            ++where.column;
        }
    }
    return where;
}

} // namespace envdesign::pddl
