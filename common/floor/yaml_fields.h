#pragma once
// Typed access to the fields of a YAML document that fail with the place of the field:
// every failure is a pddl::ParseError at FILE:LINE:COL of the node at fault (yaml-cpp's
// Mark, 0-based, reported 1-based), so that a user goes straight to the line.

#include "pddl/parse_error.h"

#include <yaml-cpp/yaml.h>

#include <string>

namespace envdesign::floor {

class YamlFields {
public:
    explicit YamlFields(std::string path) : path_(std::move(path)) {}

    // The document in `text`; malformed YAML fails at the parser's mark.
    YAML::Node load(const std::string &text) const;

    pddl::Location at(const YAML::Node &node) const;
    [[noreturn]] void fail(const YAML::Node &node, const std::string &message) const;

    // map[key], which must be there; `map` must be a map (`what` names it in messages).
    YAML::Node required(const YAML::Node &map, const std::string &key,
                        const std::string &what) const;
    YAML::Node sequence(const YAML::Node &node, const std::string &what) const;
    double number(const YAML::Node &node, const std::string &what) const; // finite
    long long integer(const YAML::Node &node, const std::string &what) const;
    std::string text(const YAML::Node &node, const std::string &what) const;
    bool boolean(const YAML::Node &node, const std::string &what) const;

    // The value of a traffic-editor parameter `params[key]`, written `[type, value]`; an
    // undefined node if `params` has no `key`.
    YAML::Node parameter(const YAML::Node &params, const std::string &key) const;

    const std::string &path() const { return path_; }

private:
    std::string path_;
};

} // namespace envdesign::floor
