#include "design/witness_search.h"

#include "design/witness.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iterator>
#include <map>
#include <memory>
#include <queue>
#include <set>
#include <tuple>
#include <unordered_set>

namespace envdesign::design {
namespace {

// A task's evaluation under some configuration, with the modifications that can change it.
struct TaskRecord {
    TaskExplicability evaluation;
    WitnessTouch touch; // the restricting modifications touching its witnesses
};
using Record = std::shared_ptr<const TaskRecord>;

struct Node {
    Configuration configuration;
    std::vector<Record> tasks;                       // null: to be evaluated
    std::vector<std::optional<double>> robot_bounds; // c_R* under this configuration
    // Per task, a lower bound on c_H(pi) here and in every superset made by restricting
    // modifications (the optimum of P_mod only rises when plans are removed); 0: none.
    std::vector<double> explicable_floor;
    double cost = 0;  // C(xi)
    double bound = 0; // on the objective of this configuration and of every superset
};

// A plan known to be valid in the human's model of some configuration xi: valid in every
// configuration that keeps xi's everywhere-added modifications (`needs`) and adds none of
// `breakers` (the restricting ones that touch it, and the everywhere-added ones outside xi).
// So the human's optimal cost there is at most `cost`.
struct PooledPlan {
    double cost = 0;
    std::vector<int> breakers;
    std::vector<int> needs;
    std::shared_ptr<const std::vector<std::string>> steps;
    bool operator<(const PooledPlan &o) const {
        return std::tie(cost, breakers, needs) < std::tie(o.cost, o.breakers, o.needs);
    }
};

// Least bound first; then the order in which SPEC.md breaks ties.
struct LaterInQueue {
    bool operator()(const Node &a, const Node &b) const {
        if (a.bound != b.bound)
            return a.bound > b.bound;
        if (a.configuration.size() != b.configuration.size())
            return a.configuration.size() > b.configuration.size();
        if (a.cost != b.cost)
            return a.cost > b.cost;
        return a.configuration > b.configuration;
    }
};

// The queue of configurations to evaluate, least bound first; pop() moves the node out.
class OpenList {
public:
    bool empty() const { return heap_.empty(); }
    std::size_t size() const { return heap_.size(); }
    const Node &top() const { return heap_.front(); }
    void push(Node node) {
        heap_.push_back(std::move(node));
        std::push_heap(heap_.begin(), heap_.end(), LaterInQueue{});
    }
    Node pop() {
        std::pop_heap(heap_.begin(), heap_.end(), LaterInQueue{});
        Node node = std::move(heap_.back());
        heap_.pop_back();
        return node;
    }
    void clear() { heap_.clear(); }

private:
    std::vector<Node> heap_;
};

// What the evaluator needs of a task known already: its values, not its plans.
TaskExplicability values_only(const TaskExplicability &e) {
    TaskExplicability out;
    out.status = e.status;
    out.ie = e.ie;
    out.robot_cost = e.robot_cost;
    out.human_plan_cost = e.human_plan_cost;
    out.human_optimal_cost = e.human_optimal_cost;
    return out;
}

bool contains(const std::vector<int> &sorted, int value) {
    return std::binary_search(sorted.begin(), sorted.end(), value);
}

class WitnessSearch {
public:
    WitnessSearch(const DesignProblem &problem, Evaluator &evaluator,
                  const DesignSearchOptions &options,
                  const std::function<void(const SearchProgress &)> &progress)
        : problem_(problem), evaluator_(evaluator), options_(options), progress_(progress),
          index_(problem), tasks_(static_cast<int>(problem.tasks.size())), pool_(tasks_) {
        const double beta = problem.weights.beta;
        for (int m = 0; m < index_.size(); ++m) {
            const ModificationClass &c = index_.of(m);
            const Modification &mod = problem.modifications[m];
            bool negative = beta * mod.cost < 0;
            if (!c.restricting)
                result_.notes.push_back("modification '" + mod.name + "' is not restricting (" +
                                        c.why_not + "): added to every configuration");
            else if (negative)
                result_.notes.push_back("modification '" + mod.name +
                                        "' has a negative cost: added to every configuration");
            if (!c.restricting || negative)
                always_.push_back(m);
            if (!c.robot_restricting)
                robot_relaxing_.push_back(m);
            if (negative)
                negative_.push_back(m);
        }
        max_size_ = options.max_design_size > 0 ? options.max_design_size : index_.size();
    }

