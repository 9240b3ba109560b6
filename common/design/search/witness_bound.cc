#include "design/search/witness_bound.h"

#include "design/behaviour/behaviour.h"

#include <algorithm>
#include <cmath>
#include <iterator>

namespace envdesign::design::witness {
namespace {

// Whether some of `mods` are not in `c`.
bool any_outside(const std::vector<int> &mods, const Configuration &c) {
    return std::any_of(mods.begin(), mods.end(), [&](int m) { return !contains(c, m); });
}

} // namespace

bool contains(const std::vector<int> &sorted, int value) {
    return std::binary_search(sorted.begin(), sorted.end(), value);
}

SupersetBound::SupersetBound(const DesignProblem &problem, const TouchIndex &index,
                             bool weigh_every_modification)
    : problem_(problem), index_(index), tasks_(static_cast<int>(problem.tasks.size())),
      pool_(tasks_), horizon_(discounted_horizon(problem.weights)),
      floors_hold_(behaviour_of(problem.weights.behaviour).takes_most_explicable_plan) {
    for (int m = 0; m < index.size(); ++m) {
        const ModificationClass &c = index.of(m);
        bool negative = problem.weights.beta * problem.modifications[m].cost < 0;
        if (!c.restricting || negative || weigh_every_modification)
            always_.push_back(m);
        if (!c.robot_restricting)
            robot_relaxing_.push_back(m);
        if (negative)
            negative_.push_back(m);
    }
}

TaskExplicability values_only(const TaskExplicability &e) {
    TaskExplicability out;
    out.status = e.status;
    out.ie = e.ie;
    out.robot_cost = e.robot_cost;
    out.human_plan_cost = e.human_plan_cost;
    out.human_optimal_cost = e.human_optimal_cost;
    return out;
}

void raise_floor(Node &node, int t, const TaskExplicability &e) {
    if (e.status == ExplicabilityStatus::SOLVED)
        node.explicable_floor[t] = std::max(node.explicable_floor[t], e.human_plan_cost);
}

// Keeps both witnesses of a new evaluation as plans of the human's model (a most
// explicable plan is one too, at its human cost).
void SupersetBound::learn(const Configuration &c, int t, const TaskExplicability &e) {
    if (e.status != ExplicabilityStatus::SOLVED || !e.human_plan || !e.human_optimal_cost)
        return;
    std::vector<int> needs; // what made the human's model hold them: not a robot-only edit
    for (int m : always_)
        if (contains(c, m) && index_.of(m).edits_human)
            needs.push_back(m);
    auto keep = [&](const std::vector<std::string> &plan, double cost) {
        auto touching = index_.touching_human_plan(c, t, plan);
        if (!touching)
            return;
        PooledPlan p{cost, {}, needs, std::make_shared<std::vector<std::string>>(plan)};
        for (int m : *touching)
            if (!contains(c, m))
                p.breakers.push_back(m);
        for (int m : always_) // an adding modification never breaks a plan
            if (!contains(c, m) && !index_.of(m).adding)
                p.breakers.push_back(m);
        std::sort(p.breakers.begin(), p.breakers.end());
        p.breakers.erase(std::unique(p.breakers.begin(), p.breakers.end()), p.breakers.end());
        pool_[t].insert(std::move(p));
    };
    keep(*e.human_plan, *e.human_optimal_cost);
    if (std::isfinite(e.human_plan_cost)) // else (COST_OPTIMAL) `plan` is not a human plan
        keep(e.plan, e.human_plan_cost);
}

// When `m` touches only the human's witness of `r`, and a known plan as cheap is still
// valid with `m` added: the human's optimum cannot drop (m is restricting), so that plan
// is optimal, pi is still optimal, and the evaluation is the same, with new witnesses.
Record SupersetBound::equally_cheap(int t, const TaskRecord &r, int m,
                                    const Configuration &c) const {
    const TaskExplicability &e = r.evaluation;
    if (!r.touch.known || e.status != ExplicabilityStatus::SOLVED || !e.human_optimal_cost ||
        contains(r.touch.explicable, m))
        return nullptr;
    double cost = *e.human_optimal_cost;
    auto it = pool_[t].lower_bound(PooledPlan{cost, {}, {}, nullptr});
    for (; it != pool_[t].end() && it->cost == cost; ++it) {
        if (!valid_in(*it, c))
            continue;
        auto record = std::make_shared<TaskRecord>(r);
        record->evaluation.human_plan = *it->steps;
        record->touch.human.clear();
        for (int b : it->breakers)
            if (index_.of(b).restricting)
                record->touch.human.push_back(b);
        record->touch.all.clear();
        std::set_union(r.touch.explicable.begin(), r.touch.explicable.end(),
                       record->touch.human.begin(), record->touch.human.end(),
                       std::back_inserter(record->touch.all));
        return record;
    }
    return nullptr;
}

// A lower bound on the objective of `node`'s configuration and of every superset.
double SupersetBound::operator()(const Node &node) const {
    return always_outside(node) ? open_bound(node) : restricted_bound(node);
}

bool SupersetBound::always_outside(const Node &node) const {
    return any_outside(always_, node.configuration);
}

// Every modification outside the node is restricting, of non-negative weighted cost: a
// task keeps its value unless a touching modification is added, c_H(pi) never drops, and
// the human's optimum is at most the cost of any known plan still valid. To bring it
// above the k-th cheapest such plan, every cheaper one must be broken; the costs of the
// modifications that do it are shared among the tasks they can change.
double SupersetBound::restricted_bound(const Node &node) const {
    scratch_.reset(tasks_, index_.size());
    std::vector<const TaskExplicability *> settled = settled_or_pooled(node);
    double total = objective_lower_bound(problem_, node.cost, settled, node.robot_bounds);
    if (std::isinf(total))
        return total;
    return total + breaking_extra(node);
}

// Per task of positive probability: its evaluation if every modification touching it is in
// the node (it holds in every superset); else, in scratch_, the known plans still valid and
// cheaper than its floor, and per modification the number of tasks whose plans it breaks.
std::vector<const TaskExplicability *> SupersetBound::settled_or_pooled(const Node &node) const {
    const Configuration &c = node.configuration;
    Scratch &s = scratch_;
    std::vector<const TaskExplicability *> settled(tasks_, nullptr);
    for (int t = 0; t < tasks_; ++t) {
        if (problem_.tasks[t].probability <= 0)
            continue;
        const Record &r = node.tasks[t];
        if (r && r->touch.known &&
            std::all_of(r->touch.all.begin(), r->touch.all.end(),
                        [&](int m) { return contains(c, m); })) {
            settled[t] = &r->evaluation;
            continue;
        }
        for (const PooledPlan &plan : pool_[t]) {
            if (plan.cost >= floor(node, t))
                break;
            if (!valid_in(plan, c))
                continue;
            s.plans[t].push_back(&plan);
            for (int m : plan.breakers)
                if (s.stamp[m] != t)
                    s.stamp[m] = t, ++s.degree[m];
        }
    }
    return settled;
}

// What breaking the pooled plans of settled_or_pooled adds to the bound. Any split of each
// modification's cost among the tasks whose plans it breaks gives a bound: start even, then
// give each cost to the tasks that used it (a few rounds; the best round counts).
double SupersetBound::breaking_extra(const Node &node) const {
    const ObjectiveWeights &w = problem_.weights;
    Scratch &s = scratch_;
    int n = index_.size();
    for (int t = 0; t < tasks_; ++t)
        for (const PooledPlan *plan : s.plans[t])
            for (int m : plan->breakers)
                s.share[t * n + m] = weighted_cost(m) / s.degree[m];
    const double least = least_ie(w.distance);
    double best_extra = 0;
    for (int round = 0; round < 4; ++round) {
        double extra = 0;
        std::fill(s.users.begin(), s.users.end(), 0);
        for (int t = 0; t < tasks_; ++t) {
            if (s.plans[t].empty())
                continue;
            double weight = w.alpha * horizon_ * problem_.tasks[t].probability;
            extra += level_bound(s.plans[t], &s.share[t * n], floor(node, t), weight, least,
                                 s.used[t]) -
                     weight * least; // the least value is counted already
            for (int m : s.used[t])
                ++s.users[m];
        }
        best_extra = std::max(best_extra, extra);
        for (int t = 0; t < tasks_; ++t) {
            for (int m : s.used[t])
                s.mark[m] = round * tasks_ + t + 1;
            double *share = &s.share[t * n];
            for (const PooledPlan *plan : s.plans[t])
                for (int m : plan->breakers)
                    if (s.users[m] > 0)
                        share[m] = s.mark[m] == round * tasks_ + t + 1
                                       ? weighted_cost(m) / s.users[m]
                                       : 0.0;
        }
    }
    return best_extra;
}

// The least IE term of one task over supersets, given the plans valid there (by cost)
// and what breaking each costs this task (`share`): to keep the human's optimum above
// the k-th plan, the k cheaper ones must be broken, at least one modification from each
// of a family of disjoint breaker sets. `used` gets the modifications of that family at
// the least value.
double SupersetBound::level_bound(const std::vector<const PooledPlan *> &plans, const double *share,
                                  double floor, double weight, double least_ie,
                                  std::vector<int> &used) const {
    auto value = [&](double human_optimum) { // the IE term when c_H* <= human_optimum
        double gap = floor - human_optimum;
        if (gap <= 0)
            return weight * least_ie;
        return weight * (least_ie == 0 ? gap : std::exp(gap));
    };
    Scratch &s = scratch_;
    s.packed.clear();
    int stamp = ++s.taken_stamp;
    double best = value(plans[0]->cost), hitting = 0;
    std::size_t best_packed = 0;
    for (std::size_t j = 0; j < plans.size(); ++j) {
        const auto &breakers = plans[j]->breakers;
        if (breakers.empty())
            break; // nothing can break it: the optimum stays at most its cost
        if (std::none_of(breakers.begin(), breakers.end(),
                         [&](int m) { return s.taken[m] == stamp; })) {
            double cheapest = INF;
            for (int m : breakers) {
                s.taken[m] = stamp;
                cheapest = std::min(cheapest, share[m]);
            }
            hitting += cheapest;
            s.packed.push_back(&breakers);
        }
        double next = j + 1 < plans.size() ? value(plans[j + 1]->cost) : weight * least_ie;
        if (next + hitting < best) {
            best = next + hitting;
            best_packed = s.packed.size();
        }
    }
    used.clear();
    for (std::size_t k = 0; k < best_packed; ++k)
        used.insert(used.end(), s.packed[k]->begin(), s.packed[k]->end());
    return best;
}

bool SupersetBound::valid_in(const PooledPlan &plan, const Configuration &c) const {
    return std::all_of(plan.needs.begin(), plan.needs.end(),
                       [&](int m) { return contains(c, m); }) &&
           std::none_of(plan.breakers.begin(), plan.breakers.end(),
                        [&](int m) { return contains(c, m); });
}

// Some modification outside the node is added everywhere (not restricting, or of
// negative cost): only what holds whatever those do.
double SupersetBound::open_bound(const Node &node) const {
    double negative = 0;
    for (int m : negative_)
        if (!contains(node.configuration, m))
            negative += weighted_cost(m);
    OpenTasks open = open_tasks(node, negative < 0);
    double total = objective_lower_bound(problem_, node.cost, open.settled, open.robot_bounds);
    if (std::isinf(total))
        return total;
    return with_open_shares(node, open, total + negative);
}

// Per task: its value if it is settled for every superset, else its least value, and whether
// the excess is bounded by a share of the costs of what touches it (none while a modification
// of negative cost is outside: `lowered`).
SupersetBound::OpenTasks SupersetBound::open_tasks(const Node &node, bool lowered) const {
    const Configuration &c = node.configuration;
    bool always_out = always_outside(node);
    bool robot_monotone = !any_outside(robot_relaxing_, c);
    OpenTasks open{std::vector<const TaskExplicability *>(tasks_, nullptr),
                   std::vector<std::optional<double>>(tasks_),
                   std::vector<std::vector<int>>(tasks_), std::vector<bool>(tasks_, false),
                   std::vector<int>(index_.size(), 0)};
    for (int t = 0; t < tasks_; ++t) {
        if (robot_monotone)
            open.robot_bounds[t] = node.robot_bounds[t];
        const Record &r = node.tasks[t];
        if (!r || !r->touch.known || problem_.tasks[t].probability <= 0)
            continue;
        for (int m : r->touch.all)
            if (!contains(c, m))
                open.touching[t].push_back(m);
        if (open.touching[t].empty() && !always_out) {
            open.settled[t] = &r->evaluation;
            continue;
        }
        if (r->evaluation.status != ExplicabilityStatus::SOLVED || lowered)
            continue;
        open.shares[t] = true;
        for (int m : open.touching[t])
            ++open.degree[m];
        for (int m : always_)
            open.degree[m] += contains(c, m) ? 0 : 1;
    }
    return open;
}

// `total` plus the shared costs: a task keeps its value unless a modification touching it is
// added.
double SupersetBound::with_open_shares(const Node &node, const OpenTasks &open,
                                       double total) const {
    const Configuration &c = node.configuration;
    const ObjectiveWeights &w = problem_.weights;
    double horizon = discounted_horizon(w);
    const double least = least_ie(w.distance);
    for (int t = 0; t < tasks_; ++t) {
        if (!open.shares[t])
            continue;
        const TaskExplicability &e = node.tasks[t]->evaluation;
        double p = problem_.tasks[t].probability;
        double robot_least = open.robot_bounds[t].value_or(0.0);
        double excess = w.alpha * horizon * p * (e.ie - least) +
                        w.kappa * w.horizon * p * (e.robot_cost - robot_least);
        double share = INF;
        auto consider = [&](int m) { share = std::min(share, weighted_cost(m) / open.degree[m]); };
        for (int m : open.touching[t])
            consider(m);
        for (int m : always_)
            if (!contains(c, m))
                consider(m);
        double extra = std::min(excess, share);
        if (extra > 0 && std::isfinite(extra))
            total += extra;
    }
    return total;
}

std::vector<std::string> SupersetBound::weighed_everywhere_notes() const {
    std::vector<std::string> notes;
    std::vector<std::string> adding;
    for (int m : always_) {
        const ModificationClass &c = index_.of(m);
        const Modification &mod = problem_.modifications[m];
        if (!c.restricting && c.adding && problem_.weights.beta * mod.cost >= 0) {
            adding.push_back("'" + mod.name + "'");
            continue;
        }
        notes.push_back(
            "modification '" + mod.name + "' " +
            (c.restricting ? "has a negative cost" : "is not restricting (" + c.why_not + ")") +
            ": the search weighs it with every design, not only where a witness plan uses "
            "what it changes");
    }
    if (adding.empty())
        return notes;
    std::string names;
    for (std::size_t i = 0; i < adding.size() && i < 5; ++i)
        names += (i ? ", " : "") + adding[i];
    if (adding.size() > 5)
        names += " and " + std::to_string(adding.size() - 5) + " more";
    notes.push_back(std::to_string(adding.size()) +
                    (adding.size() == 1 ? " modification adds" : " modifications add") +
                    " plans (" + names +
                    "): the search weighs each with every design, and bounds it by "
                    "the floors it can lower (docs/design-search.md)");
    return notes;
}

} // namespace envdesign::design::witness
