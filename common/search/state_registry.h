#pragma once
// Overview: the StateRegistry stores every state the search has seen, packed, exactly once.
//
// States are packed by a StateCodec (mutex groups as small integers, see state_codec.h)
// into `bins_per_state()` 32-bit bins and stored back to back in one vector, so state i
// lives at bins [i * stride, (i + 1) * stride). A StateID is that index. Duplicates are
// found with an open-addressing hash table of StateIDs that hashes and compares the packed
// bins in place, so no state is ever copied to be looked up. Per-state search data lives
// outside, in PerStateInformation<T> indexed by StateID (per_state_information.h).
//
// Example:
//   StateRegistry registry(task);
//   StateID init = registry.insert_initial_state().id;
//   auto [succ, is_new] = registry.insert_successor(init, op);
//   UnpackedState state(registry.codec());
//   registry.unpack(succ, state);
//
// Not thread-safe. Pointers from lookup() are invalidated by the next insertion.

#include "ground/ground_task.h"
#include "search/state_codec.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace envdesign::search {

using StateID = std::uint32_t;
inline constexpr StateID NO_STATE = 0xffffffffU;

struct InsertResult {
    StateID id;
    bool is_new;
};

class StateRegistry {
public:
    using Bin = StateCodec::Bin;

    // Keeps no reference to `task`.
    explicit StateRegistry(const ground::GroundTask &task);

    const StateCodec &codec() const { return codec_; }
    int bins_per_state() const { return stride_; }
    std::size_t bytes_per_state() const { return sizeof(Bin) * stride_; }
    std::size_t size() const { return num_states_; }

    // The packed bins of a registered state.
    const Bin *lookup(StateID id) const { return data_.data() + std::size_t(id) * stride_; }
    void unpack(StateID id, UnpackedState &out) const { codec_.unpack(lookup(id), out); }

    // Registers a state given by its true facts (used for the initial state).
    InsertResult insert_facts(const std::vector<ground::FactId> &facts);
    // Registers the successor of `parent` under operator `op` (assumed applicable).
    InsertResult insert_successor(StateID parent, ground::OperatorId op);

    // Bytes held by the state storage and the hash table (capacity, not size).
    std::size_t memory_bytes() const;

private:
    // Looks up the candidate state written just past the last registered one; keeps it
    // (returns is_new) or drops it in favour of its registered twin.
    InsertResult commit_candidate();
    std::uint64_t hash(const Bin *bins) const;
    bool equal(StateID id, const Bin *bins) const;
    void grow_table();

    StateCodec codec_;
    int stride_;
    std::size_t num_states_ = 0;
    std::vector<Bin> data_;
    std::vector<StateID> table_; // power-of-two size, NO_STATE marks an empty slot
    std::size_t table_mask_ = 0;
};

} // namespace envdesign::search
