#include "design/hitting_set.h"

#include "design/objective.h"

#include <coin/Cbc_C_Interface.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>

namespace envdesign::design::witness {
namespace {

double least_ie(const ObjectiveWeights &w) { return w.distance == Distance::COST_DIFF ? 0.0 : 1.0; }

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

HittingSetMaster::HittingSetMaster(const DesignProblem &problem, const SupersetBound &plans,
                                   RootFacts root, int max_size)
    : problem_(problem), plans_(plans), root_(std::move(root)), max_size_(max_size) {
    constant_ = objective_lower_bound(problem, 0.0, root_.settled, root_.robot_bounds);
}

double HittingSetMaster::margin(double best) { return std::max(1e-4, 1e-5 * std::abs(best)); }

// The IE term of `task`, above its least, when the human's optimum is at most `human_optimum`.
double HittingSetMaster::level_value(int task, double human_optimum) const {
    const ObjectiveWeights &w = problem_.weights;
    double weight = w.alpha * discounted_horizon(w) * problem_.tasks[task].probability;
    double gap = root_.floor[task] - human_optimum;
    if (gap <= 0)
        return 0;
    double least = least_ie(w);
    return weight * ((least == 0 ? gap : std::exp(gap)) - least);
}

// Per task that a design can change, its known plans cheaper than the floor, grouped by
// cost; the levels end at the first plan nothing breaks.
std::vector<std::vector<HittingSetMaster::Level>> HittingSetMaster::levels() const {
    int tasks = static_cast<int>(problem_.tasks.size());
    std::vector<std::vector<Level>> out(tasks);
    for (int t = 0; t < tasks; ++t) {
        if (problem_.tasks[t].probability <= 0 || root_.settled[t])
            continue;
        for (const PooledPlan &plan : plans_.plans(t)) {
            if (plan.cost >= root_.floor[t])
                break;
            if (!plan.needs.empty())
                continue; // valid only with modifications added everywhere: not used
            if (out[t].empty() || out[t].back().cost != plan.cost)
                out[t].push_back(Level{plan.cost, 0, {}});
            if (plan.breakers.empty()) {
                out[t].back().breakable = false;
                break;
            }
            out[t].back().breakers.push_back(&plan.breakers);
        }
        for (std::size_t j = 0; j < out[t].size(); ++j) {
            double next = j + 1 < out[t].size() ? level_value(t, out[t][j + 1].cost) : 0.0;
            out[t][j].saving = level_value(t, out[t][j].cost) - next;
        }
    }
    return out;
}

HittingSetMaster::Answer HittingSetMaster::least(const std::vector<Cone> &excluded, double cutoff,
                                                 const Deadline &deadline) const {
    const ObjectiveWeights &w = problem_.weights;
    int n = static_cast<int>(problem_.modifications.size());
    Answer answer;
    if (!std::isfinite(constant_)) { // no design has a finite objective
        if (std::isfinite(cutoff))
            answer.status = Answer::NONE;
        return answer;
    }
    bool in_range = solver_number(cutoff) || cutoff == INF;
    Model model(Cbc_newModel());
    Cbc_Model *m = model.get();
    Cbc_setLogLevel(m, 0);
    // Tight tolerances: CBC's defaults accept an incumbent 1e-5 (absolute) above the optimum,
    // as wide as the margin on small objectives.
    Cbc_setParameter(m, "integerTolerance", "1e-9");
    Cbc_setParameter(m, "increment", "1e-10");
    Cbc_setAllowableGap(m, 0.0);
    Cbc_setAllowableFractionGap(m, 0.0);
    if (deadline.limited())
        Cbc_setMaximumSeconds(m, deadline.remaining_seconds());
    auto add_column = [&](double objective) {
        in_range = in_range && solver_number(objective);
        Cbc_addCol(m, "", 0.0, 1.0, objective, 1, 0, nullptr, nullptr);
    };
    for (int i = 0; i < n; ++i)
        add_column(w.beta * problem_.modifications[i].cost);
    // A term above this makes a design worse than `cutoff` whatever the rest: capping the
    // savings there keeps the program's numbers small and changes no design below it.
    double cap = std::max(0.0, cutoff - constant_) + 1.0;
    double offset = constant_;
    std::vector<int> cols;
    std::vector<double> coefs;
    int col = n;
    for (const auto &task_levels : levels()) {
        double top = 0; // the task's term with nothing broken, capped
        for (const Level &level : task_levels)
            top += level.saving;
        double capped = std::min(top, cap);
        offset += capped;
        double remaining = capped; // savings beyond the cap are dropped from the top down
        int previous = -1;
        for (std::size_t j = 0; j < task_levels.size() && task_levels[j].breakable; ++j) {
            const Level &level = task_levels[j];
            double above = top - level.saving; // the term once this level is broken
            top = above;
            double saving = remaining - std::min(above, cap);
            remaining -= saving;
            add_column(-saving);
            int y = col++;
            if (previous >= 0) { // y_j <= y_(j-1)
                int both[2] = {y, previous};
                double signs[2] = {1.0, -1.0};
                Cbc_addRow(m, "", 2, both, signs, 'L', 0.0);
            }
            for (const auto *breakers : level.breakers) { // y_j <= sum of its breakers
                cols.assign(1, y);
                coefs.assign(1, 1.0);
                for (int b : *breakers)
                    cols.push_back(b), coefs.push_back(-1.0);
                Cbc_addRow(m, "", static_cast<int>(cols.size()), cols.data(), coefs.data(), 'L',
                           0.0);
            }
            previous = y;
        }
    }
    for (const Cone &cone : excluded) { // drop one of its modifications or add an escape
        cols.clear();
        coefs.clear();
        for (int i = 0; i < n; ++i) {
            if (contains(cone.design, i))
                cols.push_back(i), coefs.push_back(-1.0);
            else if (!cone.escapes || contains(*cone.escapes, i))
                cols.push_back(i), coefs.push_back(1.0);
        }
        Cbc_addRow(m, "", static_cast<int>(cols.size()), cols.data(), coefs.data(), 'G',
                   1.0 - static_cast<double>(cone.design.size()));
    }
    if (max_size_ > 0 && max_size_ < n) {
        cols.clear();
        coefs.assign(n, 1.0);
        for (int i = 0; i < n; ++i)
            cols.push_back(i);
        Cbc_addRow(m, "", n, cols.data(), coefs.data(), 'L', max_size_);
    }
    in_range = in_range && solver_number(offset);
    if (!in_range) {
        answer.out_of_range = true;
        return answer; // FAILED
    }
    if (std::isfinite(cutoff)) // INF: a ranking not full yet, every design is wanted
        Cbc_setCutoff(m, cutoff - offset + margin(cutoff));
    Cbc_solve(m);

    if (Cbc_isProvenInfeasible(m)) {
        answer.status = Answer::NONE;
        return answer;
    }
    if (!Cbc_isProvenOptimal(m))
        return answer; // FAILED: a limit, or the solver gave up
    // NONE only on the solver's proven lower bound, never on its incumbent alone.
    double lower = Cbc_getBestPossibleObjValue(m) + offset;
    if (!Cbc_bestSolution(m) || Cbc_getObjValue(m) + offset > cutoff) {
        if (lower > cutoff)
            answer.status = Answer::NONE;
        return answer; // else FAILED: the two disagree within the solver's tolerance
    }
    const double *x = Cbc_getColSolution(m);
    for (int i = 0; i < n; ++i)
        if (x[i] > 0.5)
            answer.design.push_back(i);
    answer.bound = std::min(lower, Cbc_getObjValue(m) + offset);
    answer.status = Answer::FOUND;
    return answer;
}

} // namespace envdesign::design::witness
