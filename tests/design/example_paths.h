#pragma once
// The example folders several design tests read, defined once: a unity batch compiles
// several test files as one, where a constant each file defined for itself would clash.

#include <string>

namespace envdesign {

// examples/restaurant/ (the paper's restaurant), with its trailing slash.
inline const std::string RESTAURANT = std::string(ENVDESIGN_EXAMPLES) + "/restaurant/";
// tests/data/design/roads/, with its trailing slash.
inline const std::string ROADS = std::string(ENVDESIGN_TEST_DATA) + "/design/roads/";
// The restaurant whose task mix drifts (tests/arrivals/data).
inline const std::string RESTAURANT_DRIFT =
    std::string(ENVDESIGN_TEST_DATA) + "/../arrivals/data/restaurant-drift.textproto";

} // namespace envdesign
