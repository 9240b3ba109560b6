#include "design/search/measured_floors.h"

#include "design/search/witness_bound.h"

#include <algorithm>
#include <cmath>
#include <iterator>

namespace envdesign::design::witness {

namespace {

// The modifications of `design` that are in `adding` (both ascending).
Configuration additions_of(const Configuration &design, const std::vector<int> &adding) {
    Configuration out;
    std::set_intersection(design.begin(), design.end(), adding.begin(), adding.end(),
                          std::back_inserter(out));
    return out;
}

} // namespace

std::optional<MeasuredFloor> measured_floor(const Configuration &design,
                                            const std::vector<int> &adding,
                                            const std::vector<bool> &edits_robot,
                                            const std::vector<const TaskExplicability *> &tasks,
                                            const std::vector<std::optional<double>> &robot_bounds,
                                            bool human_floors) {
    MeasuredFloor floor;
    Configuration additions = additions_of(design, adding);
    if (additions.empty())
        return std::nullopt;
    auto robot = [&](int m) { return m < static_cast<int>(edits_robot.size()) && edits_robot[m]; };
    for (int m : design)
        if (!contains(additions, m)) {
            floor.human_within.restricting.push_back(m);
            if (robot(m))
                floor.robot_within.restricting.push_back(m);
        }
    for (int e : adding)
        if (!contains(additions, e)) {
            floor.human_within.outside.push_back(e);
            if (robot(e))
                floor.robot_within.outside.push_back(e);
        }
    floor.human.resize(tasks.size());
    floor.robot.resize(tasks.size());
    for (std::size_t t = 0; t < tasks.size(); ++t) {
        const TaskExplicability *e = tasks[t];
        if (human_floors && e && e->status == ExplicabilityStatus::SOLVED &&
            std::isfinite(e->human_plan_cost))
            floor.human[t] = e->human_plan_cost;
        if (t < robot_bounds.size() && robot_bounds[t] && std::isfinite(*robot_bounds[t]))
            floor.robot[t] = robot_bounds[t];
    }
    return floor;
}

} // namespace envdesign::design::witness
