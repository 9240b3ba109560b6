#include "ground/grounder.h"

#include "ground/invariants.h"
#include "ground/reachability.h"
#include "ground/simplify.h"

#include <algorithm>
#include <limits>
#include <map>
#include <optional>

namespace envdesign::ground {
namespace {

void sort_unique(std::vector<FactId> &facts) {
    std::sort(facts.begin(), facts.end());
    facts.erase(std::unique(facts.begin(), facts.end()), facts.end());
}

class TaskBuilder {
public:
    TaskBuilder(const pddl::Domain &domain, const pddl::Problem &problem, const Reachability &r)
        : domain_(domain), problem_(problem), r_(r) {}

    GroundTask build() {
        for (std::size_t a = 0; a < r_.atoms.size(); ++a) {
            if (r_.is_fluent[r_.atoms[a][0]]) {
                fact_of_atom_[static_cast<int>(a)] = task_.num_facts();
                task_.fact_names.push_back(r_.atom_name(r_.atoms[a]));
                fact_atoms_.push_back(r_.atoms[a]);
            }
        }
        for (const auto &atom : problem_.init)
            if (auto f = fact_of(key(atom, nullptr)); f >= 0)
                task_.initial_state.push_back(f);
        for (const auto &instance : r_.actions)
            add_operator(instance);
        add_goal();
        add_complements();
        task_.has_action_costs = problem_.minimize_total_cost;
        sort_unique(task_.initial_state);
        sort_unique(task_.goal);
        fact_atoms_.resize(task_.num_facts()); // complements and markers are not atoms
        return std::move(task_);
    }

    const std::vector<AtomKey> &fact_atoms() const { return fact_atoms_; }
    const std::map<FactId, FactId> &complements() const { return complement_; }

private:
    // The atom with variables replaced by the instance's objects.
    AtomKey key(const pddl::Atom &atom, const ActionInstance *instance) const {
        AtomKey result{r_.predicate_id(atom.predicate)};
        for (const auto &arg : atom.args)
            result.push_back(arg[0] == '?' ? instance->arguments[parameter_index(instance, arg)]
                                           : r_.object_id(arg));
        return result;
    }

    int parameter_index(const ActionInstance *instance, const std::string &variable) const {
        const auto &params = domain_.actions[instance->schema].parameters;
        for (std::size_t i = 0; i < params.size(); ++i)
            if (params[i].name == variable)
                return static_cast<int>(i);
        return -1;
    }

    // The fact for a fluent atom; -1 if the atom is static or never reached.
    FactId fact_of(const AtomKey &atom) const {
        auto it = r_.atom_index.find(atom);
        if (it == r_.atom_index.end())
            return -1;
        auto f = fact_of_atom_.find(it->second);
        return f == fact_of_atom_.end() ? -1 : f->second;
    }

    FactId complement_of(FactId f) {
        auto [it, inserted] = complement_.emplace(f, task_.num_facts());
        if (inserted)
            task_.fact_names.push_back("(not " + task_.fact_names[f] + ")");
        return it->second;
    }

    // The instance's cost; none when the problem gives no value for a term of it. An
    // undefined value makes the instance inapplicable (PDDL 2.1's semantics, and Fast
    // Downward's), so it gets no operator rather than an error.
    std::optional<Cost> cost_of(const pddl::Action &action,
                                const std::vector<pddl::CostExpression> &costs,
                                const ActionInstance &instance) const {
        long long total = 0;
        for (const auto &c : costs) {
            total += c.constant;
            if (!c.function)
                continue;
            pddl::Atom term{c.function->predicate, {}, {}};
            for (const auto &arg : c.function->args)
                term.args.push_back(
                    arg[0] == '?' ? r_.objects[instance.arguments[parameter_index(&instance, arg)]]
                                  : arg);
            auto value = problem_.function_values.find(term);
            if (value == problem_.function_values.end())
                return std::nullopt;
            total += value->second;
        }
        if (total > std::numeric_limits<Cost>::max() / 2) // f = g + h must not overflow either
            throw pddl::ParseError(action.location, "the cost of an instance of action '" +
                                                        action.name + "' is too large");
        return static_cast<Cost>(total);
    }