    DesignResult run() {
        auto start = std::chrono::steady_clock::now();
        Node root{{},
                  std::vector<Record>(tasks_),
                  std::vector<std::optional<double>>(tasks_),
                  std::vector<double>(tasks_, 0.0)};
        root.bound = bound(root);
        visited_.insert(root.configuration);
        ++generated_;
        open_.push(std::move(root));
        bool interrupted = false;
        bool probed = false;
        while (!open_.empty()) {
            if (options_.deadline.expired()) {
                interrupted = true;
                break;
            }
            evaluate(next_batch());
            if (!probed && result_.baseline) {
                probe_shortcuts();
                probed = true;
            }
        }
        result_.limit_reached = interrupted || limit_seen_;
        result_.optimal = !result_.limit_reached;
        if (result_.limit_reached) {
            double least = std::min(open_.empty() ? INF : open_.top().bound, least_unfinished_);
            result_.gap = result_.best ? std::max(0.0, result_.best->objective.value - least) : INF;
        }
        auto &counters = result_.counters;
        counters.configurations_total = generated_;
        counters.evaluator = evaluator_.counters();
        counters.seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        report();
        return std::move(result_);
    }

private:
    // The next configurations worth evaluating, least bound first.
    std::vector<Node> next_batch() {
        std::vector<Node> batch;
        while (!open_.empty() &&
               static_cast<int>(batch.size()) < std::max(1, options_.batch_size)) {
            if (result_.best && clearly_greater(open_.top().bound, result_.best->objective.value)) {
                skip(static_cast<long long>(open_.size())); // every other bound is larger
                open_.clear();
                break;
            }
            Node node = open_.pop();
            double now = bound(node); // plans learnt since it was queued may raise it
            if (clearly_greater(now, node.bound)) {
                node.bound = now;
                open_.push(std::move(node));
                continue;
            }
            if (can_win(node.bound, node.configuration.size()))
                batch.push_back(std::move(node));
            else
                skip(1);
        }
        return batch;
    }

    void evaluate(std::vector<Node> batch) {
        if (batch.empty())
            return;
        std::vector<ConfigurationEvaluation> requests;
        std::map<Configuration, std::size_t> position;
        for (std::size_t i = 0; i < batch.size(); ++i) {
            if (blind(batch[i]))
                grow(batch[i]);
            if (std::all_of(batch[i].tasks.begin(), batch[i].tasks.end(),
                            [](const Record &r) { return r != nullptr; })) {
                // Known in full from smaller configurations: nothing to ask anyone.
                ConfigurationEvaluation known = unevaluated(batch[i].configuration);
                known.status = EvaluationStatus::COMPLETE;
                finish(batch[i], std::move(known));
                continue;
            }
            ConfigurationEvaluation r = unevaluated(batch[i].configuration);
            r.robot_cost_bounds = batch[i].robot_bounds;
            for (const auto &record : batch[i].tasks)
                r.tasks.push_back(record ? std::optional(values_only(record->evaluation))
                                         : std::nullopt);
            position[r.configuration] = i;
            requests.push_back(std::move(r));
        }
        EvaluationCallbacks callbacks;
        callbacks.abandon = [&](const ConfigurationEvaluation &partial) {
            const Node &node = batch[position.at(partial.configuration)];
            if (blind(node)) // grown already: only its own objective matters
                return !can_win(own_bound(node.cost, partial), node.configuration.size());
            Node known = node; // what the answers so far add; their witnesses are not read yet
            for (int t = 0; t < tasks_; ++t) {
                if (!known.robot_bounds[t] &&
                    t < static_cast<int>(partial.robot_cost_bounds.size()))
                    known.robot_bounds[t] = partial.robot_cost_bounds[t];
                if (t < static_cast<int>(partial.tasks.size()) && partial.tasks[t])
                    raise_floor(known, t, *partial.tasks[t]);
            }
            if (!can_win(bound(known), node.configuration.size()))
                return true;
            // With modifications outside that are added everywhere, the bound of the subtree
            // is weak and its witnesses narrow little: when the configuration itself cannot
            // win, stop evaluating it and grow it by every modification instead.
            if (always_outside(node) &&
                !can_win(own_bound(node.cost, partial), node.configuration.size())) {
                grow_without_witnesses_.insert(node.configuration);
                return true;
            }
            return false;
        };
        callbacks.done = [&](ConfigurationEvaluation e) {
            Node &node = batch[position.at(e.configuration)];
            finish(node, std::move(e));
        };
        evaluator_.evaluate(requests, options_.deadline, callbacks);
    }

