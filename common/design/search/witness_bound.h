#pragma once
// The witness search's knowledge of tasks and its lower bounds on every superset of a
// configuration (witness_search.h explains why they hold): the configurations it queues,
// each task's evaluation with the modifications that touch its witnesses, and a pool of
// plans known to be valid in the human's model.

#include "design/objective/objective.h"
#include "design/search/witness.h"

#include <memory>
#include <optional>
#include <set>
#include <string>
#include <tuple>
#include <vector>

namespace envdesign::design::witness {

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
    // Every design weighed (the explaining robot): a node back in the queue after some of its
    // floors were answered (its children are queued already) has `bound` on its own objective
    // alone, and these floors go with its next evaluation.
    std::vector<std::optional<double>> ie_floors;
    std::vector<std::optional<int>> explanation_floors;
};

// A plan known to be valid in the human's model of some configuration xi: valid in every
// configuration that keeps xi's everywhere-added modifications that edit the human's model
// (`needs`; a robot-only edit changes no plan of the human's model) and adds none of
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

// Whether ascending `sorted` holds `value`.
bool contains(const std::vector<int> &sorted, int value);

// What the evaluator needs of a task known already: its values, not its plans.
TaskExplicability values_only(const TaskExplicability &e);

// Raises task t's floor on c_H(pi) to what evaluation `e` says.
void raise_floor(Node &node, int t, const TaskExplicability &e);

class SupersetBound {
public:
    // Both must outlive the bound.
    // `weigh_every_modification`: every modification is added everywhere (always()), as if none
    // were restricting (no witness lemma: the explaining robot).
    SupersetBound(const DesignProblem &problem, const TouchIndex &index,
                  bool weigh_every_modification = false);

    // A lower bound on the objective of `node`'s configuration and of every superset.
    double operator()(const Node &node) const;

    // Keeps both witnesses of a new evaluation of task `t` under `c` as plans of the
    // human's model (a most explicable plan is one too, at its human cost).
    void learn(const Configuration &c, int t, const TaskExplicability &e);
    // The evaluation of task `t` under `c` + `m` without planning, when `m` breaks only the
    // human's witness of `r` and a known plan as cheap is still valid; else null.
    Record equally_cheap(int t, const TaskRecord &r, int m, const Configuration &c) const;

    // The plans known for task `t`, by cost.
    const std::set<PooledPlan> &plans(int t) const { return pool_[t]; }
    // Modifications added to every configuration: not restricting, or of negative cost.
    const std::vector<int> &always() const { return always_; }
    bool always_outside(const Node &node) const;
    // Why some modifications are weighed with every design: one note per modification that is
    // not restricting or costs less than nothing, and one for all that add plans (a floor's
    // lanes are hundreds).
    std::vector<std::string> weighed_everywhere_notes() const;

private:
    // What open_bound knows of each task.
    struct OpenTasks {
        std::vector<const TaskExplicability *> settled;  // its value in every superset
        std::vector<std::optional<double>> robot_bounds; // where c_R* only rises
        std::vector<std::vector<int>> touching;          // the modifications outside that touch it
        std::vector<bool> shares;                        // its excess is bounded by their costs
        std::vector<int> degree;                         // per modification: the tasks sharing it
    };

    double restricted_bound(const Node &node) const;
    std::vector<const TaskExplicability *> settled_or_pooled(const Node &node) const;
    double breaking_extra(const Node &node) const;
    double open_bound(const Node &node) const;
    OpenTasks open_tasks(const Node &node, bool lowered) const;
    double with_open_shares(const Node &node, const OpenTasks &open, double total) const;
    // beta * the cost of modification `m`: what adding it adds to the objective.
    double weighted_cost(int m) const {
        return problem_.weights.beta * problem_.modifications[m].cost;
    }
    double level_bound(const std::vector<const PooledPlan *> &plans, const double *share,
                       double floor, double weight, double least_ie, std::vector<int> &used) const;
    bool valid_in(const PooledPlan &plan, const Configuration &c) const;
    // Task t's floor on c_H(pi) in the supersets, or 0 where floors do not hold.
    double floor(const Node &node, int t) const {
        return floors_hold_ ? node.explicable_floor[t] : 0.0;
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

    const DesignProblem &problem_;
    const TouchIndex &index_;
    int tasks_;
    std::vector<int> always_;                // added to every configuration
    std::vector<int> robot_relaxing_;        // may lower the robot's optimal cost
    std::vector<int> negative_;              // of negative weighted cost
    std::vector<std::set<PooledPlan>> pool_; // per task, by cost
    double horizon_;                         // f_T(x) / x
    // Removing plans never lowers the most explicable plan's human cost, but it can lower
    // the worst cost-optimal plan's (COST_OPTIMAL), and raising c_R* can bring cheaper ones
    // (COST_OPTIMAL_BEST_CASE): there the IE term is bounded by its least value only.
    bool floors_hold_;
    mutable Scratch scratch_;
};

} // namespace envdesign::design::witness
