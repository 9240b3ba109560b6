#pragma once
// S-expressions with source locations: the first layer of the PDDL reader.
// Symbols are lower-cased (PDDL is case-insensitive); ';' starts a comment.

#include "pddl/parse_error.h"

#include <string>
#include <vector>

namespace envdesign::pddl {

struct SExpr {
    bool is_list = false;
    std::string symbol;       // when !is_list
    std::vector<SExpr> items; // when is_list
    Location location;        // of the symbol or the opening parenthesis

    bool is_symbol(const std::string &s) const { return !is_list && symbol == s; }
    // True for a list whose first item is the symbol `head`.
    bool has_head(const std::string &head) const {
        return is_list && !items.empty() && items[0].is_symbol(head);
    }
    std::string to_string() const;
};

// Reads exactly one top-level list from `text`; `file` is used for locations only.
// Throws ParseError on unbalanced parentheses or trailing content.
SExpr read_sexpr(const std::string &text, const std::string &file);

} // namespace envdesign::pddl