    void finish(Node &node, ConfigurationEvaluation e) {
        auto &counters = result_.counters;
        if (e.status == EvaluationStatus::LIMIT) {
            limit_seen_ = true;
            least_unfinished_ = std::min(least_unfinished_, node.bound);
            return;
        }
        ++done_;
        if (e.status == EvaluationStatus::CUT_OFF) {
            ++counters.configurations_abandoned;
            if (grow_without_witnesses_.erase(node.configuration) > 0) {
                std::fill(node.tasks.begin(), node.tasks.end(), nullptr);
                grow(node); // every modification is a candidate, nothing is inherited
            }
            report();
            return;
        }
        ++counters.configurations_evaluated;
        std::vector<const TaskExplicability *> evaluations;
        for (int t = 0; t < tasks_; ++t) {
            if (node.tasks[t]) {
                ++counters.tasks_inherited;
            } else {
                auto record = std::make_shared<TaskRecord>();
                record->evaluation = std::move(*e.tasks[t]);
                record->touch = index_.touching(node.configuration, t, record->evaluation);
                learn_plans(node.configuration, t, record->evaluation);
                node.tasks[t] = std::move(record);
            }
            if (!node.robot_bounds[t] && t < static_cast<int>(e.robot_cost_bounds.size()))
                node.robot_bounds[t] = e.robot_cost_bounds[t];
            raise_floor(node, t, node.tasks[t]->evaluation);
            evaluations.push_back(&node.tasks[t]->evaluation);
        }
        // Copies of the evaluations only for a design that ranks first.
        double value = objective_lower_bound(problem_, node.cost, evaluations); // all known
        if (can_win(value, node.configuration.size()) || node.configuration.empty()) {
            std::vector<TaskExplicability> copies;
            for (const auto *e : evaluations)
                copies.push_back(*e);
            consider_design(problem_, node.configuration, std::move(copies), result_);
        }
        if (!blind(node)) {
            node.bound = bound(node);
            grow(node);
        }
        report();
    }

    // Queues the configurations one modification larger that can matter (witness_search.h).
    void grow(const Node &node) {
        const Configuration &c = node.configuration;
        if (static_cast<int>(c.size()) >= max_size_ || !can_win(node.bound, c.size() + 1))
            return;
        for (int m : candidates(node)) {
            Configuration child_configuration = c;
            child_configuration.insert(
                std::upper_bound(child_configuration.begin(), child_configuration.end(), m), m);
            if (!visited_.insert(child_configuration).second)
                continue;
            ++generated_;
            const ModificationClass &k = index_.of(m);
            Node child{std::move(child_configuration),
                       node.tasks,
                       node.robot_bounds,
                       node.explicable_floor,
                       node.cost + problem_.modifications[m].cost,
                       0};
            for (int t = 0; t < tasks_; ++t) {
                const Record &r = node.tasks[t];
                if (!r || !k.restricting || !r->touch.known || contains(r->touch.all, m))
                    child.tasks[t] =
                        r && k.restricting ? equally_cheap(t, *r, m, child.configuration) : nullptr;
                if (k.edits_robot)
                    child.robot_bounds[t].reset();
                if (!k.restricting)
                    child.explicable_floor[t] = 0;
            }
            child.bound = bound(child);
            if (can_win(child.bound, child.configuration.size()))
                open_.push(std::move(child));
            else
                skip(1);
        }
    }

