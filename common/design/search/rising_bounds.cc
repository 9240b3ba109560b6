#include "design/search/rising_bounds.h"

#include <algorithm>
#include <iterator>

namespace envdesign::design {

void RisingBounds::remember(const Configuration &configuration,
                            const std::vector<std::optional<double>> &bounds) {
    if (std::none_of(bounds.begin(), bounds.end(), [](const auto &b) { return b.has_value(); }))
        return;
    std::vector<std::optional<double>> &kept = known_[configuration];
    if (kept.size() < bounds.size())
        kept.resize(bounds.size());
    for (std::size_t t = 0; t < bounds.size(); ++t)
        if (bounds[t] && (!kept[t] || *kept[t] < *bounds[t]))
            kept[t] = bounds[t];
}

std::vector<Configuration> RisingBounds::parents(const Configuration &configuration) const {
    std::vector<Configuration> out;
    for (int m : configuration) {
        if (m < 0 || m >= static_cast<int>(rising_.size()) || !rising_[m])
            continue;
        Configuration &smaller = out.emplace_back();
        std::copy_if(configuration.begin(), configuration.end(), std::back_inserter(smaller),
                     [m](int k) { return k != m; });
    }
    return out;
}

void RisingBounds::inherit(const Configuration &configuration,
                           std::vector<std::optional<double>> &bounds) const {
    for (const Configuration &smaller : parents(configuration)) {
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
