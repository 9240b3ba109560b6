#pragma once
// The hitting-set phase of the witness search: the least objective over every design,
// from the human plans known so far, by an integer program (COIN-OR CBC).
//
// When every modification is restricting and of non-negative cost, the pooled plans of
// witness_bound.h give each design S a relaxed objective that is a lower bound on its
// real one: per task, the human's optimum under S is at most the cost d of the cheapest
// known plan that S does not break, c_H(pi) is at least its value with no modification
// (plans are only removed), so IE >= g(floor - d); the robot's cost is at least its
// optimum with no modification when no modification relaxes the robot; design cost is
// exact. Minimising it over all designs is a weighted hitting set with levels:
//   minimise  sum_m beta c_m x_m + sum_t sum_j -delta_tj y_tj   (+ a constant)
//   y_tj <= y_t(j-1),  y_tj <= sum of x_m over the breakers of each plan at level j,
// where y_tj = 1 says task t's plans up to cost level j are all broken, and delta_tj is
// what that saves.
// With modifications that add plans (witness.h: adding) the same holds with two changes.
// A pooled plan learnt under adding modifications is valid only where they are all chosen:
// its row gets + sum of (1 - x_n) over those `needs`. And a task's floor falls to F_k once
// a modification e with L(t, e) <= F_k is chosen (addition_floors.h): binary u_tk says so
// (u_tk <= sum of those x_e), and the task's term is a variable T_t with, for every floor
// level k and plan level j, T_t >= V(F_k, D_j) (1 - u_t(k+1) - y_t(j+1)), V the IE term
// above its least when the floor is F_k and the human's optimum at most D_j. The robot's
// cost falls the same way from c_R* with no modification: nested binaries v_tk <= sum of
// the x_e that bring it to R_k, each saving kappa T p_t (R_(k-1) - R_k). The phase
// (witness_search.cc) evaluates the design the program picks, learns the plans that refute its
// relaxed value, and excludes it; it stops when no design left has a relaxed objective within a
// margin of the best real one: then every design is either evaluated or provably worse, and the
// best evaluated one is optimal, ties included. The program is solved to optimality with tight
// tolerances (integrality 1e-9, no allowed gap, a cutoff increment of 1e-10), and NONE rests on the
// solver's proven lower bound; the margin (1e-5 relative, at least 1e-4) absorbs what is left of
// its tolerances.

#include "design/design_problem.h"
#include "design/evaluation/task_evaluation.h"
#include "design/model/configuration.h"
#include "design/search/addition_floors.h"
#include "design/search/deadline.h"
#include "design/search/explanation_bound.h"
#include "design/search/measured_floors.h"
#include "design/search/witness_bound.h"

#include <optional>
#include <set>
#include <vector>

namespace envdesign::design::witness {

// What holds for every design, read from the empty design's evaluation.
struct RootFacts {
    std::vector<double> floor; // per task, c_H(pi) with no modification
    // Per task, the adding modifications that can bring c_H(pi) to at most `cost`
    // (addition_floors.h): a design with none of them keeps the floor above.
    std::vector<std::vector<UseFloor>> lower_floors;
    std::vector<std::optional<double>> robot_bounds; // per task, c_R* with no modification
    // Per task, the adding modifications that can bring c_R* to at most `cost`.
    std::vector<std::vector<UseFloor>> lower_robot_floors;
    std::vector<const TaskExplicability *> settled; // tasks no modification can change
    // Every action costs people at least what it costs the robot (ie_floors_hold): then
    // c_H(pi) >= c_R(pi) >= c_R*, so the robot's floor is one on c_H(pi) too.
    bool robot_floor_bounds_human = false;
    // robot_behaviour EXPLAINING: the bound on the explaining option (explanation_bound.h);
    // null otherwise. Each task's term is then the lesser of the two options' bounds.
    const ExplanationBound *explaining = nullptr;
};

// An evaluated design and the designs that provably rank after it: every superset that
// adds only modifications outside `escapes` (restricting ones touching none of its
// witnesses) has its task values, more modifications and no less cost (witness_search.h).
struct Cone {
    Configuration design;
    std::optional<std::vector<int>> escapes; // ascending; nullopt: every modification
};

class HittingSetMaster {
public:
    // `plans` (the pool) must outlive the master; `max_size` 0: no limit.
    HittingSetMaster(const DesignProblem &problem, const SupersetBound &plans, RootFacts root,
                     int max_size);

    struct Answer {
        enum Status { FOUND, NONE, FAILED } status = FAILED;
        Configuration design;
        double bound = 0;          // the least relaxed objective outside the cones
        bool out_of_range = false; // FAILED: numbers beyond what the solver takes exactly
    };
    // The design outside the cones with the least relaxed objective, if it is at most
    // `cutoff` (INF: any); NONE when every such design is above it. `measured`: floors of
    // evaluated designs with additions (measured_floors.h), in the floor levels too.
    Answer least(const std::vector<Cone> &excluded, const std::vector<MeasuredFloor> &measured,
                 double cutoff, const Deadline &deadline) const;

    // The margin above the best objective within which designs are still evaluated.
    static double margin(double best);

private:
    struct Level {
        double cost;   // the plans' cost at this level
        double saving; // what breaking them all (and those below) saves
        std::vector<const PooledPlan *> plans;
        bool breakable = true;
    };
    class Program;
    struct FloorLevels {
        std::vector<double> floors; // F_0 > F_1 > ...
        std::vector<int> columns;   // u_k for k >= 1 (u_0, always 1, has none: -1)
    };
    std::vector<Level> levels(int task) const;
    double level_value(int task, double floor, double human_optimum) const;
    double add_fixed_floor(Program &program, const std::vector<Level> &levels, double cap) const;
    void add_falling_floor(Program &program, int task, const std::vector<Level> &levels, double cap,
                           const std::vector<MeasuredFloor> &measured,
                           const std::optional<FloorLevels> &robot, int explains = -1) const;
    void add_term_rows(Program &program, int task, int term, const FloorLevels &floors,
                       const std::vector<Level> &levels, const std::vector<int> &y, double cap,
                       int explains) const;
    int add_explaining_option(Program &program, int task, int voided) const;
    int add_voided_column(Program &program) const;
    std::vector<int> add_plan_levels(Program &program, const std::vector<Level> &levels,
                                     const std::vector<double> &objective) const;
    std::optional<FloorLevels>
    add_falling_robot_floor(Program &program, int task,
                            const std::vector<MeasuredFloor> &measured) const;
    FloorLevels add_floor_levels(Program &program, int task, double top,
                                 const std::vector<UseFloor> &lowering,
                                 const std::vector<MeasuredFloor> &measured, bool robot,
                                 double saving_weight) const;
    void exclude(Program &program, const std::vector<Cone> &excluded) const;

    const DesignProblem &problem_;
    const SupersetBound &plans_;
    RootFacts root_;
    int max_size_;
    double constant_; // the objective's part that no design changes, at its least
};

} // namespace envdesign::design::witness
