#include "design/search/hitting_set.h"

#include "design/objective/objective.h"

#include <coin/Cbc_C_Interface.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <string>

namespace envdesign::design::witness {
namespace {

// Beyond this magnitude a coefficient, bound or cutoff is not given to CBC (it aborts near
// 1e25, and its absolute tolerances lose meaning long before): the phase gives up instead,
// and the search proves the optimum without it (numbers.h keeps every input far below).
constexpr double SOLVER_MAGNITUDE = 1e15;

bool solver_number(double v) { return std::abs(v) <= SOLVER_MAGNITUDE; } // false for NaN too

// Owns a CBC model.
struct ModelDeleter {
    void operator()(Cbc_Model *m) const { Cbc_deleteModel(m); }
};
using Model = std::unique_ptr<Cbc_Model, ModelDeleter>;

} // namespace

// The integer program being written: columns (binary unless said) and rows, with every
// number checked against what the solver takes. It is kept here and given to CBC whole by
// load(): CBC's addRow copies its whole matrix at each row, quadratic in a program of
// thousands of rows.
class HittingSetMaster::Program {
public:
    bool in_range() const { return in_range_; }
    void check(double v) { in_range_ = in_range_ && solver_number(v); }

    int column(double objective, double upper = 1.0, bool binary = true) {
        check(objective);
        check(upper);
        objective_.push_back(objective);
        upper_.push_back(upper);
        binary_.push_back(binary);
        return static_cast<int>(objective_.size()) - 1;
    }
    // sum of coefs[i] * column cols[i]  (sense: 'L' <=, 'G' >=)  rhs
    void row(const std::vector<int> &cols, const std::vector<double> &coefs, char sense,
             double rhs) {
        for (double c : coefs)
            check(c);
        check(rhs);
        int r = static_cast<int>(row_lower_.size());
        for (std::size_t i = 0; i < cols.size(); ++i)
            entries_.push_back({cols[i], r, coefs[i]});
        row_lower_.push_back(sense == 'L' ? -COIN_INFINITY : rhs);
        row_upper_.push_back(sense == 'G' ? COIN_INFINITY : rhs);
    }

