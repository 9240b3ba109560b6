#include "zones.h"

#include "floor.h"
#include "json_file.h"

#include "pddl/input_file.h"
#include "pddl/parse_error.h"

#include <set>

namespace envdesign::floor {

namespace {

using nlohmann::json;

bool known_type(const std::string &type) { return type == "BLOCKED" || type == "LINE_GUIDED"; }

std::vector<Point> polygon(const JsonFile &file, std::size_t i, const json &zone) {
    if (!zone.contains("vertices") || !zone["vertices"].is_array() || zone["vertices"].size() < 3)
        file.fail({"zones", i, "vertices"},
                  "zone " + std::to_string(i) + ": 'vertices' is not a list of at least 3 points");
    std::vector<Point> corners;
    for (std::size_t k = 0; k < zone["vertices"].size(); ++k) {
        const json &v = zone["vertices"][k];
        if (!v.is_object() || !v.contains("x") || !v.contains("y"))
            file.fail({"zones", i, "vertices", k},
                      "zone " + std::to_string(i) + ": a vertex is not {\"x\": m, \"y\": m}");
        corners.push_back({file.coordinate(v["x"], {"zones", i, "vertices", k, "x"}, "x"),
                           file.coordinate(v["y"], {"zones", i, "vertices", k, "y"}, "y")});
    }
    return corners;
}

std::string text_field(const JsonFile &file, std::size_t i, const json &zone,
                       const std::string &key) {
    if (!zone.contains(key) || !zone[key].is_string() || zone[key].get<std::string>().empty())
        file.fail({"zones", i, key}, "zone " + std::to_string(i) + ": no " + key + " string");
    return zone[key].get<std::string>();
}

Zone read_zone(const JsonFile &file, std::size_t i, const json &zone, std::string &type) {
    if (!zone.is_object())
        file.fail({"zones", i}, "zone " + std::to_string(i) + ": a zone is not an object");
    Zone z;
    z.id = text_field(file, i, zone, "zoneId");
    if (std::string why = name_problem(z.id); !why.empty())
        file.fail({"zones", i, "zoneId"}, "zone " + std::to_string(i) + ": its zoneId " + why);
    type = text_field(file, i, zone, "zoneType");
    z.type = type == "LINE_GUIDED" ? ZoneType::LINE_GUIDED : ZoneType::BLOCKED;
    if (!known_type(type))
        return z;
    z.polygon = polygon(file, i, zone);
    if (!zone.contains("cost"))
        file.fail({"zones", i}, "zone " + std::to_string(i) + ": zone '" + z.id + "' has no cost");
    z.cost = file.coordinate(zone["cost"], {"zones", i, "cost"}, "cost");
    if (z.cost < 0)
        file.fail({"zones", i, "cost"}, "zone " + std::to_string(i) + ": cost is negative");
    return z;
}

} // namespace

std::vector<Zone> read_zones(const std::string &path, std::vector<std::string> &warnings) {
    return parse_zones(pddl::read_input_file(path, MAX_MAP_FILE_BYTES), path, warnings);
}

std::vector<Zone> parse_zones(const std::string &text, const std::string &path,
                              std::vector<std::string> &warnings) {
    JsonFile file(text, path);
    const json &doc = file.doc();
    if (!doc.is_object() || !doc.contains("zones") || !doc["zones"].is_array())
        file.fail({}, "a zone file is {\"zones\": [...]}");
    std::vector<Zone> zones;
    std::set<std::string> ids;
    for (std::size_t i = 0; i < doc["zones"].size(); ++i) {
        std::string type;
        Zone z = read_zone(file, i, doc["zones"][i], type);
        if (!ids.insert(z.id).second)
            file.fail({"zones", i, "zoneId"},
                      "zone " + std::to_string(i) + ": zoneId '" + z.id + "' is given twice");
        if (!known_type(type)) {
            warnings.push_back(path + ": zone '" + z.id + "' of type " + type +
                               " skipped (only BLOCKED and LINE_GUIDED zones are candidates)");
            continue;
        }
        zones.push_back(z);
    }
    return zones;
}

} // namespace envdesign::floor
