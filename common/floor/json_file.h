#pragma once
// A JSON input file (zones, Nav2 route graphs) read with nlohmann_json, whose faults are
// reported at FILE:LINE:COL: malformed JSON where the parser stopped, and a fault in a
// well-formed file at the value it concerns. nlohmann keeps no positions of values, so those
// come from yaml-cpp's marks on the same text (JSON is YAML).
//
//   JsonFile file(text, "zones.json");
//   file.fail({"zones", 3, "cost"}, "cost is negative");   // zones.json:9:14: error: ...

#include "yaml_fields.h"

#include <nlohmann/json.hpp>

#include <initializer_list>
#include <string>
#include <variant>

namespace envdesign::floor {

using JsonKey = std::variant<std::size_t, std::string>;

class JsonFile {
public:
    // Parses `text`; malformed JSON throws pddl::ParseError where the parser stopped.
    JsonFile(const std::string &text, const std::string &path);

    const nlohmann::json &doc() const { return doc_; }
    const std::string &path() const { return yaml_.path(); }

    // Throws pddl::ParseError at the deepest value along `at` that exists (the file's start
    // if none does).
    [[noreturn]] void fail(std::initializer_list<JsonKey> at, const std::string &message) const;

    // doc-value `value` as a finite number within MAX_COORDINATE_M, else fail(at, ...).
    double coordinate(const nlohmann::json &value, std::initializer_list<JsonKey> at,
                      const std::string &what) const;

private:
    YamlFields yaml_;
    nlohmann::json doc_;
    YAML::Node marks_;
};

} // namespace envdesign::floor
