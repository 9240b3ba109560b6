#include "ground/invariants.h"

#include <algorithm>
#include <deque>
#include <map>
#include <optional>
#include <set>

namespace envdesign::ground {
namespace {

// One predicate's share of an invariant: argument position -> invariant parameter, or -1 for
// the (at most one) counted argument.
struct Part {
    int predicate = 0;
    std::vector<int> parameter_of;
    auto operator<=>(const Part &) const = default;
};

struct Candidate {
    int num_parameters = 0;
    std::vector<Part> parts; // sorted, one per predicate
    auto operator<=>(const Candidate &) const = default;
};

using InstanceKey = std::vector<int>;

std::optional<InstanceKey> instance_of(const Candidate &c, const AtomKey &atom) {
    if (atom.empty())
        return std::nullopt;
    for (const auto &part : c.parts) {
        if (part.predicate != atom[0])
            continue;
        InstanceKey key(c.num_parameters, -1);
        for (std::size_t pos = 0; pos < part.parameter_of.size(); ++pos)
            if (part.parameter_of[pos] >= 0)
                key[part.parameter_of[pos]] = atom[pos + 1];
        return key;
    }
    return std::nullopt;
}

class InvariantFinder {
public:
    InvariantFinder(const GroundTask &task, const std::vector<AtomKey> &fact_atoms)
        : task_(task), atoms_(fact_atoms) {}

    std::vector<Candidate> find() {
        seed();
        std::vector<Candidate> invariants;
        // A cap keeps pathological domains from exploring forever; missing an invariant only
        // costs compactness, never correctness.
        for (int checked = 0; !queue_.empty() && checked < 2000; ++checked) {
            Candidate c = queue_.front();
            queue_.pop_front();
            if (holds(c))
                invariants.push_back(c);
        }
        return invariants;
    }

private:
    void enqueue(Candidate c) {
        std::sort(c.parts.begin(), c.parts.end());
        if (seen_.insert(c).second)
            queue_.push_back(std::move(c));
    }

    void seed() {
        std::map<int, std::size_t> arity;
        for (const auto &atom : atoms_)
            if (!atom.empty())
                arity[atom[0]] = atom.size() - 1;
        for (auto [predicate, n] : arity) {
            std::vector<int> all(n);
            for (std::size_t i = 0; i < n; ++i)
                all[i] = static_cast<int>(i);
            enqueue({static_cast<int>(n), {{predicate, all}}});
            for (std::size_t counted = 0; counted < n; ++counted) {
                std::vector<int> mapping(n);
                for (std::size_t i = 0, next = 0; i < n; ++i)
                    mapping[i] = i == counted ? -1 : static_cast<int>(next++);
                enqueue({static_cast<int>(n) - 1, {{predicate, mapping}}});
            }
        }
    }

    bool holds(const Candidate &c) {
        std::set<InstanceKey> initially;
        for (FactId f : task_.initial_state)
            if (auto key = instance_of(c, atoms_[f]); key && !initially.insert(*key).second)
                return false;
        for (const auto &op : task_.operators)
            if (!balanced(c, op))
                return false;
        return true;
    }

    // An operator that makes an atom of instance K true must make a required atom of K false.
    bool balanced(const Candidate &c, const GroundOperator &op) {
        std::set<InstanceKey> added;
        for (FactId a : op.add) {
            auto key = instance_of(c, atoms_[a]);
            if (!key || std::binary_search(op.pre.begin(), op.pre.end(), a))
                continue;
            if (!added.insert(*key).second)
                return false; // two atoms of one instance at once: no refinement helps
            bool deletes_required = false;
            for (FactId d : op.del)
                if (std::binary_search(op.pre.begin(), op.pre.end(), d) &&
                    instance_of(c, atoms_[d]) == key)
                    deletes_required = true;
            if (!deletes_required) {
                refine(c, op, *key);
                return false;
            }
        }
        return true;
    }

