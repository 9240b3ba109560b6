#include "design/search/addition_floors.h"

#include "design/model/compilation.h"
#include "design/model/configuration.h"
#include "ground/grounder.h"
#include "ground/stop.h"
#include "planning/planner.h"
#include "search/state_space.h"

#include <algorithm>
#include <chrono>
#include <functional>
#include <map>
#include <queue>
#include <set>
#include <sstream>

namespace envdesign::design {
namespace {

// "+|r-connected|v19|v18": a literal of P_mod, its sign first.
std::string literal_key(bool negated, const std::string &predicate,
                        const std::vector<std::string> &args) {
    std::string key = negated ? "-|" : "+|";
    key += predicate;
    for (const std::string &a : args)
        key += "|" + a;
    return key;
}

// The operators of one ground P_mod, indexed by what they read and which schema they are.
struct OperatorIndex {
    std::map<std::string, std::vector<int>> by_literal; // precondition literal -> operators
    std::map<std::string, std::vector<int>> by_schema;
    std::set<std::string> goal; // goal literals, keyed the same way

    OperatorIndex(const pddl::Domain &domain, const pddl::Problem &problem,
                  const ground::GroundTask &task) {
        for (int o = 0; o < task.num_operators(); ++o) {
            std::istringstream words(task.operators[o].name.substr(1)); // "(move a b)"
            std::string schema, word;
            std::vector<std::string> args;
            words >> schema;
            while (words >> word)
                args.push_back(word.back() == ')' ? word.substr(0, word.size() - 1) : word);
            by_schema[schema].push_back(o);
            const pddl::Action *action = domain.find_action(schema);
            if (!action)
                continue; // cannot happen: every operator comes from a schema
            for (const pddl::Literal &l : action->precondition) {
                std::vector<std::string> bound;
                for (const std::string &a : l.atom.args) {
                    std::string value = a;
                    for (std::size_t i = 0; i < action->parameters.size() && i < args.size(); ++i)
                        if (action->parameters[i].name == a)
                            value = args[i];
                    bound.push_back(value);
                }
                by_literal[literal_key(l.negated, l.atom.predicate, bound)].push_back(o);
            }
        }
        for (const pddl::Literal &l : problem.goal)
            goal.insert(literal_key(l.negated, l.atom.predicate, l.atom.args));
    }
};

// A predicate's name in the searched model for an edit of the robot's (true) or the human's
// model; nullopt: that model is not searched.
using Naming = std::function<std::optional<std::string>(bool robot, const std::string &name)>;

std::optional<std::string> in_compilation(bool robot, const std::string &name) {
    return robot ? robot_copy(name) : human_copy(name);
}
std::optional<std::string> in_robot_model(bool robot, const std::string &name) {
    return robot ? std::optional<std::string>(name) : std::nullopt;
}

// The operators a plan of A needs to use `modification`; nullopt: any plan may (it edits
// the goal, or an initial atom the goal reads).
std::optional<std::set<int>> users(const Modification &modification, const OperatorIndex &index,
                                   const Naming &naming) {
    std::set<int> out;
    auto take = [&](const std::map<std::string, std::vector<int>> &from, const std::string &key) {
        auto it = from.find(key);
        if (it != from.end())
            out.insert(it->second.begin(), it->second.end());
    };
    for (const Edit &edit : modification.edits) {
        for (bool robot : {true, false}) {
            // The edit's model, if it is the one searched (naming gives no name otherwise).
            if (!(robot ? applies_to_robot(edit.model) : applies_to_human(edit.model)) ||
                !naming(robot, ""))
                continue;
            auto copy = [&](const std::string &name) { return *naming(robot, name); };
            switch (edit.kind) {
            case EditKind::ADD_INIT:
            case EditKind::REMOVE_INIT: {
                const pddl::SExpr &atom = edit.expression;
                if (!atom.is_list || atom.items.empty())
                    return std::nullopt;
                std::vector<std::string> args;
                for (std::size_t i = 1; i < atom.items.size(); ++i)
                    args.push_back(atom.items[i].to_string());
                // More atoms help a plan only where it reads one; fewer, where it reads one
                // as absent.
                std::string key = literal_key(edit.kind == EditKind::REMOVE_INIT,
                                              copy(atom.items[0].to_string()), args);
                std::string opposite = (key[0] == '+' ? "-" : "+") + key.substr(1);
                if (index.goal.count(key) || index.goal.count(opposite))
                    return std::nullopt;
                take(index.by_literal, key);
                break;
            }
            case EditKind::REMOVE_PRECONDITION:
            case EditKind::ADD_EFFECT:
            case EditKind::REMOVE_EFFECT:
                take(index.by_schema, edit.action);
                break;
            case EditKind::ADD_PREDICATE:
                break;
            default: // REMOVE_GOAL, and kinds an adding modification does not have
                return std::nullopt;
            }
        }
    }
    return out;
}

// One floor search's time: past it what the search proved stands in (the largest f it
// expanded, or the floor of every plan of A: weaker, still a floor), so that one hard task
// does not keep the phase from every other.
constexpr double FLOOR_SEARCH_SECONDS = 0.25;

// A task of A with at most this many states is explored whole once (search/state_space.h)
// for every L(t, e) at once; a larger one gets a search per modification.
constexpr std::size_t EXPLORED_STATES = 100000;

// `cap_s` > 0: a floor search of a task too large to explore whole (state_space.h), where
// LM-cut's fewer expansions repay its cost per state.
planning::PlannerOptions options_for(const Deadline &deadline, double cap_s = 0) {
    planning::PlannerOptions options;
    options.inherit_cuts = true; // costs alone: any optimal plan
    options.limits.stop = deadline.stop_flag();
    if (deadline.limited())
        options.limits.time_limit_s = std::max(1e-3, deadline.remaining_seconds());
    if (cap_s > 0 && (options.limits.time_limit_s <= 0 || cap_s < options.limits.time_limit_s))
        options.limits.time_limit_s = cap_s;
    return options;
}

// The least primary cost of a plan of `task`: INF when there is none, nullopt when a limit
// stopped the search, with `proven` set to what it had proven by then (no plan costs less:
// the largest f expanded, search/astar_search.h).
std::optional<double> least_cost(const ground::GroundTask &task, const Deadline &deadline,
                                 double cap_s = 0, double *proven = nullptr) {
    planning::PlanReport report = planning::plan_task(task, options_for(deadline, cap_s));
    if (report.status == search::SearchStatus::SOLVED)
        return static_cast<double>(report.cost);
    if (report.status == search::SearchStatus::FAILED)
        return INF;
    if (proven)
        *proven = static_cast<double>(report.statistics.f_bound);
    return std::nullopt;
}

// The task with one more fact, `used`, that the goal requires; least_cost_using() says which
// operators set it, so that a plan of it is a plan of the task with one of those steps.
class FlaggedTask {
public:
    explicit FlaggedTask(const ground::GroundTask &task) : task_(task), used_(task.num_facts()) {
        task_.fact_names.push_back("(envdesign-used-addition)");
        task_.goal.push_back(used_);
    }
    std::optional<double> least_cost_using(const std::set<int> &steps, const Deadline &deadline,
                                           double &proven) {
        for (int o : steps)
            task_.operators[o].add.push_back(used_); // the largest id: the list stays sorted
        auto cost = least_cost(task_, deadline, FLOOR_SEARCH_SECONDS, &proven);
        for (int o : steps)
            task_.operators[o].add.pop_back();
        return cost;
    }

private:
    ground::GroundTask task_;
    ground::FactId used_;
};

// Per operator, a lower bound on the cost of any plan prefix that ends with it: h^max of
// its precondition from the initial state (delete relaxation) plus its cost. INF where the
// relaxation never reaches it.
std::vector<double> cheapest_prefix(const ground::GroundTask &task) {
    std::vector<double> fact(task.num_facts(), INF);
    std::vector<std::vector<int>> readers(task.num_facts());
    std::vector<int> unmet(task.num_operators());
    std::vector<double> reached(task.num_operators(), 0.0);
    using Entry = std::pair<double, ground::FactId>;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<>> queue;
    for (ground::FactId f : task.initial_state)
        fact[f] = 0, queue.push({0.0, f});
    std::vector<double> out(task.num_operators(), INF);
    auto apply = [&](int o) {
        out[o] = reached[o] + task.operators[o].cost;
        for (ground::FactId f : task.operators[o].add)
            if (out[o] < fact[f])
                fact[f] = out[o], queue.push({out[o], f});
    };
    for (int o = 0; o < task.num_operators(); ++o) {
        unmet[o] = static_cast<int>(task.operators[o].pre.size());
        for (ground::FactId f : task.operators[o].pre)
            readers[f].push_back(o);
        if (unmet[o] == 0)
            apply(o);
    }
    while (!queue.empty()) {
        auto [cost, f] = queue.top();
        queue.pop();
        if (cost > fact[f])
            continue;
        for (int o : readers[f]) {
            reached[o] = std::max(reached[o], cost); // facts leave the queue by cost
            if (--unmet[o] == 0)
                apply(o);
        }
    }
    return out;
}

} // namespace

namespace {

// The least cost of a plan of a task of A through one of some operators, asked for one
// modification after another: a small task is explored whole at the first question and
// answers every later one; a larger one gets a flagged search per question.
class ThroughSearch {
public:
    ThroughSearch(const ground::GroundTask &task, const Deadline &deadline, long long &searches)
        : task_(task), deadline_(deadline), searches_(searches) {}

