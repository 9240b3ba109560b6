#include "design/model/ground_key.h"

#include <algorithm>
#include <cstdio>
#include <numeric>
#include <tuple>

namespace envdesign::design {
namespace {

using ground::FactId;

void remap(std::vector<FactId> &facts, const std::vector<FactId> &new_id) {
    for (auto &f : facts)
        f = new_id[f];
    std::sort(facts.begin(), facts.end());
}

// Two 64-bit streams with different primes and offsets (FNV-1a and a multiply-xorshift
// variant); together they make the 128-bit key.
class Hasher {
public:
    void bytes(const void *data, std::size_t size) {
        const auto *p = static_cast<const unsigned char *>(data);
        for (std::size_t i = 0; i < size; ++i) {
            a_ = (a_ ^ p[i]) * 0x100000001b3ull;
            b_ = (b_ + p[i] + 1) * 0x9e3779b97f4a7c15ull;
            b_ ^= b_ >> 29;
        }
    }
    void number(std::int64_t v) { bytes(&v, sizeof v); }
    void text(const std::string &s) {
        number(static_cast<std::int64_t>(s.size()));
        bytes(s.data(), s.size());
    }
    void list(const std::vector<FactId> &facts) {
        number(static_cast<std::int64_t>(facts.size()));
        for (FactId f : facts)
            number(f);
    }
    TaskKey key() const { return {a_, b_ ^ (b_ >> 31)}; }

private:
    std::uint64_t a_ = 0xcbf29ce484222325ull;
    std::uint64_t b_ = 0x243f6a8885a308d3ull;
};

} // namespace

std::string TaskKey::hex() const {
    char buffer[33];
    std::snprintf(buffer, sizeof buffer, "%016llx%016llx", static_cast<unsigned long long>(high),
                  static_cast<unsigned long long>(low));
    return buffer;
}

ground::GroundTask canonicalize(const ground::GroundTask &task) {
    std::vector<FactId> order(task.num_facts());
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(),
                     [&](FactId a, FactId b) { return task.fact_names[a] < task.fact_names[b]; });
    std::vector<FactId> new_id(task.num_facts());
    ground::GroundTask out;
    out.has_action_costs = task.has_action_costs;
    for (std::size_t i = 0; i < order.size(); ++i) {
        new_id[order[i]] = static_cast<FactId>(i);
        out.fact_names.push_back(task.fact_names[order[i]]);
    }
    out.operators = task.operators;
    for (auto &op : out.operators) {
        remap(op.pre, new_id);
        remap(op.add, new_id);
        remap(op.del, new_id);
    }
    std::stable_sort(out.operators.begin(), out.operators.end(), [](const auto &a, const auto &b) {
        return std::tie(a.name, a.cost, a.secondary_cost, a.pre, a.add, a.del) <
               std::tie(b.name, b.cost, b.secondary_cost, b.pre, b.add, b.del);
    });
    out.initial_state = task.initial_state;
    remap(out.initial_state, new_id);
    out.goal = task.goal;
    remap(out.goal, new_id);
    out.mutex_groups = task.mutex_groups;
    for (auto &group : out.mutex_groups)
        remap(group, new_id);
    std::sort(out.mutex_groups.begin(), out.mutex_groups.end());
    return out;
}

TaskKey key_of_text(const std::string &text) {
    Hasher h;
    h.text(text);
    return h.key();
}

TaskKey key_of(const ground::GroundTask &task) {
    Hasher h;
    h.number(task.has_action_costs ? 1 : 0);
    h.number(task.num_facts());
    for (const auto &name : task.fact_names)
        h.text(name);
    h.number(task.num_operators());
    for (const auto &op : task.operators) {
        h.text(op.name);
        h.list(op.pre);
        h.list(op.add);
        h.list(op.del);
        h.number(op.cost);
        h.number(op.secondary_cost);
    }
    h.list(task.initial_state);
    h.list(task.goal);
    h.number(static_cast<std::int64_t>(task.mutex_groups.size()));
    for (const auto &group : task.mutex_groups)
        h.list(group);
    return h.key();
}

} // namespace envdesign::design
