#pragma once
// Per-state data kept outside the StateRegistry, indexed by StateID, like Fast Downward's
// PerStateInformation<T>: entries for states not seen yet read as the default value.

#include "search/state_registry.h"

#include <cstddef>
#include <vector>

namespace envdesign::search {

template <class T> class PerStateInformation {
public:
    explicit PerStateInformation(T default_value = T()) : default_(default_value) {}

    // Grows the storage as needed; references are invalidated by the next growth.
    T &operator[](StateID id) {
        if (id >= entries_.size())
            entries_.resize(std::size_t(id) + 1, default_);
        return entries_[id];
    }
    const T &get(StateID id) const { return id < entries_.size() ? entries_[id] : default_; }

    std::size_t memory_bytes() const { return entries_.capacity() * sizeof(T); }

private:
    T default_;
    std::vector<T> entries_;
};

} // namespace envdesign::search
