#include "design/witness_bound.h"

#include <algorithm>
#include <cmath>
#include <iterator>

namespace envdesign::design::witness {

bool contains(const std::vector<int> &sorted, int value) {
    return std::binary_search(sorted.begin(), sorted.end(), value);
}

SupersetBound::SupersetBound(const DesignProblem &problem, const TouchIndex &index)
    : problem_(problem), index_(index), tasks_(static_cast<int>(problem.tasks.size())),
      pool_(tasks_), horizon_(discounted_horizon(problem.weights)),
      floors_hold_(problem.weights.behaviour == RobotBehaviour::EXPLICABLE) {
    for (int m = 0; m < index.size(); ++m) {
        const ModificationClass &c = index.of(m);
        bool negative = problem.weights.beta * problem.modifications[m].cost < 0;
        if (!c.restricting || negative)
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
    std::vector<int> needs;
    for (int m : always_)
        if (contains(c, m))
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
    return std::any_of(always_.begin(), always_.end(),
                       [&](int m) { return !contains(node.configuration, m); });
}

// Every modification outside the node is restricting, of non-negative weighted cost: a
// task keeps its value unless a touching modification is added, c_H(pi) never drops, and
// the human's optimum is at most the cost of any known plan still valid. To bring it
// above the k-th cheapest such plan, every cheaper one must be broken; the costs of the
// modifications that do it are shared among the tasks they can change.
double SupersetBound::restricted_bound(const Node &node) const {
    const Configuration &c = node.configuration;
    const ObjectiveWeights &w = problem_.weights;
    Scratch &s = scratch_;
    int n = index_.size();
    s.reset(tasks_, n);
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
    double total = objective_lower_bound(problem_, node.cost, settled, node.robot_bounds);
    if (std::isinf(total))
        return total;
    // Any split of each modification's cost among the tasks whose plans it breaks gives
    // a bound: start even, then give each cost to the tasks that used it (a few rounds;
    // the best round counts).
    auto cost = [&](int m) { return w.beta * problem_.modifications[m].cost; };
    for (int t = 0; t < tasks_; ++t)
        for (const PooledPlan *plan : s.plans[t])
            for (int m : plan->breakers)
                s.share[t * n + m] = cost(m) / s.degree[m];
    double least_ie = w.distance == Distance::COST_DIFF ? 0.0 : 1.0;
    double best_extra = 0;
    for (int round = 0; round < 4; ++round) {
        double extra = 0;
        std::fill(s.users.begin(), s.users.end(), 0);
        for (int t = 0; t < tasks_; ++t) {
            if (s.plans[t].empty())
                continue;
            double weight = w.alpha * horizon_ * problem_.tasks[t].probability;
            extra += level_bound(s.plans[t], &s.share[t * n], floor(node, t), weight, least_ie,
                                 s.used[t]) -
                     weight * least_ie; // the least value is counted already
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
                        share[m] = s.mark[m] == round * tasks_ + t + 1 ? cost(m) / s.users[m] : 0.0;
        }
    }
    return total + best_extra;
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
    const Configuration &c = node.configuration;
    const ObjectiveWeights &w = problem_.weights;
    auto outside = [&](const std::vector<int> &mods) {
        return std::any_of(mods.begin(), mods.end(), [&](int m) { return !contains(c, m); });
    };
    bool always_outside = outside(always_);
    bool robot_monotone = !outside(robot_relaxing_);
    double negative = 0;
    for (int m : negative_)
        if (!contains(c, m))
            negative += w.beta * problem_.modifications[m].cost;

    // Per task: its value if it is settled for every superset, else its least value.
    std::vector<const TaskExplicability *> settled(tasks_, nullptr);
    std::vector<std::optional<double>> robot_bounds(tasks_);
    std::vector<std::vector<int>> open_touching(tasks_);
    std::vector<bool> shares(tasks_, false);
    std::vector<int> degree(index_.size(), 0);
    for (int t = 0; t < tasks_; ++t) {
        if (robot_monotone)
            robot_bounds[t] = node.robot_bounds[t];
        const Record &r = node.tasks[t];
        if (!r || !r->touch.known || problem_.tasks[t].probability <= 0)
            continue;
        for (int m : r->touch.all)
            if (!contains(c, m))
                open_touching[t].push_back(m);
        if (open_touching[t].empty() && !always_outside) {
            settled[t] = &r->evaluation;
            continue;
        }
        if (r->evaluation.status != ExplicabilityStatus::SOLVED || negative < 0)
            continue;
        shares[t] = true;
        for (int m : open_touching[t])
            ++degree[m];
        for (int m : always_)
            degree[m] += contains(c, m) ? 0 : 1;
    }
    double total = objective_lower_bound(problem_, node.cost, settled, robot_bounds);
    if (std::isinf(total))
        return total;
    total += negative;
    // Shared costs: a task keeps its value unless a modification touching it is added.
    double horizon = discounted_horizon(w);
    double least_ie = w.distance == Distance::COST_DIFF ? 0.0 : 1.0;
    for (int t = 0; t < tasks_; ++t) {
        if (!shares[t])
            continue;
        const TaskExplicability &e = node.tasks[t]->evaluation;
        double p = problem_.tasks[t].probability;
        double robot_least = robot_bounds[t].value_or(0.0);
        double excess = w.alpha * horizon * p * (e.ie - least_ie) +
                        w.kappa * w.horizon * p * (e.robot_cost - robot_least);
        double share = INF;
        auto consider = [&](int m) {
            share = std::min(share, w.beta * problem_.modifications[m].cost / degree[m]);
        };
        for (int m : open_touching[t])
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

} // namespace envdesign::design::witness