    // When `m` touches only the human's witness of `r`, and a known plan as cheap is still
    // valid with `m` added: the human's optimum cannot drop (m is restricting), so that plan
    // is optimal, pi is still optimal, and the evaluation is the same, with new witnesses.
    Record equally_cheap(int t, const TaskRecord &r, int m, const Configuration &c) const {
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

    static void raise_floor(Node &node, int t, const TaskExplicability &e) {
        if (e.status == ExplicabilityStatus::SOLVED)
            node.explicable_floor[t] = std::max(node.explicable_floor[t], e.human_plan_cost);
    }

    // Keeps both witnesses of a new evaluation as plans of the human's model (a most
    // explicable plan is one too, at its human cost).
    void learn_plans(const Configuration &c, int t, const TaskExplicability &e) {
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
            for (int m : always_)
                if (!contains(c, m))
                    p.breakers.push_back(m);
            std::sort(p.breakers.begin(), p.breakers.end());
            p.breakers.erase(std::unique(p.breakers.begin(), p.breakers.end()), p.breakers.end());
            pool_[t].insert(std::move(p));
        };
        keep(*e.human_plan, *e.human_optimal_cost);
        keep(e.plan, e.human_plan_cost);
    }

    // Before the search proper, when every modification is restricting: meets each task's
    // plans of the human's model that are cheaper than its most explicable plan. A probe
    // design breaks every such plan known; the human's optimal plan there is either another
    // one (whose breakers are new, since it avoids all the others) or no cheaper, and then
    // the known ones are all there is to break. Probes are real designs, evaluated as such;
    // what they add is plans for the bounds and, within the size limit, designs to beat.
    void probe_shortcuts() {
        if (!always_.empty())
            return;
        std::set<int> active;
        for (int t = 0; t < tasks_; ++t)
            if (problem_.tasks[t].probability > 0 &&
                result_.baseline->tasks[t].status == ExplicabilityStatus::SOLVED)
                active.insert(t);
        std::set<Configuration> tried{{}};
        for (int round = 0; round < 64 && !active.empty() && !options_.deadline.expired();
             ++round) {
            std::map<Configuration, std::vector<int>> probes; // design -> the tasks it probes
            std::vector<int> shared(index_.size(), 0);        // how many tasks' plans each breaks
            for (int t = 0; t < tasks_; ++t) {
                std::set<int> mods;
                for (const PooledPlan &plan : pool_[t])
                    mods.insert(plan.breakers.begin(), plan.breakers.end());
                for (int m : mods)
                    ++shared[m];
            }
            for (int t : std::set<int>(active)) {
                // A cheap way to break every known cheaper plan: per plan not broken yet,
                // the breaker that the most tasks' plans share.
                double floor = result_.baseline->tasks[t].human_plan_cost;
                std::set<int> design_set;
                for (const PooledPlan &plan : pool_[t]) {
                    if (plan.cost >= floor || !plan.needs.empty() || plan.breakers.empty() ||
                        std::any_of(plan.breakers.begin(), plan.breakers.end(),
                                    [&](int m) { return design_set.count(m) > 0; }))
                        continue;
                    design_set.insert(*std::max_element(
                        plan.breakers.begin(), plan.breakers.end(), [&](int a, int b) {
                            return shared[a] != shared[b] ? shared[a] < shared[b] : a > b;
                        }));
                }
                Configuration design(design_set.begin(), design_set.end());
                if (!tried.insert(design).second && !probes.count(design))
                    active.erase(t); // nothing new to break
                else
                    probes[design].push_back(t);
            }
            std::vector<ConfigurationEvaluation> requests;
            for (const auto &[design, tasks] : probes)
                requests.push_back(unevaluated(design));
            EvaluationCallbacks callbacks;
            callbacks.abandon = [](const ConfigurationEvaluation &) { return false; };
            callbacks.done = [&](ConfigurationEvaluation e) {
                const std::vector<int> &probed = probes.at(e.configuration);
                if (e.status != EvaluationStatus::COMPLETE) {
                    for (int t : probed)
                        active.erase(t);
                    return;
                }
                std::vector<TaskExplicability> tasks;
                for (int t = 0; t < tasks_; ++t) {
                    learn_plans(e.configuration, t, *e.tasks[t]);
                    tasks.push_back(std::move(*e.tasks[t]));
                }
                for (int t : probed)
                    if (!(tasks[t].human_optimal_cost.value_or(INF) <
                          result_.baseline->tasks[t].human_plan_cost))
                        active.erase(t); // no cheaper plan is left
                ++result_.counters.configurations_probed;
                if (static_cast<int>(e.configuration.size()) <= max_size_)
                    consider_design(problem_, e.configuration, std::move(tasks), result_);
            };
            if (!requests.empty())
                evaluator_.evaluate(requests, options_.deadline, callbacks);
        }
    }

