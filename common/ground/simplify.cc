#include "ground/simplify.h"

#include <algorithm>

namespace envdesign::ground {
namespace {

// Keeps the facts and operators marked, renumbering facts and dropping ones no longer kept.
void restrict(GroundTask &task, const std::vector<bool> &keep_fact,
              const std::vector<bool> &keep_operator) {
    std::vector<FactId> new_id(task.num_facts(), -1);
    std::vector<std::string> names;
    for (FactId f = 0; f < task.num_facts(); ++f) {
        if (keep_fact[f]) {
            new_id[f] = static_cast<FactId>(names.size());
            names.push_back(std::move(task.fact_names[f]));
        }
    }
    auto remap = [&](std::vector<FactId> &facts) {
        std::vector<FactId> kept;
        for (FactId f : facts)
            if (new_id[f] >= 0)
                kept.push_back(new_id[f]);
        facts = std::move(kept);
    };
    std::vector<GroundOperator> operators;
    for (OperatorId o = 0; o < task.num_operators(); ++o) {
        if (!keep_operator[o])
            continue;
        GroundOperator op = std::move(task.operators[o]);
        remap(op.pre);
        remap(op.add);
        remap(op.del);
        operators.push_back(std::move(op));
    }
    task.fact_names = std::move(names);
    task.operators = std::move(operators);
    remap(task.initial_state);
    remap(task.goal);
    for (auto &group : task.mutex_groups)
        remap(group);
    std::erase_if(task.mutex_groups, [](const auto &g) { return g.size() < 2; });
}

} // namespace

void remove_unreachable(GroundTask &task) {
    std::vector<bool> reached(task.num_facts(), false), applicable(task.num_operators(), false);
    for (FactId f : task.initial_state)
        reached[f] = true;
    for (bool changed = true; changed;) {
        changed = false;
        for (OperatorId o = 0; o < task.num_operators(); ++o) {
            if (applicable[o])
                continue;
            const auto &op = task.operators[o];
            if (!std::all_of(op.pre.begin(), op.pre.end(), [&](FactId f) { return reached[f]; }))
                continue;
            applicable[o] = changed = true;
            for (FactId f : op.add)
                reached[f] = true;
        }
    }
    // Goal facts stay even when unreachable: the search must still prove unsolvability.
    for (FactId f : task.goal)
        reached[f] = true;
    restrict(task, reached, applicable);
}

void remove_always_true(GroundTask &task) {
    std::vector<bool> keep(task.num_facts(), true);
    for (FactId f : task.initial_state)
        keep[f] = false;
    for (const auto &op : task.operators)
        for (FactId f : op.del)
            keep[f] = true;
    restrict(task, keep, std::vector<bool>(task.num_operators(), true));
}

void remove_unread(GroundTask &task) {
    std::vector<bool> read(task.num_facts(), false);
    for (FactId f : task.goal)
        read[f] = true;
    for (const auto &op : task.operators)
        for (FactId f : op.pre)
            read[f] = true;
    restrict(task, read, std::vector<bool>(task.num_operators(), true));
}

void remove_irrelevant(GroundTask &task) {
    std::vector<bool> relevant(task.num_facts(), false), useful(task.num_operators(), false);
    for (FactId f : task.goal)
        relevant[f] = true;
    auto touches_relevant = [&](const GroundOperator &op) {
        auto is_relevant = [&](FactId f) { return relevant[f]; };
        return std::any_of(op.add.begin(), op.add.end(), is_relevant) ||
               std::any_of(op.del.begin(), op.del.end(), is_relevant);
    };
    for (bool changed = true; changed;) {
        changed = false;
        for (OperatorId o = 0; o < task.num_operators(); ++o) {
            const auto &op = task.operators[o];
            if (useful[o] || !touches_relevant(op))
                continue;
            useful[o] = changed = true;
            for (FactId f : op.pre)
                relevant[f] = true;
        }
    }
    restrict(task, relevant, useful);
}

} // namespace envdesign::ground
