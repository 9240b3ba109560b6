#include "pddl/sexpr.h"

#include <cctype>
#include <optional>
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
            line_start_ = pos_ + 1;
            line_indent_ = -1;
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
        const int indent = indentation();
        // Recursion depth is bounded so that hostile input fails cleanly, not on the stack.
        if (++depth_ > MAX_DEPTH)
            throw ParseError(list.location,
                             "parentheses nested more than " + std::to_string(MAX_DEPTH) + " deep");
        advance(); // '('
        while (true) {
            skip_space();
            if (at_end())
                throw never_closed(list.location);
            char c = text_[pos_];
            if (c == ')') {
                advance();
                --depth_;
                return list;
            }
            note_suspect(list, indent);
            list.items.push_back(c == '(' ? read_list() : read_symbol());
        }
    }

    // The spaces and tabs that start the current line; computed once a line (a hostile file
    // may be one line of megabytes).
    int indentation() const {
        if (line_indent_ < 0) {
            std::size_t first = text_.find_first_not_of(" \t", line_start_);
            line_indent_ =
                static_cast<int>((first == std::string::npos ? text_.size() : first) - line_start_);
        }
        return line_indent_;
    }

    bool first_on_its_line() const {
        return pos_ == line_start_ + static_cast<std::size_t>(indentation());
    }

    // The next item of `list` (opened on a line indented `indent`) where a ')' may be
    // missing: a section "(:..." inside anything but the top level (sections belong to
    // define), or an item starting a line no deeper than the line that opened `list`. The
    // top level is left out of the second rule: "(define" often has its sections at column 1.
    // Only the first place counts; it is used only if the parentheses do not balance.
    void note_suspect(const SExpr &list, int indent) {
        if (suspect_ || depth_ < 2)
            return;
        bool section = text_.compare(pos_, 2, "(:") == 0;
        bool outdented =
            list.location.line < line_ && first_on_its_line() && indentation() <= indent;
        if (!section && !outdented)
            return;
        std::string head = list.items.empty() ? "(" : "(" + list.items[0].to_string();
        suspect_ = Suspect{here(), list.location, head, section};
    }

    // At the end of the text, with `innermost` still open: where a ')' is most likely
    // missing, if the layout says so, else at the '(' that is never closed.
    ParseError never_closed(const Location &innermost) const {
        if (!suspect_)
            return ParseError(innermost, "unbalanced parentheses: this '(' is never closed");
        const Suspect &s = *suspect_;
        std::string open =
            "'" + s.head + "' (opened at line " + std::to_string(s.opened.line) + ") is still open";
        if (s.section)
            return ParseError(s.at, "missing ')' before this section: " + open +
                                        ", and a section belongs directly in (define ...)");
        return ParseError(s.at, "missing ')' before this line: " + open +
                                    ", though this line is indented no deeper than that one");
    }

    struct Suspect {
        Location at;     // the item that should not be inside the list
        Location opened; // the list's '('
        std::string head;
        bool section = false;
    };

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
    std::optional<Suspect> suspect_;
    std::size_t line_start_ = 0;
    mutable int line_indent_ = -1;
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
