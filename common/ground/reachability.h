#pragma once
// Relaxed reachability over the lifted task: which atoms and which action instances are
// reachable when delete effects are ignored. This is where grounding spends its time, so it
// works on object and predicate ids and joins preconditions through per-argument indexes.

#include "ground/stop.h"
#include "pddl/task.h"

#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

namespace envdesign::ground {

// An atom as [predicate id, argument object ids...].
using AtomKey = std::vector<int>;

struct AtomKeyHash {
    std::size_t operator()(const AtomKey &key) const {
        std::uint64_t h = 1469598103934665603ull;
        for (int v : key)
            h = (h ^ static_cast<std::uint32_t>(v)) * 1099511628211ull;
        return static_cast<std::size_t>(h);
    }
};

struct ActionInstance {
    int schema = 0;             // index into domain.actions
    std::vector<int> arguments; // object id per parameter
};

struct Reachability {
    std::vector<std::string> objects;    // object id -> name (constants first)
    std::vector<std::string> predicates; // predicate id -> name
    std::vector<bool> is_fluent;         // per predicate: some action adds or deletes it
    std::vector<AtomKey> atoms;          // every reachable atom, init atoms first
    std::unordered_map<AtomKey, int, AtomKeyHash> atom_index;
    std::vector<ActionInstance> actions;
    std::unordered_map<std::string, int> object_ids, predicate_ids;

    int object_id(const std::string &name) const;
    int predicate_id(const std::string &name) const; // -1 if undeclared
    std::string atom_name(const AtomKey &atom) const;
    bool is_reached(const AtomKey &atom) const { return atom_index.count(atom) > 0; }
};

// `stop` is asked every few thousand steps (ground/stop.h).
Reachability explore(const pddl::Domain &domain, const pddl::Problem &problem,
                     const StopCheck &stop = {});

} // namespace envdesign::ground
