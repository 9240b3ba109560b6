#include "floor_names.h"

#include "floor_error.h"
#include "tasks.h"

namespace envdesign::floor {

FloorNames::FloorNames(const nlohmann::json &floor) {
    try {
        for (const auto &p : floor.at("places")) {
            Place place;
            place.vertex = p.at("vertex").get<int>();
            place.name = p.at("name").get<std::string>();
            floor_.places.push_back(place);
        }
    } catch (const nlohmann::json::exception &e) {
        throw FloorError(std::string("floor.json has no usable places: ") + e.what());
    }
}

std::optional<std::string> FloorNames::task(const std::string &from, const std::string &to,
                                            std::string &why) const {
    std::optional<int> a = find_place(floor_, from, why);
    if (!a)
        return std::nullopt;
    std::optional<int> b = find_place(floor_, to, why);
    if (!b)
        return std::nullopt;
    if (*a == *b) {
        why = "from and to are the same place, " + object_name(*a);
        return std::nullopt;
    }
    return object_name(*a) + "-" + object_name(*b);
}

} // namespace envdesign::floor
