#include "search/state_registry.h"

#include <algorithm>
#include <cstring>
#include <stdexcept>

namespace envdesign::search {
namespace {

constexpr std::size_t INITIAL_TABLE_SIZE = 1024;

std::uint64_t mix(std::uint64_t h) {
    h ^= h >> 33;
    h *= 0xff51afd7ed558ccdULL;
    h ^= h >> 33;
    h *= 0xc4ceb9fe1a85ec53ULL;
    h ^= h >> 33;
    return h;
}

} // namespace

StateRegistry::StateRegistry(const ground::GroundTask &task)
    : codec_(task), stride_(std::max(1, codec_.num_bins())), table_(INITIAL_TABLE_SIZE, NO_STATE),
      table_mask_(INITIAL_TABLE_SIZE - 1) {}

InsertResult StateRegistry::insert_facts(const std::vector<ground::FactId> &facts) {
    data_.resize(data_.size() + stride_, 0);
    codec_.pack(facts, data_.data() + data_.size() - stride_);
    return commit_candidate();
}

InsertResult StateRegistry::insert_successor(StateID parent, ground::OperatorId op) {
    // Resize first: it may move the storage, and the parent lives in it.
    data_.resize(data_.size() + stride_);
    Bin *candidate = data_.data() + data_.size() - stride_;
    codec_.apply(lookup(parent), op, candidate);
    return commit_candidate();
}

InsertResult StateRegistry::commit_candidate() {
    const Bin *candidate = data_.data() + data_.size() - stride_;
    std::size_t slot = hash(candidate) & table_mask_;
    while (table_[slot] != NO_STATE) {
        if (equal(table_[slot], candidate)) {
            data_.resize(data_.size() - stride_);
            return {table_[slot], false};
        }
        slot = (slot + 1) & table_mask_;
    }
    if (num_states_ >= NO_STATE - 1)
        throw std::length_error("StateRegistry: too many states for 32-bit StateIDs");
    StateID id = static_cast<StateID>(num_states_++);
    table_[slot] = id;
    // Keep the load factor at most 1/2 so that linear probing stays short.
    if (2 * num_states_ > table_.size())
        grow_table();
    return {id, true};
}

std::uint64_t StateRegistry::hash(const Bin *bins) const {
    std::uint64_t h = 0x9e3779b97f4a7c15ULL;
    for (int i = 0; i < stride_; ++i)
        h = mix(h ^ bins[i]);
    return h;
}

bool StateRegistry::equal(StateID id, const Bin *bins) const {
    return std::memcmp(lookup(id), bins, sizeof(Bin) * stride_) == 0;
}

void StateRegistry::grow_table() {
    std::vector<StateID> old;
    old.swap(table_);
    table_.assign(old.size() * 2, NO_STATE);
    table_mask_ = table_.size() - 1;
    for (StateID id : old) {
        if (id == NO_STATE)
            continue;
        std::size_t slot = hash(lookup(id)) & table_mask_;
        while (table_[slot] != NO_STATE)
            slot = (slot + 1) & table_mask_;
        table_[slot] = id;
    }
}

std::size_t StateRegistry::memory_bytes() const {
    return data_.capacity() * sizeof(Bin) + table_.capacity() * sizeof(StateID);
}

} // namespace envdesign::search
