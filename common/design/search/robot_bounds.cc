#include "design/search/robot_bounds.h"

#include <algorithm>
#include <iterator>

namespace envdesign::design {

void RobotBoundMemory::remember(const Configuration &configuration,
                                const std::vector<std::optional<double>> &bounds) {
    if (std::any_of(bounds.begin(), bounds.end(), [](const auto &b) { return b.has_value(); }))
        known_.insert_or_assign(configuration, bounds);
}

void RobotBoundMemory::inherit(const Configuration &configuration,
                               std::vector<std::optional<double>> &bounds) const {
    for (int m : configuration) {
        if (m < 0 || m >= static_cast<int>(robot_restricting_.size()) || !robot_restricting_[m])
            continue;
        Configuration smaller;
        std::copy_if(configuration.begin(), configuration.end(), std::back_inserter(smaller),
                     [m](int k) { return k != m; });
        auto it = known_.find(smaller);
        if (it == known_.end())
            continue;
        if (bounds.size() < it->second.size())
            bounds.resize(it->second.size());
        for (std::size_t t = 0; t < it->second.size(); ++t)
            if (it->second[t] && (!bounds[t] || *bounds[t] < *it->second[t]))
                bounds[t] = it->second[t];
    }
}

} // namespace envdesign::design
