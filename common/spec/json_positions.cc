#include "spec/json_positions.h"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>

namespace envdesign::spec {
namespace {

// Line and column (UTF-8 characters, not bytes) over a walk through JSON text.
class JsonCursor {
protected:
    JsonCursor(const std::string &text, const std::string &file) : text_(text), file_(file) {}

    bool at_end() const { return pos_ >= text_.size(); }
    char peek() const { return at_end() ? '\0' : text_[pos_]; }
    pddl::Location here() const { return {file_, line_, column_}; }

    void advance() {
        if (text_[pos_] == '\n') {
            ++line_;
            column_ = 1;
        } else if ((static_cast<unsigned char>(text_[pos_]) & 0xC0) != 0x80) {
            ++column_;
        }
        ++pos_;
    }

    const std::string &text_;
    std::string file_;
    std::size_t pos_ = 0;
    int line_ = 1;
    int column_ = 1;
};

// A walk over well-formed JSON that records positions; values are skipped, not decoded.
class PositionScanner : JsonCursor {
public:
    PositionScanner(const std::string &text, const std::string &file,
                    std::map<std::string, pddl::Location> &out)
        : JsonCursor(text, file), out_(out) {}

    void scan() {
        skip_space();
        value("");
    }

private:
    void skip_space() {
        while (!at_end() && std::isspace(static_cast<unsigned char>(peek())))
            advance();
    }

    void value(const std::string &path) {
        if (peek() == '{')
            object(path);
        else if (peek() == '[')
            array(path);
        else if (peek() == '"')
            string();
        else
            while (!at_end() && std::string_view(",]} \t\r\n").find(peek()) == std::string::npos)
                advance();
    }

    std::string string() {
        std::string s;
        advance(); // '"'
        while (!at_end() && peek() != '"') {
            if (peek() == '\\')
                advance();
            s += peek();
            advance();
        }
        if (!at_end())
            advance();
        return s;
    }

    void object(const std::string &path) {
        advance(); // '{'
        for (skip_space(); !at_end() && peek() != '}'; skip_space()) {
            if (peek() == ',') {
                advance();
                continue;
            }
            pddl::Location where = here();
            std::string key = snake_case(string());
            std::string child = path.empty() ? key : path + "." + key;
            out_[child] = where; // a duplicate key: the later one, the one protobuf met last
            skip_space();
            if (peek() == ':')
                advance();
            skip_space();
            value(child);
        }
        if (!at_end())
            advance();
    }

    void array(const std::string &path) {
        advance(); // '['
        int index = 0;
        for (skip_space(); !at_end() && peek() != ']'; skip_space()) {
            if (peek() == ',') {
                advance();
                continue;
            }
            std::string element = path + "[" + std::to_string(index++) + "]";
            out_.emplace(element, here());
            value(element);
        }
        if (!at_end())
            advance();
    }

    std::map<std::string, pddl::Location> &out_;
};

// A linear walk that checks nesting depth and number range before any parser runs.
class LimitScanner : JsonCursor {
public:
    LimitScanner(const std::string &text, const std::string &file) : JsonCursor(text, file) {}

    void scan() {
        int depth = 0;
        while (pos_ < text_.size()) {
            char c = text_[pos_];
            if (c == '"') {
                skip_string();
            } else if (c == '[' || c == '{') {
                if (++depth > MAX_JSON_DEPTH)
                    throw pddl::ParseError(here(), "arrays and objects nested more than " +
                                                       std::to_string(MAX_JSON_DEPTH) + " deep");
                advance();
            } else if (c == ']' || c == '}') {
                --depth;
                advance();
            } else if (c == '-' || std::isdigit(static_cast<unsigned char>(c))) {
                number();
            } else {
                advance();
            }
        }
    }

private:
    void skip_string() {
        advance(); // '"'
        while (pos_ < text_.size() && text_[pos_] != '"') {
            if (text_[pos_] == '\\' && pos_ + 1 < text_.size())
                advance();
            advance();
        }
        if (pos_ < text_.size())
            advance();
    }

    void number() {
        pddl::Location start = here();
        std::string token;
        while (pos_ < text_.size() &&
               std::string_view("+-.0123456789eE").find(text_[pos_]) != std::string::npos) {
            token += text_[pos_];
            advance();
        }
        errno = 0;
        double value = std::strtod(token.c_str(), nullptr);
        if (std::isinf(value) || (errno == ERANGE && std::abs(value) > 1))
            throw pddl::ParseError(start, "the number " + token.substr(0, 40) +
                                              " is beyond the range of a double");
    }
};

} // namespace

void check_json_limits(const std::string &text, const std::string &file) {
    LimitScanner(text, file).scan();
}

std::string snake_case(const std::string &name) {
    std::string out;
    for (char c : name) {
        if (std::isupper(static_cast<unsigned char>(c))) {
            out += '_';
            out += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        } else {
            out += c;
        }
    }
    return out;
}

std::map<std::string, pddl::Location> index_json_positions(const std::string &text,
                                                           const std::string &file) {
    std::map<std::string, pddl::Location> out;
    PositionScanner(text, file, out).scan();
    return out;
}

} // namespace envdesign::spec
