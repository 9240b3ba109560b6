#include "zones.h"

#include "floor.h"
#include "yaml_fields.h"

#include "pddl/input_file.h"
#include "pddl/parse_error.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <set>

namespace envdesign::floor {

namespace {

using nlohmann::json;

// FILE:LINE:COL of a byte offset.
pddl::Location location_of(const std::string &text, const std::string &path, std::size_t byte) {
    pddl::Location where{path, 1, 1};
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

// nlohmann keeps no positions of values, so faults in a well-formed file are placed with
// yaml-cpp's marks: JSON is YAML, and the file has already parsed as JSON.
class ZoneFile {
public:
    ZoneFile(const std::string &text, const std::string &path) : yaml_(path) {
        try {
            marks_ = yaml_.load(text);
        } catch (const pddl::ParseError &) { // positions unknown; the fault is still named
        }
    }

    [[noreturn]] void fail(std::size_t zone, const char *key, const std::string &message) const {
        YAML::Node node;
        if (marks_.IsMap() && marks_["zones"].IsSequence() && zone < marks_["zones"].size()) {
            node = marks_["zones"][zone];
            if (key && node.IsMap() && node[key].IsDefined())
                node = node[key];
        }
        throw pddl::ParseError(yaml_.at(node), "zone " + std::to_string(zone) + ": " + message);
    }

    double number(const json &value, std::size_t zone, const char *key,
                  const std::string &what) const {
        if (!value.is_number())
            fail(zone, key, what + " is not a number");
        double v = value.get<double>();
        if (!std::isfinite(v) || std::abs(v) > MAX_COORDINATE_M)
            fail(zone, key, what + " is not a finite number within 1e6");
        return v;
    }

private:
    YamlFields yaml_;
    YAML::Node marks_;
};

ZoneType zone_type(const ZoneFile &file, std::size_t i, const json &zone, bool &known,
                   std::string &name) {
    if (!zone.contains("zoneType") || !zone["zoneType"].is_string())
        file.fail(i, "zoneType", "no zoneType string");
    name = zone["zoneType"].get<std::string>();
    known = name == "BLOCKED" || name == "LINE_GUIDED";
    return name == "LINE_GUIDED" ? ZoneType::LINE_GUIDED : ZoneType::BLOCKED;
}

std::vector<Point> polygon(const ZoneFile &file, std::size_t i, const json &zone) {
    if (!zone.contains("vertices") || !zone["vertices"].is_array() || zone["vertices"].size() < 3)
        file.fail(i, "vertices", "'vertices' is not a list of at least 3 points");
    std::vector<Point> corners;
    for (const auto &v : zone["vertices"]) {
        if (!v.is_object() || !v.contains("x") || !v.contains("y"))
            file.fail(i, "vertices", "a vertex is not {\"x\": metres, \"y\": metres}");
        corners.push_back(
            {file.number(v["x"], i, "vertices", "x"), file.number(v["y"], i, "vertices", "y")});
    }
    return corners;
}

Zone read_zone(const ZoneFile &file, std::size_t i, const json &zone, bool &known,
               std::string &type_name) {
    if (!zone.is_object())
        file.fail(i, nullptr, "a zone is not an object");
    Zone z;
    if (!zone.contains("zoneId") || !zone["zoneId"].is_string() ||
        zone["zoneId"].get<std::string>().empty())
        file.fail(i, "zoneId", "no zoneId string");
    z.id = zone["zoneId"].get<std::string>();
    z.type = zone_type(file, i, zone, known, type_name);
    if (!known)
        return z;
    z.polygon = polygon(file, i, zone);
    if (!zone.contains("cost"))
        file.fail(i, nullptr, "zone '" + z.id + "' has no cost");
    z.cost = file.number(zone["cost"], i, "cost", "cost");
    if (z.cost < 0)
        file.fail(i, "cost", "cost is negative");
    return z;
}

} // namespace

std::vector<Zone> read_zones(const std::string &path, std::vector<std::string> &warnings) {
    return parse_zones(pddl::read_input_file(path), path, warnings);
}

std::vector<Zone> parse_zones(const std::string &text, const std::string &path,
                              std::vector<std::string> &warnings) {
    json doc;
    try {
        doc = json::parse(text);
    } catch (const json::parse_error &e) {
        // e.what() is "[json.exception...] parse error at line L, column C: WHY": keep WHY.
        std::string why = e.what();
        std::size_t colon = why.find(": ", why.find("column"));
        why = colon == std::string::npos ? why : why.substr(colon + 2);
        throw pddl::ParseError(location_of(text, path, e.byte ? e.byte - 1 : 0),
                               "malformed JSON: " + why);
    }
    ZoneFile file(text, path);
    if (!doc.is_object() || !doc.contains("zones") || !doc["zones"].is_array())
        throw pddl::ParseError({path, 1, 1}, "a zone file is {\"zones\": [...]}");
    std::vector<Zone> zones;
    std::set<std::string> ids;
    for (std::size_t i = 0; i < doc["zones"].size(); ++i) {
        bool known = false;
        std::string type;
        Zone z = read_zone(file, i, doc["zones"][i], known, type);
        if (!ids.insert(z.id).second)
            file.fail(i, "zoneId", "zoneId '" + z.id + "' is given twice");
        if (!known) {
            warnings.push_back(path + ": zone '" + z.id + "' of type " + type +
                               " skipped (only BLOCKED and LINE_GUIDED zones are candidates)");
            continue;
        }
        zones.push_back(z);
    }
    return zones;
}

} // namespace envdesign::floor