    // Proposes adding the predicate of a deleted precondition, its arguments mapped to the
    // invariant parameters by the objects they share with the instance.
    void refine(const Candidate &c, const GroundOperator &op, const InstanceKey &key) {
        for (FactId d : op.del) {
            const AtomKey &atom = atoms_[d];
            if (atom.empty() || !std::binary_search(op.pre.begin(), op.pre.end(), d))
                continue;
            bool present = std::any_of(c.parts.begin(), c.parts.end(),
                                       [&](const Part &p) { return p.predicate == atom[0]; });
            if (present)
                continue;
            Part part{atom[0], {}};
            int counted = 0;
            std::set<int> covered;
            for (std::size_t pos = 1; pos < atom.size(); ++pos) {
                auto it = std::find(key.begin(), key.end(), atom[pos]);
                int parameter = it == key.end() || covered.count(static_cast<int>(it - key.begin()))
                                    ? -1
                                    : static_cast<int>(it - key.begin());
                counted += parameter < 0;
                if (parameter >= 0)
                    covered.insert(parameter);
                part.parameter_of.push_back(parameter);
            }
            if (counted <= 1 && static_cast<int>(covered.size()) == c.num_parameters) {
                Candidate refined = c;
                refined.parts.push_back(part);
                enqueue(refined);
            }
        }
    }

    const GroundTask &task_;
    const std::vector<AtomKey> &atoms_;
    std::deque<Candidate> queue_;
    std::set<Candidate> seen_;
};

// All instances of all invariants, as groups of facts.
std::vector<std::vector<FactId>> instantiate(const std::vector<Candidate> &invariants,
                                             const std::vector<AtomKey> &atoms) {
    std::vector<std::vector<FactId>> groups;
    for (const auto &c : invariants) {
        std::map<InstanceKey, std::vector<FactId>> by_instance;
        for (FactId f = 0; f < static_cast<FactId>(atoms.size()); ++f)
            if (auto key = instance_of(c, atoms[f]))
                by_instance[*key].push_back(f);
        for (auto &[key, facts] : by_instance)
            if (facts.size() >= 2)
                groups.push_back(std::move(facts));
    }
    return groups;
}

// Greedy cover: the largest group first, its facts removed from the others (FD does the same).
std::vector<std::vector<FactId>> choose_disjoint(std::vector<std::vector<FactId>> groups,
                                                 int num_facts) {
    std::vector<bool> covered(num_facts, false);
    std::vector<std::vector<FactId>> chosen;
    while (true) {
        for (auto &g : groups)
            std::erase_if(g, [&](FactId f) { return covered[f]; });
        auto best =
            std::max_element(groups.begin(), groups.end(),
                             [](const auto &a, const auto &b) { return a.size() < b.size(); });
        if (best == groups.end() || best->size() < 2)
            return chosen;
        for (FactId f : *best)
            covered[f] = true;
        chosen.push_back(std::move(*best));
        best->clear();
    }
}

} // namespace

void add_mutex_groups(GroundTask &task, const std::vector<AtomKey> &fact_atoms) {
    auto invariants = InvariantFinder(task, fact_atoms).find();
    auto groups = instantiate(invariants, fact_atoms);
    std::vector<std::vector<int>> groups_of(task.num_facts());
    for (int g = 0; g < static_cast<int>(groups.size()); ++g)
        for (FactId f : groups[g])
            groups_of[f].push_back(g);
    auto mutex_within = [&](const std::vector<FactId> &facts) {
        std::set<int> seen;
        for (FactId f : facts)
            for (int g : groups_of[f])
                if (!seen.insert(g).second)
                    return true;
        return false;
    };
    std::erase_if(task.operators, [&](const GroundOperator &op) { return mutex_within(op.pre); });
    if (mutex_within(task.goal)) {
        task.goal.push_back(task.num_facts());
        task.fact_names.push_back("(goal-facts-are-mutex)");
    }
    task.mutex_groups = choose_disjoint(std::move(groups), task.num_facts());
}

} // namespace envdesign::ground
