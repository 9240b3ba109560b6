#pragma once
// A fleet's trips named as an imported floor's tasks: from and to by vI or by a place's label
// (the rules of the tasks CSV, tasks.h find_place) -> "vI-vJ", so that a trip log written in
// the site's words feeds envdesign-arrivals and the bridge.
//
//   FloorNames names(read_floor_json("imported/"));
//   std::string why;
//   std::optional<std::string> task = names.task("pick_a", "dock", why);   // "v19-v16"

#include "floor.h"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>

namespace envdesign::floor {

class FloorNames {
public:
    // `floor` is a floor.json (floor_draw.h read_floor_json). Throws FloorError when a place
    // lacks its vertex number or name.
    explicit FloorNames(const nlohmann::json &floor);

    // The task's name, or nullopt with `why` set: a place that is not there, a label two
    // places share, or from = to.
    std::optional<std::string> task(const std::string &from, const std::string &to,
                                    std::string &why) const;

private:
    Floor floor_; // the places only
};

} // namespace envdesign::floor
