#include "search/state_codec.h"

#include <algorithm>
#include <bit>
#include <cstring>
#include <stdexcept>

namespace envdesign::search {
namespace {

// Builds the variables: one per mutex group, then one per fact in no group.
std::vector<std::vector<ground::FactId>> make_variables(const ground::GroundTask &task) {
    std::vector<std::vector<ground::FactId>> vars;
    std::vector<bool> grouped(task.num_facts(), false);
    for (const std::vector<ground::FactId> &group : task.mutex_groups) {
        if (group.empty())
            continue;
        for (ground::FactId fact : group) {
            if (fact < 0 || fact >= task.num_facts() || grouped[fact])
                throw std::invalid_argument("mutex groups overlap or name unknown facts");
            grouped[fact] = true;
        }
        vars.push_back(group);
    }
    for (ground::FactId fact = 0; fact < task.num_facts(); ++fact)
        if (!grouped[fact])
            vars.push_back({fact});
    return vars;
}

// A variable is "exactly one" if the initial state has one of its facts and every operator
// that deletes one of them adds another: with the mutex property, one of its facts is then
// true in every reachable state, so it needs no "none" value (like FD's variables without
// "<none of those>"). A single fact that is always true packs into zero bits.
std::vector<bool> exactly_one_variables(const ground::GroundTask &task,
                                        const std::vector<std::vector<ground::FactId>> &vars) {
    std::vector<int> var_of(task.num_facts());
    for (int v = 0; v < static_cast<int>(vars.size()); ++v)
        for (ground::FactId f : vars[v])
            var_of[f] = v;
    std::vector<int> initial_count(vars.size(), 0);
    for (ground::FactId f : task.initial_state)
        ++initial_count[var_of[f]];
    std::vector<bool> exactly_one(vars.size());
    for (std::size_t v = 0; v < vars.size(); ++v)
        exactly_one[v] = initial_count[v] == 1;
    for (const ground::GroundOperator &op : task.operators) {
        for (ground::FactId f : op.del) {
            int v = var_of[f];
            bool adds_mate = std::any_of(op.add.begin(), op.add.end(),
                                         [&](ground::FactId a) { return var_of[a] == v; });
            if (!adds_mate)
                exactly_one[v] = false;
        }
    }
    return exactly_one;
}

std::vector<int> variable_ranges(const std::vector<std::vector<ground::FactId>> &vars,
                                 const std::vector<bool> &exactly_one) {
    std::vector<int> ranges;
    ranges.reserve(vars.size());
    for (std::size_t v = 0; v < vars.size(); ++v)
        ranges.push_back(static_cast<int>(vars[v].size()) + (exactly_one[v] ? 0 : 1));
    return ranges;
}

} // namespace

UnpackedState::UnpackedState(const StateCodec &codec) : bits(codec.num_bitset_words(), 0) {
    facts.reserve(codec.num_facts());
}

StateCodec::StateCodec(const ground::GroundTask &task)
    : var_facts_(make_variables(task)), exactly_one_(exactly_one_variables(task, var_facts_)),
      fact_var_(task.num_facts()), fact_value_(task.num_facts()),
      packer_(variable_ranges(var_facts_, exactly_one_)) {
    for (int var = 0; var < static_cast<int>(var_facts_.size()); ++var) {
        const auto &facts = var_facts_[var];
        none_value_.push_back(static_cast<int>(facts.size()));
        for (int value = 0; value < static_cast<int>(facts.size()); ++value) {
            fact_var_[facts[value]] = var;
            fact_value_[facts[value]] = value;
        }
    }
    compile_effects(task);
}

// Delete effects come first so that an add of another fact of the same variable wins. A
// delete resets its variable only if that fact is the one currently true, because deleting
// a false fact must not erase its true group mate.
void StateCodec::compile_effects(const ground::GroundTask &task) {
    effect_offsets_.push_back(0);
    for (const ground::GroundOperator &op : task.operators) {
        for (ground::FactId fact : op.del) {
            int var = fact_var_[fact];
            bool var_added = std::any_of(op.add.begin(), op.add.end(),
                                         [&](ground::FactId a) { return fact_var_[a] == var; });
            if (var_added)
                continue;
            bool known_true = std::binary_search(op.pre.begin(), op.pre.end(), fact);
            effects_.push_back(
                {var, none_value_[var], known_true ? NO_CONDITION : fact_value_[fact]});
        }
        for (ground::FactId fact : op.add)
            effects_.push_back({fact_var_[fact], fact_value_[fact], NO_CONDITION});
        effect_offsets_.push_back(static_cast<int>(effects_.size()));
    }
}

void StateCodec::pack(std::span<const ground::FactId> facts, Bin *out) const {
    std::vector<int> values(none_value_);
    for (ground::FactId fact : facts)
        values[fact_var_[fact]] = fact_value_[fact];
    std::fill(out, out + num_bins(), 0);
    for (int var = 0; var < packer_.num_variables(); ++var) {
        if (exactly_one_[var] && values[var] == none_value_[var])
            throw std::invalid_argument("state has no fact of an exactly-one mutex group");
        packer_.set(out, var, values[var]);
    }
}

void StateCodec::unpack(const Bin *in, UnpackedState &out) const {
    std::fill(out.bits.begin(), out.bits.end(), 0);
    for (int var = 0; var < packer_.num_variables(); ++var) {
        int value = packer_.get(in, var);
        if (value != none_value_[var]) {
            ground::FactId fact = var_facts_[var][value];
            out.bits[fact >> 6] |= std::uint64_t(1) << (fact & 63);
        }
    }
    // Scanning the bitset yields the facts sorted, whatever the variable order.
    out.facts.clear();
    for (int word = 0; word < static_cast<int>(out.bits.size()); ++word) {
        for (std::uint64_t w = out.bits[word]; w != 0; w &= w - 1)
            out.facts.push_back(word * 64 + std::countr_zero(w));
    }
}

void StateCodec::apply(const Bin *parent, ground::OperatorId op, Bin *out) const {
    std::memcpy(out, parent, sizeof(Bin) * num_bins());
    for (int i = effect_offsets_[op]; i < effect_offsets_[op + 1]; ++i) {
        const Effect &effect = effects_[i];
        if (effect.only_if == NO_CONDITION || packer_.get(out, effect.var) == effect.only_if)
            packer_.set(out, effect.var, effect.value);
    }
}

} // namespace envdesign::search
