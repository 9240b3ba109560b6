#include "service/config_file.h"

#include <fstream>

namespace envdesign::service {
namespace {

bool blank(char c) { return c == ' ' || c == '\t' || c == '\r'; }

std::string trimmed(const std::string &s) {
    std::size_t begin = 0, end = s.size();
    while (begin < end && blank(s[begin]))
        ++begin;
    while (end > begin && blank(s[end - 1]))
        --end;
    return s.substr(begin, end - begin);
}

bool key_char(char c) {
    return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-' || c == '_';
}

[[noreturn]] void fail(const std::string &path, int line, std::size_t column,
                       const std::string &what) {
    throw ConfigError(path + ":" + std::to_string(line) + ":" + std::to_string(column) +
                      ": error: " + what);
}

// The value after '=': quoted, or up to a " #" comment.
std::string value_of(const std::string &rest, const std::string &path, int line,
                     std::size_t column) {
    std::string v = trimmed(rest);
    if (!v.empty() && v.front() == '"') {
        std::size_t close = v.find('"', 1);
        if (close == std::string::npos)
            fail(path, line, column, "unterminated quote");
        std::string after = trimmed(v.substr(close + 1));
        if (!after.empty() && after.front() != '#')
            fail(path, line, column, "text after the closing quote");
        return v.substr(1, close - 1);
    }
    std::size_t comment = v.find(" #");
    if (comment == std::string::npos)
        comment = v.find("\t#");
    return trimmed(v.substr(0, comment));
}

} // namespace

std::vector<ConfigSetting> read_config_file(const std::string &path) {
    std::ifstream in(path);
    if (!in)
        throw ConfigError(path + ": error: cannot read the config file");
    std::vector<ConfigSetting> settings;
    std::string text;
    for (int line = 1; std::getline(in, text); ++line) {
        std::size_t start = 0;
        while (start < text.size() && blank(text[start]))
            ++start;
        if (start == text.size() || text[start] == '#')
            continue;
        std::size_t end = start;
        while (end < text.size() && key_char(text[end]))
            ++end;
        if (end == start || text[start] == '-' || text[start] == '_') // "--x": a flag, not a name
            fail(path, line, start + 1, "expected a setting name (a flag's name, no dashes)");
        std::size_t eq = end;
        while (eq < text.size() && blank(text[eq]))
            ++eq;
        if (eq == text.size() || text[eq] != '=')
            fail(path, line, eq + 1,
                 "expected '=' after '" + text.substr(start, end - start) + "'");
        settings.push_back({text.substr(start, end - start),
                            value_of(text.substr(eq + 1), path, line, eq + 2), line,
                            static_cast<int>(start + 1)});
    }
    if (in.bad())
        throw ConfigError(path + ": error: cannot read the config file");
    return settings;
}

} // namespace envdesign::service
