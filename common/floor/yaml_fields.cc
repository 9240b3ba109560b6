#include "yaml_fields.h"

#include <cmath>
#include <cstring>

namespace envdesign::floor {

namespace {

// yaml-cpp parses nested flow collections ([[[...]]]) and block indentation by recursion: a
// document nested deeper than any map needs is refused before it can exhaust the stack.
constexpr int MAX_FLOW_DEPTH = 64;
constexpr std::size_t MAX_INDENT = 256;

void check_nesting(const std::string &text, const std::string &path) {
    int depth = 0, line = 1, column = 0;
    char quote = 0;
    bool line_start = true, comment = false;
    std::size_t indent = 0;
    for (std::size_t i = 0; i < text.size(); ++i) {
        char c = text[i];
        ++column;
        if (c == '\n') {
            ++line, column = 0, indent = 0, line_start = true, comment = false;
            continue;
        }
        if (line_start && c == ' ' && ++indent > MAX_INDENT)
            throw pddl::ParseError({path, line, column}, "indented deeper than YAML maps need");
        line_start = line_start && c == ' ';
        if (comment)
            continue;
        if (quote) {
            if (c == '\\' && quote == '"')
                ++i, ++column;
            else if (c == quote)
                quote = 0;
        } else if ((c == '"' || c == '\'') && (i == 0 || std::strchr(" \t[{,:-\n", text[i - 1]))) {
            quote = c; // a quoted scalar starts only where a token may (not "it's")
        } else if (c == '#') {
            comment = true;
        } else if ((c == '[' || c == '{') && ++depth > MAX_FLOW_DEPTH) {
            throw pddl::ParseError({path, line, column},
                                   "nested deeper than " + std::to_string(MAX_FLOW_DEPTH));
        } else if (c == ']' || c == '}') {
            --depth;
        }
    }
}

} // namespace

YAML::Node YamlFields::load(const std::string &text) const {
    check_nesting(text, path_);
    try {
        return YAML::Load(text);
    } catch (const YAML::ParserException &e) {
        pddl::Location where{path_, e.mark.line + 1, e.mark.column + 1};
        throw pddl::ParseError(where, "malformed YAML: " + e.msg);
    }
}

pddl::Location YamlFields::at(const YAML::Node &node) const {
    YAML::Mark mark = node.IsDefined() ? node.Mark() : YAML::Mark::null_mark();
    if (mark.is_null())
        return {path_, 0, 0};
    return {path_, mark.line + 1, mark.column + 1};
}

void YamlFields::fail(const YAML::Node &node, const std::string &message) const {
    throw pddl::ParseError(at(node), message);
}

YAML::Node YamlFields::required(const YAML::Node &map, const std::string &key,
                                const std::string &what) const {
    if (!map.IsMap())
        fail(map, what + " is not a map");
    YAML::Node value = map[key];
    if (!value.IsDefined() || value.IsNull())
        fail(map, what + " has no '" + key + "'");
    return value;
}

YAML::Node YamlFields::sequence(const YAML::Node &node, const std::string &what) const {
    if (!node.IsSequence())
        fail(node, what + " is not a list");
    return node;
}

double YamlFields::number(const YAML::Node &node, const std::string &what) const {
    double value = 0;
    if (!node.IsScalar() || !YAML::convert<double>::decode(node, value))
        fail(node, what + " is not a number");
    if (!std::isfinite(value))
        fail(node, what + " is not finite");
    return value;
}

long long YamlFields::integer(const YAML::Node &node, const std::string &what) const {
    long long value = 0;
    if (!node.IsScalar() || !YAML::convert<long long>::decode(node, value))
        fail(node, what + " is not an integer");
    return value;
}

std::string YamlFields::text(const YAML::Node &node, const std::string &what) const {
    if (!node.IsScalar())
        fail(node, what + " is not a string");
    return node.Scalar();
}

bool YamlFields::boolean(const YAML::Node &node, const std::string &what) const {
    bool value = false;
    if (!node.IsScalar() || !YAML::convert<bool>::decode(node, value))
        fail(node, what + " is not true or false");
    return value;
}

YAML::Node YamlFields::parameter(const YAML::Node &params, const std::string &key) const {
    if (!params.IsDefined() || params.IsNull())
        return YAML::Node(YAML::NodeType::Undefined);
    if (!params.IsMap())
        fail(params, "the parameters are not a map");
    YAML::Node pair = params[key];
    if (!pair.IsDefined())
        return pair;
    if (!pair.IsSequence() || pair.size() != 2)
        fail(pair, "parameter '" + key + "' is not a [type, value] pair");
    return pair[1];
}

} // namespace envdesign::floor