    // A lower bound on the objective of the configuration alone, from what is known of it.
    double own_bound(double cost, const ConfigurationEvaluation &partial) const {
        std::vector<const TaskExplicability *> tasks;
        for (const auto &t : partial.tasks)
            tasks.push_back(t ? &*t : nullptr);
        return objective_lower_bound(problem_, cost, tasks, partial.robot_cost_bounds);
    }

    bool always_outside(const Node &node) const {
        return std::any_of(always_.begin(), always_.end(),
                           [&](int m) { return !contains(node.configuration, m); });
    }

    // When every modification outside `node` is added everywhere anyway, its witnesses do not
    // say what to add: it is grown before it is evaluated, and its evaluation may be
    // abandoned as soon as the configuration itself cannot win (as in the exhaustive search).
    bool blind(const Node &node) const {
        std::size_t outside = 0;
        for (int m : always_)
            outside += contains(node.configuration, m) ? 0 : 1;
        return outside + node.configuration.size() == static_cast<std::size_t>(index_.size());
    }

    // The modifications that can change a task of `node` (or are added everywhere).
    std::vector<int> candidates(const Node &node) const {
        std::set<int> out(always_.begin(), always_.end());
        for (int t = 0; t < tasks_; ++t) {
            if (problem_.tasks[t].probability <= 0)
                continue;
            const Record &r = node.tasks[t];
            if (!r || !r->touch.known) {
                for (int m = 0; m < index_.size(); ++m)
                    out.insert(m);
                break;
            }
            out.insert(r->touch.all.begin(), r->touch.all.end());
        }
        std::vector<int> result;
        for (int m : out)
            if (!contains(node.configuration, m))
                result.push_back(m);
        return result;
    }

    // A lower bound on the objective of `node`'s configuration and of every superset.
    double bound(const Node &node) const {
        return always_outside(node) ? open_bound(node) : restricted_bound(node);
    }

    // Every modification outside the node is restricting, of non-negative weighted cost: a
    // task keeps its value unless a touching modification is added, c_H(pi) never drops, and
    // the human's optimum is at most the cost of any known plan still valid. To bring it
    // above the k-th cheapest such plan, every cheaper one must be broken; the costs of the
    // modifications that do it are shared among the tasks they can change.
    double restricted_bound(const Node &node) const {
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
                if (plan.cost >= node.explicable_floor[t])
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
                extra += level_bound(s.plans[t], &s.share[t * n], node.explicable_floor[t], weight,
                                     least_ie, s.used[t]) -
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
                            share[m] =
                                s.mark[m] == round * tasks_ + t + 1 ? cost(m) / s.users[m] : 0.0;
            }
        }
        return total + best_extra;
    }

    // Buffers of restricted_bound, kept between calls.
    struct Scratch {
        std::vector<std::vector<const PooledPlan *>> plans; // per task, valid, by cost
        std::vector<int> degree, stamp, users, mark, taken;
        std::vector<double> share; // [task * n + modification]
        std::vector<std::vector<int>> used;
        std::vector<const std::vector<int> *> packed;
        int taken_stamp = 0;

