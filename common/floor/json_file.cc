#include "json_file.h"

#include "floor.h"
#include "pddl/text_location.h"

#include <cmath>

namespace envdesign::floor {

JsonFile::JsonFile(const std::string &text, const std::string &path) : yaml_(path) {
    try {
        doc_ = nlohmann::json::parse(text);
    } catch (const nlohmann::json::parse_error &e) {
        // e.what() is "[json.exception...] parse error at line L, column C: WHY": keep WHY.
        std::string why = e.what();
        std::size_t colon = why.find(": ", why.find("column"));
        why = colon == std::string::npos ? why : why.substr(colon + 2);
        throw pddl::ParseError(pddl::location_of_byte(text, e.byte ? e.byte - 1 : 0, path),
                               "malformed JSON: " + why);
    } catch (const nlohmann::json::exception &e) { // a number too large for a double
        std::string why = e.what();
        std::size_t bracket = why.find("] ");
        throw pddl::ParseError({path, 1, 1},
                               "malformed JSON: " +
                                   (bracket == std::string::npos ? why : why.substr(bracket + 2)));
    }
    if (text.size() > MAX_MAP_FILE_BYTES) // marks would cost too much memory: no positions
        return;
    try {
        marks_ = yaml_.load(text);
    } catch (const pddl::ParseError &) { // positions unknown; faults are still named
    }
}

void JsonFile::fail(std::initializer_list<JsonKey> at, const std::string &message) const {
    // reset() rebinds; operator= would write through to the document.
    YAML::Node node;
    node.reset(marks_);
    for (const JsonKey &key : at) {
        YAML::Node next;
        if (auto *index = std::get_if<std::size_t>(&key);
            index && node.IsSequence() && *index < node.size())
            next = node[*index];
        else if (auto *name = std::get_if<std::string>(&key);
                 name && node.IsMap() && node[*name].IsDefined())
            next = node[*name];
        else
            break;
        node.reset(next);
    }
    pddl::Location where = yaml_.at(node);
    if (where.line == 0)
        where = {path(), 1, 1};
    throw pddl::ParseError(where, message);
}

double JsonFile::coordinate(const nlohmann::json &value, std::initializer_list<JsonKey> at,
                            const std::string &what) const {
    if (!value.is_number())
        fail(at, what + " is not a number");
    double v = value.get<double>();
    if (!std::isfinite(v) || std::abs(v) > MAX_COORDINATE_M)
        fail(at, what + " is not a finite number within 1e6");
    return v;
}

} // namespace envdesign::floor
