#pragma once
// Grounding that stops when its caller says so: a time limit must hold while a large task
// is still being grounded, not only once the search starts.

#include <functional>
#include <stdexcept>

namespace envdesign::ground {

// Asked now and then while grounding; true: stop (GroundingStopped is thrown).
using StopCheck = std::function<bool()>;

class GroundingStopped : public std::runtime_error {
public:
    GroundingStopped() : std::runtime_error("grounding stopped: the time limit passed") {}
};

// Throws GroundingStopped if `stop` says so.
inline void check(const StopCheck &stop) {
    if (stop && stop())
        throw GroundingStopped();
}

} // namespace envdesign::ground