    // nullopt when a limit stopped the search, with `proven` set to what it had proven.
    std::optional<double> least_using(const std::set<int> &steps, double &proven) {
        if (!explored_) {
            explored_ = true;
            through_ = search::least_cost_through_operators(task_, EXPLORED_STATES,
                                                            [&] { return deadline_.expired(); });
            ++searches_;
        }
        if (through_) {
            double found = INF;
            for (int o : steps)
                found = std::min(found, (*through_)[o]);
            return found;
        }
        if (!flagged_)
            flagged_.emplace(task_);
        std::optional<double> found = flagged_->least_cost_using(steps, deadline_, proven);
        ++searches_;
        return found;
    }

private:
    const ground::GroundTask &task_;
    const Deadline &deadline_;
    long long &searches_;
    bool explored_ = false;
    std::optional<std::vector<double>> through_; // per operator, from the exploration
    std::optional<FlaggedTask> flagged_;
};

// `domain` and `problem` grounded with every operator kept (every plan of A is a plan of the
// ground task), and its operators indexed. False, with `why`, when they do not ground.
bool ground_all(const pddl::Domain &domain, const pddl::Problem &problem, const Deadline &deadline,
                ground::GroundTask &task, std::optional<OperatorIndex> &index, std::string &why) {
    try {
        task = ground::ground(
            domain, problem, nullptr, [&] { return deadline.expired(); }, false);
        index.emplace(domain, problem, task);
    } catch (const std::exception &e) {
        why = std::string("the design of every adding modification does not ground: ") + e.what();
        return false;
    }
    return true;
}

// One model of A for one task: its floors for every modification in `adding`, kept where at
// most `floor`. False, with `why`, when it does not ground or the deadline passes first.
bool model_floors(const DesignProblem &problem, const std::vector<int> &adding,
                  const pddl::Domain &domain, const pddl::Problem &pddl_problem,
                  const Naming &naming, double floor, const Deadline &deadline,
                  std::vector<UseFloor> &below, long long &searches, std::string &why) {
    ground::GroundTask task;
    std::optional<OperatorIndex> index;
    if (!ground_all(domain, pddl_problem, deadline, task, index, why))
        return false;
    // The least over every plan of A: a floor for every e; above `floor`, no adding
    // modification can lower it.
    auto least = least_cost(task, deadline);
    ++searches;
    if (!least) {
        why = "a time limit stopped the floors of adding modifications";
        return false;
    }
    if (*least > floor)
        return true;
    std::vector<double> prefix = cheapest_prefix(task);
    ThroughSearch through(task, deadline, searches);
    for (int e : adding) {
        auto steps = users(problem.modifications[e], *index, naming);
        double cost = *least;
        if (steps && steps->empty())
            continue; // no plan of A uses it
        if (steps) {
            double cheapest = INF; // a plan using e costs at least this: no search needed
            for (int o : *steps)
                cheapest = std::min(cheapest, prefix[o]);
            if (cheapest > floor)
                continue;
            double proven = 0; // by a search its cap stopped
            std::optional<double> found = through.least_using(*steps, proven);
            if (!found && deadline.expired()) {
                why = "a time limit stopped the floors of adding modifications";
                return false;
            }
            // A planner limit: what the search proved, or the floor of every plan.
            cost = found.value_or(std::max(*least, proven));
        }
        if (cost <= floor)
            below.push_back({e, cost});
    }
    return true;
}

} // namespace

std::optional<AdditionFloors> addition_floors(const DesignProblem &problem,
                                              const std::vector<int> &adding,
                                              const std::vector<double> &floor,
                                              const std::vector<std::optional<double>> &robot_floor,
                                              const Deadline &deadline, std::string &why) {
    auto start = std::chrono::steady_clock::now();
    AdditionFloors out;
    int tasks = static_cast<int>(problem.tasks.size());
    out.below.resize(tasks);
    out.robot_below.resize(tasks);
    for (int t = 0; t < tasks && !adding.empty(); ++t) {
        if (problem.tasks[t].probability <= 0)
            continue;
        ModelPair models = configured_models(problem, adding, t);
        std::optional<CompiledTask> compiled;
        try {
            compiled = compile_explicable(models);
        } catch (const std::exception &e) {
            why = std::string("the design of every adding modification does not compile: ") +
                  e.what();
            return std::nullopt;
        }
        bool ok = floor[t] == -INF || // no floor asked for: nothing is below it
                  model_floors(problem, adding, compiled->domain, compiled->problem, in_compilation,
                               floor[t], deadline, out.below[t], out.searches, why);
        if (ok && robot_floor[t])
            ok = model_floors(problem, adding, models.robot_domain, models.robot_problem,
                              in_robot_model, *robot_floor[t], deadline, out.robot_below[t],
                              out.searches, why);
        if (!ok) {
            why += " (task '" + problem.tasks[t].name + "')";
            return std::nullopt;
        }
    }
    out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return out;
}

} // namespace envdesign::design