    // The model with every column and row, in compressed columns as CBC loads them.
    Cbc_Model *load() {
        int n = static_cast<int>(objective_.size());
        std::stable_sort(entries_.begin(), entries_.end(),
                         [](const Entry &a, const Entry &b) { return a.col < b.col; });
        std::vector<CoinBigIndex> start(n + 1, 0);
        std::vector<int> index;
        std::vector<double> value;
        index.reserve(entries_.size());
        value.reserve(entries_.size());
        for (const Entry &e : entries_) {
            ++start[e.col + 1];
            index.push_back(e.row);
            value.push_back(e.coef);
        }
        for (int j = 0; j < n; ++j)
            start[j + 1] += start[j];
        std::vector<double> lower(n, 0.0);
        Cbc_loadProblem(model_.get(), n, static_cast<int>(row_lower_.size()), start.data(),
                        index.data(), value.data(), lower.data(), upper_.data(), objective_.data(),
                        row_lower_.data(), row_upper_.data());
        for (int j = 0; j < n; ++j)
            if (binary_[j])
                Cbc_setInteger(model_.get(), j);
        return model_.get();
    }

private:
    static constexpr double COIN_INFINITY = std::numeric_limits<double>::max();
    struct Entry {
        int col;
        int row;
        double coef;
    };
    Model model_{Cbc_newModel()};
    std::vector<double> objective_, upper_, row_lower_, row_upper_;
    std::vector<bool> binary_;
    std::vector<Entry> entries_;
    bool in_range_ = true;
};

namespace {

// The solver's verdict: NONE only on its proven lower bound, never on its incumbent alone.
HittingSetMaster::Answer read_answer(Cbc_Model *m, int n, double offset, double cutoff) {
    HittingSetMaster::Answer answer;
    if (Cbc_isProvenInfeasible(m)) {
        answer.status = HittingSetMaster::Answer::NONE;
        return answer;
    }
    if (!Cbc_isProvenOptimal(m))
        return answer; // FAILED: a limit, or the solver gave up
    double lower = Cbc_getBestPossibleObjValue(m) + offset;
    if (!Cbc_bestSolution(m) || Cbc_getObjValue(m) + offset > cutoff) {
        if (lower > cutoff)
            answer.status = HittingSetMaster::Answer::NONE;
        return answer; // else FAILED: the two disagree within the solver's tolerance
    }
    const double *x = Cbc_getColSolution(m);
    for (int i = 0; i < n; ++i)
        if (x[i] > 0.5)
            answer.design.push_back(i);
    answer.bound = std::min(lower, Cbc_getObjValue(m) + offset);
    answer.status = HittingSetMaster::Answer::FOUND;
    return answer;
}

} // namespace

HittingSetMaster::HittingSetMaster(const DesignProblem &problem, const SupersetBound &plans,
                                   RootFacts root, int max_size)
    : problem_(problem), plans_(plans), root_(std::move(root)), max_size_(max_size) {
    constant_ = objective_lower_bound(problem, 0.0, root_.settled, root_.robot_bounds);
    root_.lower_floors.resize(problem.tasks.size());
    root_.lower_robot_floors.resize(problem.tasks.size());
}

double HittingSetMaster::margin(double best) { return std::max(1e-4, 1e-5 * std::abs(best)); }

// The IE term of `task`, above its least, when c_H(pi) is at least `floor` and the human's
// optimum at most `human_optimum`.
double HittingSetMaster::level_value(int task, double floor, double human_optimum) const {
    const ObjectiveWeights &w = problem_.weights;
    double weight = w.alpha * discounted_horizon(w) * problem_.tasks[task].probability;
    double gap = floor - human_optimum;
    if (gap <= 0)
        return 0;
    double least = least_ie(w.distance);
    return weight * ((least == 0 ? gap : std::exp(gap)) - least);
}

// The task's known plans cheaper than its floor, grouped by cost; the levels end at the
// first plan nothing breaks (no breaker, valid without any adding modification).
std::vector<HittingSetMaster::Level> HittingSetMaster::levels(int t) const {
    std::vector<Level> out;
    if (problem_.tasks[t].probability <= 0 || root_.settled[t])
        return out;
    double floor = root_.floor[t];
    for (const PooledPlan &plan : plans_.plans(t)) {
        if (plan.cost >= floor)
            break;
        if (out.empty() || out.back().cost != plan.cost)
            out.push_back(Level{plan.cost, 0, {}});
        if (plan.breakers.empty() && plan.needs.empty()) {
            out.back().breakable = false;
            break;
        }
        out.back().plans.push_back(&plan);
    }
    for (std::size_t j = 0; j < out.size(); ++j) {
        double next = j + 1 < out.size() ? level_value(t, floor, out[j + 1].cost) : 0.0;
        out[j].saving = level_value(t, floor, out[j].cost) - next;
    }
    return out;
}

// Columns y_j for the breakable levels (objective coefficients `objective`), with
// y_j <= y_(j-1) and, per plan of level j, y_j <= its breakers + its needs left out.
std::vector<int> HittingSetMaster::add_plan_levels(Program &program,
                                                   const std::vector<Level> &levels,
                                                   const std::vector<double> &objective) const {
    std::vector<int> y;
    for (std::size_t j = 0; j < levels.size() && levels[j].breakable; ++j) {
        y.push_back(program.column(objective[j]));
        if (j > 0)
            program.row({y[j], y[j - 1]}, {1.0, -1.0}, 'L', 0.0);
        for (const PooledPlan *plan : levels[j].plans) {
            std::vector<int> cols{y[j]};
            std::vector<double> coefs{1.0};
            for (int b : plan->breakers)
                cols.push_back(b), coefs.push_back(-1.0);
            for (int n : plan->needs)
                cols.push_back(n), coefs.push_back(1.0);
            program.row(cols, coefs, 'L', static_cast<double>(plan->needs.size()));
        }
    }
    return y;
}

// A task whose floor no design lowers: its term is top - sum of savings y_j. Returns the
// top, capped, which goes to the objective's constant.
double HittingSetMaster::add_fixed_floor(Program &program, const std::vector<Level> &levels,
                                         double cap) const {
    double top = 0; // the task's term with nothing broken
    for (const Level &level : levels)
        top += level.saving;
    double capped = std::min(top, cap);
    double remaining = capped; // savings beyond the cap are dropped from the top down
    std::vector<double> savings;
    for (std::size_t j = 0; j < levels.size() && levels[j].breakable; ++j) {
        double above = top - levels[j].saving; // the term once this level is broken
        top = above;
        double saving = remaining - std::min(above, cap);
        remaining -= saving;
        savings.push_back(-saving);
    }
    add_plan_levels(program, levels, savings);
    return capped;
}

// The levels a task's floor may fall to, from `top`: every L(t, e) of `lowering` and every
// measured floor below it. Binary u_k says the floor may be at most F_k: u_k <= the x_e that
// bring it there, u_k <= u_(k-1), and, per measured design D whose floor is above F_k,
// u_k <= (additions outside D's) + (D's restricting ones left out): a design within D keeps
// D's floor (measured_floors.h). Each u_k costs -saving_weight (F_(k-1) - F_k).
HittingSetMaster::FloorLevels HittingSetMaster::add_floor_levels(
    Program &program, int t, double top, const std::vector<UseFloor> &lowering,
    const std::vector<MeasuredFloor> &measured, bool robot, double saving_weight) const {
    auto floor_of = [&](const MeasuredFloor &d) -> const std::optional<double> & {
        return robot ? d.robot[t] : d.human[t];
    };
    FloorLevels out{{top}, {-1}};
    for (const UseFloor &f : lowering)
        if (f.cost < top)
            out.floors.push_back(f.cost);
    for (const MeasuredFloor &d : measured)
        if (floor_of(d) && *floor_of(d) < top)
            out.floors.push_back(*floor_of(d));
    std::sort(out.floors.begin() + 1, out.floors.end(), std::greater<>());
    out.floors.erase(std::unique(out.floors.begin(), out.floors.end()), out.floors.end());
    for (std::size_t k = 1; k < out.floors.size(); ++k) {
        // No weight: no saving (a level of -INF, COST_OPTIMAL's floor dropped, gives 0 x INF).
        double saving =
            saving_weight == 0 ? 0.0 : saving_weight * (out.floors[k - 1] - out.floors[k]);
        int u = program.column(-saving);
        out.columns.push_back(u);
        std::vector<int> cols{u};
        std::vector<double> coefs{1.0};
        for (const UseFloor &f : lowering)
            if (f.cost <= out.floors[k])
                cols.push_back(f.modification), coefs.push_back(-1.0);
        program.row(cols, coefs, 'L', 0.0);
        if (k > 1)
            program.row({u, out.columns[k - 1]}, {1.0, -1.0}, 'L', 0.0);
    }
    // A measured floor binds the first level below it (the nesting carries it down).
    for (const MeasuredFloor &d : measured) {
        const std::optional<double> &floor = floor_of(d);
        if (!floor)
            continue;
        std::size_t k = 1;
        while (k < out.floors.size() && !(out.floors[k] < *floor))
            ++k;
        if (k >= out.floors.size())
            continue;
        const Within &within = robot ? d.robot_within : d.human_within;
        std::vector<int> cols{out.columns[k]};
        std::vector<double> coefs{1.0};
        for (int e : within.outside)
            cols.push_back(e), coefs.push_back(-1.0);
        for (int r : within.restricting)
            cols.push_back(r), coefs.push_back(1.0);
        program.row(cols, coefs, 'L', static_cast<double>(within.restricting.size()));
    }
    return out;
}

// A task whose floor falls when adding modifications are chosen: term T_t >= V(F_k, D_j)
// (1 - u_(k+1) - y_(j+1)) for every floor level k and plan level j (hitting_set.h); where the
// robot's floor bounds c_H(pi) too, the same rows with its levels.
void HittingSetMaster::add_falling_floor(Program &program, int t, const std::vector<Level> &levels,
                                         double cap, const std::vector<MeasuredFloor> &measured,
                                         const std::optional<FloorLevels> &robot,
                                         int explains) const {
    std::vector<int> y = add_plan_levels(program, levels, std::vector<double>(levels.size(), 0.0));
    FloorLevels falls =
        add_floor_levels(program, t, root_.floor[t], root_.lower_floors[t], measured, false, 0.0);
    int term = program.column(1.0, cap, false);
    add_term_rows(program, t, term, falls, levels, y, cap, explains);
    if (robot && root_.robot_floor_bounds_human)
        add_term_rows(program, t, term, *robot, levels, y, cap, explains);
}

// T_t >= V(F_k, D_j) (1 - u_(k+1) - y_(j+1)) (- z: explaining instead, where the other
// option's bound holds) for the levels of one floor.
void HittingSetMaster::add_term_rows(Program &program, int t, int term, const FloorLevels &falls,
                                     const std::vector<Level> &levels, const std::vector<int> &y,
                                     double cap, int explains) const {
    const std::vector<double> &floors = falls.floors;
    const std::vector<int> &u = falls.columns;
    for (std::size_t k = 0; k < floors.size(); ++k) {
        for (std::size_t j = 0; j <= y.size(); ++j) {
            if (j >= levels.size())
                break; // every level broken: no plan below the floor is known
            double value = std::min(level_value(t, floors[k], levels[j].cost), cap);
            if (value <= 0)
                continue;
            std::vector<int> cols{term};
            std::vector<double> coefs{1.0};
            if (k + 1 < floors.size())
                cols.push_back(u[k + 1]), coefs.push_back(value);
            if (j < y.size())
                cols.push_back(y[j]), coefs.push_back(value);
            if (explains >= 0)
                cols.push_back(explains), coefs.push_back(value);
            program.row(cols, coefs, 'G', value);
        }
    }
}

// EXPLAINING (explanation_bound.h): binary z says the task explains, and returns it. Each
// difference e_i of the empty design told costs H p x; every pooled plan cheaper than h_R
// must be broken by the design or by one told: touching modifications + e_i over its
// breaking differences >= z, unless the design holds a modification that voids the argument
// (+ `voided`, at most the sum of those x_m: explanation_bound.h).
int HittingSetMaster::add_explaining_option(Program &program, int t, int voided) const {
    int explains = program.column(0.0);
    const ExplanationBound &bound = *root_.explaining;
    std::optional<double> robot_plan = bound.robot_plan_cost(t);
    if (!robot_plan)
        return explains; // nothing known: explaining may cost nothing above the constant
    const ObjectiveWeights &w = problem_.weights;
    double each = w.explanation_cost * discounted_horizon(w) * problem_.tasks[t].probability;
    std::vector<int> told(bound.differences(t), -1);
    for (const PooledPlan &plan : plans_.plans(t)) {
        if (plan.cost >= *robot_plan)
            break;
        if (!plan.needs.empty())
            continue; // a plan only where an addition is chosen, and there nothing binds
        const ExplanationBound::Breakers &breakers = bound.breaking(t, plan);
        std::vector<int> cols{explains};
        std::vector<double> coefs{-1.0};
        for (int m : breakers.modifications)
            cols.push_back(m), coefs.push_back(1.0);
        if (voided >= 0)
            cols.push_back(voided), coefs.push_back(1.0);
        for (int i : breakers.differences) {
            if (told[i] < 0)
                told[i] = program.column(each);
            cols.push_back(told[i]), coefs.push_back(1.0);
        }
        program.row(cols, coefs, 'G', 0.0);
    }
    return explains;
}

// EXPLAINING: a column at most the number of chosen modifications that void the explaining
// bound (explanation_bound.h), shared by every task's rows (one entry per row instead of one
// per such modification); -1 when there is none.
int HittingSetMaster::add_voided_column(Program &program) const {
    const std::vector<int> &relaxing = root_.explaining->relaxing();
    if (relaxing.empty())
        return -1;
    int voided = program.column(0.0, 1.0, false);
    std::vector<int> cols{voided};
    std::vector<double> coefs{1.0};
    for (int m : relaxing)
        cols.push_back(m), coefs.push_back(-1.0);
    program.row(cols, coefs, 'L', 0.0);
    return voided;
}

// A task whose robot floor c_R* falls when adding modifications are chosen: the constant
// counts it at c_R* with no modification, and each level reached saves kappa T p (R_(k-1) -
// R_k) (add_floor_levels).
std::optional<HittingSetMaster::FloorLevels>
HittingSetMaster::add_falling_robot_floor(Program &program, int t,
                                          const std::vector<MeasuredFloor> &measured) const {
    const ObjectiveWeights &w = problem_.weights;
    if (!root_.robot_bounds[t] || root_.settled[t] || problem_.tasks[t].probability <= 0)
        return std::nullopt;
    return add_floor_levels(program, t, *root_.robot_bounds[t], root_.lower_robot_floors[t],
                            measured, true, w.kappa * w.horizon * problem_.tasks[t].probability);
}

// Every cone is left: drop one of its design's modifications or add an escape.
void HittingSetMaster::exclude(Program &program, const std::vector<Cone> &excluded) const {
    int n = static_cast<int>(problem_.modifications.size());
    for (const Cone &cone : excluded) {
        std::vector<int> cols;
        std::vector<double> coefs;
        for (int i = 0; i < n; ++i) {
            if (contains(cone.design, i))
                cols.push_back(i), coefs.push_back(-1.0);
            else if (!cone.escapes || contains(*cone.escapes, i))
                cols.push_back(i), coefs.push_back(1.0);
        }
        program.row(cols, coefs, 'G', 1.0 - static_cast<double>(cone.design.size()));
    }
    if (max_size_ > 0 && max_size_ < n) {
        std::vector<int> cols(n);
        for (int i = 0; i < n; ++i)
            cols[i] = i;
        program.row(cols, std::vector<double>(n, 1.0), 'L', max_size_);
    }
}

HittingSetMaster::Answer HittingSetMaster::least(const std::vector<Cone> &excluded,
                                                 const std::vector<MeasuredFloor> &measured,
                                                 double cutoff, const Deadline &deadline) const {
    const ObjectiveWeights &w = problem_.weights;
    int n = static_cast<int>(problem_.modifications.size());
    Answer answer;
    if (!std::isfinite(constant_)) { // no design has a finite objective
        if (std::isfinite(cutoff))
            answer.status = Answer::NONE;
        return answer;
    }
    Program program;
    for (int i = 0; i < n; ++i)
        program.column(w.beta * problem_.modifications[i].cost);
    // A term above this makes a design worse than `cutoff` whatever the rest: capping the
    // terms there keeps the program's numbers small and changes no design below it.
    double cap = std::max(0.0, cutoff - constant_) + 1.0;
    double offset = constant_;
    int voided = root_.explaining ? add_voided_column(program) : -1;
    for (int t = 0; t < static_cast<int>(problem_.tasks.size()); ++t) {
        auto robot = add_falling_robot_floor(program, t, measured);
        std::vector<Level> task_levels = levels(t);
        if (task_levels.empty())
            continue;
        if (root_.explaining)
            add_falling_floor(program, t, task_levels, cap, measured, robot,
                              add_explaining_option(program, t, voided));
        else if (root_.lower_floors[t].empty())
            offset += add_fixed_floor(program, task_levels, cap);
        else
            add_falling_floor(program, t, task_levels, cap, measured, robot);
    }
    exclude(program, excluded);
    program.check(offset);
    if (!program.in_range() || !(solver_number(cutoff) || cutoff == INF)) {
        answer.out_of_range = true;
        return answer; // FAILED
    }
    Cbc_Model *m = program.load();
    Cbc_setLogLevel(m, 0);
    // Tight tolerances: CBC's defaults accept an incumbent 1e-5 (absolute) above the optimum,
    // as wide as the margin on small objectives.
    Cbc_setParameter(m, "integerTolerance", "1e-9");
    Cbc_setParameter(m, "increment", "1e-10");
    // Zero-half cuts cost Cgl a zeroed table per call, 70-98% of the phase on the explaining
    // robot's grid problems, and never decide the answer (the program is solved to
    // optimality either way).
    Cbc_setParameter(m, "zeroHalfCuts", "off");
    Cbc_setAllowableGap(m, 0.0);
    Cbc_setAllowableFractionGap(m, 0.0);
    if (deadline.limited())
        Cbc_setMaximumSeconds(m, deadline.remaining_seconds());
    if (std::isfinite(cutoff)) // INF: a ranking not full yet, every design is wanted
        Cbc_setCutoff(m, cutoff - offset + margin(cutoff));
    Cbc_solve(m);
    return read_answer(m, n, offset, cutoff);
}

} // namespace envdesign::design::witness
