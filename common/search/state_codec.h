#pragma once
// The packed state layout of a GroundTask, on top of IntPacker.
//
// Each mutex group of the task becomes one variable whose value is the index of its true
// fact in the group, or |group| for "none of them"; each fact in no group becomes a 1-bit
// variable. Variables that provably always have a true fact (see exactly_one_variables in
// the .cc) get no "none" value, as FD's do, which often saves a bit per group. The codec packs and
// unpacks states and applies an operator directly to a packed state (delete effects before add
// effects, so add wins, as in PDDL).
//
// Example:
//   StateCodec codec(task);
//   std::vector<IntPacker::Bin> bins(codec.num_bins());
//   codec.pack(task.initial_state, bins.data());
//   UnpackedState state(codec);
//   codec.unpack(bins.data(), state);    // state.facts == sorted initial state

#include "ground/ground_task.h"
#include "search/int_packer.h"

#include <cstdint>
#include <span>
#include <vector>

namespace envdesign::search {

class StateCodec;

// A state as the heuristics and the successor generator want it: its true facts, sorted,
// and the same set as a bitset (bit f of word f / 64).
struct UnpackedState {
    explicit UnpackedState(const StateCodec &codec);
    std::vector<ground::FactId> facts;
    std::vector<std::uint64_t> bits;

    bool holds(ground::FactId fact) const { return (bits[fact >> 6] >> (fact & 63)) & 1U; }
};

class StateCodec {
public:
    using Bin = IntPacker::Bin;

    // Throws std::invalid_argument if the mutex groups overlap or name unknown facts.
    explicit StateCodec(const ground::GroundTask &task);

    int num_bins() const { return packer_.num_bins(); }
    int num_facts() const { return static_cast<int>(fact_var_.size()); }
    int num_bitset_words() const { return (num_facts() + 63) / 64; }

    // `facts` must respect the mutex groups (at most one true fact per group); throws
    // std::invalid_argument if it lacks a fact of an always-one variable.
    void pack(std::span<const ground::FactId> facts, Bin *out) const;
    void unpack(const Bin *in, UnpackedState &out) const;
    // Writes the successor of `parent` under operator `op` to `out` (which may not alias
    // `parent`). The operator is assumed applicable.
    void apply(const Bin *parent, ground::OperatorId op, Bin *out) const;

private:
    static constexpr int NO_CONDITION = -1;
    struct Effect {
        int var;
        int value;
        int only_if; // NO_CONDITION, or the value the variable must have for the effect
    };

    void compile_effects(const ground::GroundTask &task);

    // One variable per group (facts listed), then one per ungrouped fact.
    std::vector<std::vector<ground::FactId>> var_facts_;
    std::vector<bool> exactly_one_; // per variable: never "none" in reachable states
    std::vector<int> fact_var_;     // the variable of each fact
    std::vector<int> fact_value_;   // the value of its variable that means "this fact is true"
    std::vector<int> none_value_;   // per variable: the value meaning "no fact of it true"
    IntPacker packer_;
    std::vector<int> effect_offsets_; // effects of op i: effects_[offsets[i]..offsets[i+1])
    std::vector<Effect> effects_;
};

} // namespace envdesign::search