    void add_operator(const ActionInstance &instance) {
        const pddl::Action &action = domain_.actions[instance.schema];
        // Without the metric every action costs 1 and its cost terms are not read.
        auto cost = problem_.minimize_total_cost ? cost_of(action, action.costs, instance) : 1;
        auto secondary_cost = cost_of(action, action.secondary_costs, instance);
        if (!cost || !secondary_cost)
            return;
        GroundOperator op;
        op.cost = *cost;
        op.secondary_cost = *secondary_cost;
        op.name = "(" + action.name;
        for (int o : instance.arguments)
            op.name += " " + r_.objects[o];
        op.name += ")";
        for (const auto &l : action.precondition) {
            if (l.atom.predicate == "=")
                continue; // checked during exploration
            FactId f = fact_of(key(l.atom, &instance));
            if (f >= 0)
                op.pre.push_back(l.negated ? complement_of(f) : f);
        }
        for (const auto &l : action.effect) {
            FactId f = fact_of(key(l.atom, &instance));
            if (f >= 0)
                (l.negated ? op.del : op.add).push_back(f);
        }
        sort_unique(op.pre);
        sort_unique(op.add);
        sort_unique(op.del);
        std::erase_if(
            op.del, [&](FactId f) { return std::binary_search(op.add.begin(), op.add.end(), f); });
        task_.operators.push_back(std::move(op));
    }

    void add_goal() {
        bool unreachable = false;
        for (const auto &l : problem_.goal) {
            if (l.atom.predicate == "=") {
                bool same = r_.object_id(l.atom.args[0]) == r_.object_id(l.atom.args[1]);
                unreachable |= same == l.negated;
                continue;
            }
            AtomKey atom = key(l.atom, nullptr);
            bool fluent = r_.is_fluent[atom[0]];
            bool reached = r_.is_reached(atom);
            if (fluent && reached)
                task_.goal.push_back(l.negated ? complement_of(fact_of(atom)) : fact_of(atom));
            else if (l.negated == reached) // static and false, or never reachable
                unreachable = true;
        }
        if (unreachable) {
            task_.goal.push_back(task_.num_facts());
            task_.fact_names.push_back("(goal-unreachable-by-grounding)");
        }
    }

    // Operators that change a fact also change its complement, the other way round.
    void add_complements() {
        std::vector<bool> initially(task_.num_facts(), false);
        for (FactId f : task_.initial_state)
            initially[f] = true;
        for (auto [fact, complement] : complement_) {
            if (!initially[fact])
                task_.initial_state.push_back(complement);
            for (auto &op : task_.operators) {
                if (std::binary_search(op.add.begin(), op.add.end(), fact))
                    op.del.push_back(complement);
                else if (std::binary_search(op.del.begin(), op.del.end(), fact))
                    op.add.push_back(complement);
            }
        }
        for (auto &op : task_.operators) {
            sort_unique(op.add);
            sort_unique(op.del);
        }
    }

    const pddl::Domain &domain_;
    const pddl::Problem &problem_;
    const Reachability &r_;
    GroundTask task_;
    std::map<int, FactId> fact_of_atom_;
    std::map<FactId, FactId> complement_;
    std::vector<AtomKey> fact_atoms_;
};

// A fact and its complement are a group of two unless the fact is in a group already.
void add_complement_groups(GroundTask &task, const std::map<FactId, FactId> &complements) {
    std::vector<bool> grouped(task.num_facts(), false);
    for (const auto &group : task.mutex_groups)
        for (FactId f : group)
            grouped[f] = true;
    for (auto [fact, complement] : complements)
        if (!grouped[fact] && !grouped[complement])
            task.mutex_groups.push_back({fact, complement});
}

} // namespace

GroundTask ground(const pddl::Domain &domain, const pddl::Problem &problem,
                  GroundingStatistics *statistics, const StopCheck &stop, bool prune_irrelevant) {
    Reachability reachability = explore(domain, problem, stop);
    TaskBuilder builder(domain, problem, reachability);
    GroundTask task = builder.build();
    check(stop);
    add_mutex_groups(task, builder.fact_atoms());
    check(stop);
    add_complement_groups(task, builder.complements());
    if (statistics) {
        statistics->reachable_atoms = static_cast<int>(reachability.atoms.size());
        statistics->reachable_actions = static_cast<int>(reachability.actions.size());
    }
    remove_unreachable(task);
    remove_always_true(task);
    if (prune_irrelevant)
        remove_irrelevant(task);
    if (statistics) {
        statistics->relevant_facts = task.num_facts();
        statistics->relevant_operators = task.num_operators();
    }
    return task;
}

} // namespace envdesign::ground