        void reset(int tasks, int n) {
            plans.resize(tasks);
            used.resize(tasks);
            for (int t = 0; t < tasks; ++t)
                plans[t].clear(), used[t].clear();
            degree.assign(n, 0);
            stamp.assign(n, -1);
            users.assign(n, 0);
            mark.assign(n, 0);
            if (static_cast<int>(taken.size()) != n)
                taken.assign(n, 0), taken_stamp = 0;
            share.assign(static_cast<std::size_t>(tasks) * n, 0.0);
        }
    };

    // The least IE term of one task over supersets, given the plans valid there (by cost)
    // and what breaking each costs this task (`share`): to keep the human's optimum above
    // the k-th plan, the k cheaper ones must be broken, at least one modification from each
    // of a family of disjoint breaker sets. `used` gets the modifications of that family at
    // the least value.
    double level_bound(const std::vector<const PooledPlan *> &plans, const double *share,
                       double floor, double weight, double least_ie, std::vector<int> &used) const {
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

    bool valid_in(const PooledPlan &plan, const Configuration &c) const {
        return std::all_of(plan.needs.begin(), plan.needs.end(),
                           [&](int m) { return contains(c, m); }) &&
               std::none_of(plan.breakers.begin(), plan.breakers.end(),
                            [&](int m) { return contains(c, m); });
    }

    // Some modification outside the node is added everywhere (not restricting, or of
    // negative cost): only what holds whatever those do.
    double open_bound(const Node &node) const {
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

    // Whether a design of objective >= `bound` with at least `size` modifications could still
    // rank before the best one.
    bool can_win(double bound, std::size_t size) const {
        if (!result_.best)
            return true;
        double best = result_.best->objective.value;
        if (nearly_equal(bound, best))
            return size <= result_.best->ranked.configuration.size();
        return bound < best;
    }

    void skip(long long count) {
        result_.counters.configurations_skipped += count;
        done_ += count;
    }

    void report() const {
        if (!progress_)
            return;
        EvaluatorCounters e = evaluator_.counters();
        SearchProgress p{done_,
                         generated_,
                         result_.best ? result_.best->objective.value : INF,
                         e.planner_runs,
                         e.cache_hits,
                         static_cast<long long>(open_.size()),
                         open_.empty() ? INF : open_.top().bound};
        progress_(p);
    }

    const DesignProblem &problem_;
    Evaluator &evaluator_;
    const DesignSearchOptions &options_;
    const std::function<void(const SearchProgress &)> &progress_;
    TouchIndex index_;
    int tasks_;
    int max_size_ = 0;
    std::vector<int> always_;                // added to every configuration
    std::vector<int> robot_relaxing_;        // may lower the robot's optimal cost
    std::vector<int> negative_;              // of negative weighted cost
    std::vector<std::set<PooledPlan>> pool_; // per task, by cost
    mutable Scratch scratch_;
    OpenList open_;
    struct ConfigurationHash {
        std::size_t operator()(const Configuration &c) const {
            std::size_t h = c.size();
            for (int m : c)
                h = h * 1000003u ^ static_cast<std::size_t>(m);
            return h;
        }
    };
    std::unordered_set<Configuration, ConfigurationHash> visited_;
    double horizon_ = discounted_horizon(problem_.weights); // f_T(x) / x
    std::set<Configuration> grow_without_witnesses_;        // abandoned on their own bound
    DesignResult result_;
    long long generated_ = 0;
    long long done_ = 0;
    bool limit_seen_ = false;
    double least_unfinished_ = INF;
};

} // namespace

DesignResult search_witness(const DesignProblem &problem, Evaluator &evaluator,
                            const DesignSearchOptions &options,
                            const std::function<void(const SearchProgress &)> &progress) {
    return WitnessSearch(problem, evaluator, options, progress).run();
}

} // namespace envdesign::design
