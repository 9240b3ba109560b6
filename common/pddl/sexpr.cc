#include "pddl/sexpr.h"

#include <cctype>
#include <sstream>

namespace envdesign::pddl {
namespace {

class Reader {
public:
    Reader(const std::string &text, const std::string &file) : text_(text), file_(file) {}

    SExpr read_top() {
        skip_space();
        if (at_end())
            throw ParseError(here(), "empty input: expected '(define ...)'");
        if (text_.compare(pos_, 3, "\xEF\xBB\xBF") == 0)
            throw ParseError(here(), "the file starts with a UTF-8 byte-order mark; PDDL is "
                                     "ASCII (save it without the mark)");
        if (text_[pos_] != '(')
            throw ParseError(here(), "expected '(' at the start of the file");
        SExpr top = read_list();
        skip_space();
        if (!at_end())
            throw ParseError(here(), "unexpected text after the closing parenthesis of "
                                     "the top-level expression (unbalanced parentheses?)");
        return top;
    }

private:
    bool at_end() const { return pos_ >= text_.size(); }
    Location here() const { return {file_, line_, column_}; }

    void advance() {
        if (text_[pos_] == '\n') {
            ++line_;
            column_ = 1;
        } else {
            ++column_;
        }
        ++pos_;
    }

    void skip_space() {
        while (!at_end()) {
            char c = text_[pos_];
            if (c == ';') {
                while (!at_end() && text_[pos_] != '\n')
                    advance();
            } else if (std::isspace(static_cast<unsigned char>(c))) {
                advance();
            } else {
                return;
            }
        }
    }

    SExpr read_list() {
        SExpr list;
        list.is_list = true;
        list.location = here();
        // Recursion depth is bounded so that hostile input fails cleanly, not on the stack.
        if (++depth_ > MAX_DEPTH)
            throw ParseError(list.location,
                             "parentheses nested more than " + std::to_string(MAX_DEPTH) + " deep");
        advance(); // '('
        while (true) {
            skip_space();
            if (at_end())
                throw ParseError(list.location, "unbalanced parentheses: this '(' is never closed");
            char c = text_[pos_];
            if (c == ')') {
                advance();
                --depth_;
                return list;
            }
            list.items.push_back(c == '(' ? read_list() : read_symbol());
        }
    }

    SExpr read_symbol() {
        SExpr symbol;
        symbol.location = here();
        while (!at_end()) {
            char c = text_[pos_];
            if (c == '(' || c == ')' || c == ';' || std::isspace(static_cast<unsigned char>(c)))
                break;
            // '?' always starts a variable, as in Fast Downward's translator: IPC 2002's
            // Zenotravel writes "(aircraft?a)".
            if (c == '?' && !symbol.symbol.empty())
                break;
            symbol.symbol += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
            advance();
        }
        return symbol;
    }

    static constexpr int MAX_DEPTH = 10000;
    const std::string &text_;
    int depth_ = 0;
    std::string file_;
    std::size_t pos_ = 0;
    int line_ = 1;
    int column_ = 1;
};

} // namespace

std::string SExpr::to_string() const {
    if (!is_list)
        return symbol;
    std::string out = "(";
    for (std::size_t i = 0; i < items.size(); ++i)
        out += (i ? " " : "") + items[i].to_string();
    return out + ")";
}

SExpr read_sexpr(const std::string &text, const std::string &file) {
    // A stray ')' is reported where it is, not as trailing content.
    return Reader(text, file).read_top();
}

} // namespace envdesign::pddl
