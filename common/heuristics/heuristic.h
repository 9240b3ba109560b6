#pragma once
// The heuristic interface: a state in, an estimate of its primary goal distance out.
//
// Heuristics see a state as a StateView: the sorted list of its true facts plus the same set
// as a bitset, both owned by the caller (the search unpacks each state once and lends it
// to the heuristic and to the goal test). Estimates are primary costs; DEAD_END means the
// goal is unreachable from the state (for the heuristics here: even in the delete
// relaxation), so the search may prune it.
//
// Example (make_heuristic.h):
//   auto h = make_heuristic(parse_heuristic_kind("lmcut"), task);
//   int estimate = h->compute(view);   // view built by the search, see StateView
//   if (estimate == DEAD_END) ...

#include "ground/ground_task.h"

#include <cstdint>
#include <limits>
#include <memory>
#include <span>
#include <string_view>

namespace envdesign::heuristics {

inline constexpr int DEAD_END = std::numeric_limits<int>::max();

// A non-owning view of one unpacked state. `facts` is sorted ascending; `bits` has bit f
// (word f / 64, bit f % 64) set exactly for the facts in `facts`.
class StateView {
public:
    StateView(std::span<const ground::FactId> facts, std::span<const std::uint64_t> bits)
        : facts_(facts), bits_(bits) {}

    std::span<const ground::FactId> facts() const { return facts_; }
    bool holds(ground::FactId fact) const { return (bits_[fact >> 6] >> (fact & 63)) & 1U; }

private:
    std::span<const ground::FactId> facts_;
    std::span<const std::uint64_t> bits_;
};

// Number of 64-bit words a bitset over the task's facts needs.
inline int bitset_words(const ground::GroundTask &task) { return (task.num_facts() + 63) / 64; }

class Heuristic {
public:
    virtual ~Heuristic();
    // The estimate for `state` (>= 0) or DEAD_END. Not thread-safe: implementations reuse
    // scratch memory between calls.
    virtual int compute(const StateView &state) = 0;
};

enum class HeuristicKind { BLIND, HMAX, LMCUT };

// "blind", "hmax" or "lmcut" (exact, lower case); throws std::invalid_argument otherwise.
HeuristicKind parse_heuristic_kind(std::string_view name);

std::string_view heuristic_kind_name(HeuristicKind kind);

} // namespace envdesign::heuristics
