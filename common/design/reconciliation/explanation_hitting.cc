#include "design/reconciliation/explanation_hitting.h"

#include "design/behaviour/explicability.h"
#include "design/reconciliation/plan_reads.h"
#include "validate/plan_validator.h"

#include <algorithm>
#include <cctype>
#include <map>
#include <set>

namespace envdesign::design {
namespace {

std::set<std::string> negatively_read(const ModelPair &m) {
    std::set<std::string> out;
    for (const pddl::Domain *d : {&m.robot_domain, &m.human_domain})
        for (const auto &a : d->actions)
            for (const auto &l : a.precondition)
                if (l.negated)
                    out.insert(l.atom.predicate);
    for (const pddl::Problem *p : {&m.robot_problem, &m.human_problem})
        for (const auto &l : p->goal)
            if (l.negated)
                out.insert(l.atom.predicate);
    return out;
}

bool restricting(const ModelDifference &d, const std::set<std::string> &negative) {
    bool positive_only =
        !negative.count(d.literal.atom.predicate) && d.literal.atom.predicate != "=";
    switch (d.kind) {
    case DifferenceKind::INIT:
        return !d.robot_has && positive_only;
    case DifferenceKind::PRECONDITION:
    case DifferenceKind::GOAL:
        return d.robot_has && !d.literal.negated && positive_only;
    case DifferenceKind::DELETE_EFFECT:
        return d.robot_has && positive_only;
    case DifferenceKind::ADD_EFFECT:
        return !d.robot_has && positive_only;
    case DifferenceKind::ACTION:
        return !d.robot_has;
    }
    return false;
}

bool valid_with(const ModelPair &models, const ExplanationSearch &search, int d,
                const std::vector<std::string> &plan) {
    ModelPair told = told_human_model(models, search.differences, {d});
    return validate::validate_plan(told.human_domain, told.human_problem, plan).valid;
}

} // namespace

// Differences that add a requirement (a precondition or a goal) on a predicate.
bool adds_requirement(const ModelDifference &d) {
    return d.kind == DifferenceKind::PRECONDITION || d.kind == DifferenceKind::GOAL;
}

bool all_restricting(const ModelPair &models, const std::vector<ModelDifference> &differences) {
    std::set<std::string> negative = negatively_read(models);
    std::set<std::string> required, shrunk;
    for (const auto &d : differences) {
        if (!restricting(d, negative))
            return false;
        if (d.kind != DifferenceKind::ACTION)
            (adds_requirement(d) ? required : shrunk).insert(d.literal.atom.predicate);
    }
    // A requirement and a shrink on the same predicate break the union closure: Blocksworld's
    // (handempty) precondition alone or its delete alone keeps a two-block plan valid, both
    // together do not.
    for (const auto &p : required)
        if (shrunk.count(p))
            return false;
    return true;
}

namespace {

// Per difference: whether it breaks pi_R alone (never a candidate), and whether it removes an
// initial atom the human's model holds once (the fast case of breaks_alone).
struct Candidates {
    std::vector<bool> breaks_robot;
    std::vector<bool> init_once;
};

// Whether `plan` is invalid in P_H + {d} (`valid_here`: it is valid in P_H). An initial atom
// held once and removed breaks a plan valid in P_H iff the plan reads it before a step adds it
// (reads.from_init): until then the states differ in that atom alone, which nothing reads
// negatively (d is restricting), after it they are equal, and costs read no atom. The
// validator answers the other cases.
bool breaks_alone(const ModelPair &models, const ExplanationSearch &search,
                  const Candidates &candidates, int d, const std::vector<std::string> &plan,
                  const PlanReads &reads, bool valid_here) {
    const ModelDifference &difference = search.differences[d];
    if (!may_break(difference, reads))
        return false;
    if (valid_here && reads.known && candidates.init_once[d])
        return reads.from_init.count(difference.literal.atom) > 0;
    return !valid_with(models, search, d, plan);
}

Candidates candidates_of(const ModelPair &models, const ExplanationSearch &search,
                         const std::vector<std::string> &robot_plan) {
    int n = static_cast<int>(search.differences.size());
    std::map<pddl::Atom, int> held;
    for (const auto &atom : models.human_problem.init)
        ++held[atom];
    Candidates c{std::vector<bool>(n), std::vector<bool>(n)};
    for (int d = 0; d < n; ++d) {
        const ModelDifference &x = search.differences[d];
        auto it = held.find(x.literal.atom);
        c.init_once[d] =
            x.kind == DifferenceKind::INIT && !x.robot_has && it != held.end() && it->second == 1;
    }
    PlanReads reads = plan_reads(models, robot_plan);
    for (int d = 0; d < n; ++d) // pi_R is valid in P_H (checked before)
        c.breaks_robot[d] = breaks_alone(models, search, c, d, robot_plan, reads, true);
    return c;
}

// The candidates (differences that keep pi_R) that `plan` does not survive alone.
std::vector<int> breaking_alone(const ModelPair &models, const ExplanationSearch &search,
                                const Candidates &candidates,
                                const std::vector<std::string> &plan) {
    PlanReads reads = plan_reads(models, plan);
    bool valid_here =
        validate::validate_plan(models.human_domain, models.human_problem, plan).valid;
    std::vector<int> hit;
    for (int d = 0; d < static_cast<int>(candidates.breaks_robot.size()); ++d)
        if (!candidates.breaks_robot[d] &&
            breaks_alone(models, search, candidates, d, plan, reads, valid_here))
            hit.push_back(d);
    return hit;
}

// The sets T of the plans earlier searches met (PlanCache::cheaper_plans) that are plans of
// P_H here and cheaper than pi_R (cost `robot_cost`): the argument above holds for any such
// plan, wherever it was found. False when one has an empty T (no explanation exists).
bool sets_of_known_plans(const ModelPair &models, const std::vector<std::string> &robot_plan,
                         long long robot_cost, const Candidates &candidates,
                         const PlanCache &planner, const ExplanationSearch &search,
                         std::vector<std::vector<int>> &sets) {
    for (const auto &plan : planner.cheaper_plans(robot_plan)) {
        auto v = validate::validate_plan(models.human_domain, models.human_problem, plan);
        if (!v.valid || v.cost >= robot_cost)
            continue;
        std::vector<int> hit = breaking_alone(models, search, candidates, plan);
        if (hit.empty())
            return false;
        if (std::find(sets.begin(), sets.end(), hit) == sets.end())
            sets.push_back(std::move(hit));
    }
    return true;
}

// The answer of telling `chosen`: FOUND when pi_R is then optimal for the human, else the
// set T of the cheaper plan found joins `sets` (NEW_SET; NONE if T is empty: nothing breaks
// that plan); LIMIT when the deadline passed.
enum class Told { FOUND, NEW_SET, NONE, LIMIT };

Told tell(const ModelPair &models, const std::vector<std::string> &robot_plan,
          const std::vector<int> &chosen, const Candidates &candidates, PlanCache &planner,
          const Deadline &deadline, ExplanationSearch &search,
          std::vector<std::vector<int>> &sets) {
    ++search.subsets_tried;
    ModelPair told = told_models(models, search.differences, chosen);
    auto v = validate::validate_plan(told.human_domain, told.human_problem, robot_plan);
    PlanOutcome best = solve_model(told.human_domain, told.human_problem, planner, deadline);
    ++search.planner_checks;
    if (best.status == PlanStatus::LIMIT)
        return Told::LIMIT;
    if (best.status == PlanStatus::SOLVED && v.valid && best.cost == v.cost)
        return Told::FOUND;
    if (best.status == PlanStatus::SOLVED && v.valid && best.cost < v.cost)
        planner.remember_cheaper_plan(robot_plan, best.plan);
    std::vector<int> hit = breaking_alone(models, search, candidates, best.plan);
    if (hit.empty())
        return Told::NONE;
    sets.push_back(std::move(hit));
    return Told::NEW_SET;
}

// After E failed: tell E with every element of the sets just found as well, until no cheaper
// plan is left. Each plan found there is valid with E and those sets told, so none of their
// elements breaks it alone (validity is closed under union): its set is disjoint from E and
// from each of them. Several sets per hitting-set round instead of one, and the disjoint-sets
// bound of least_hitting_set rises as fast as the answer. One plan is cheap on a floor; a
// hitting set of dozens of sight lines is not. NEW_SET when the sets grew (always, unless the
// deadline passed or a plan had an empty set). `more` grows by at least one element a step,
// so at most `size` steps; a set that met it would break that argument, and ends the pass.
template <class Tell>
Told more_disjoint_sets(const std::vector<int> &chosen, Tell &told,
                        std::vector<std::vector<int>> &sets, int size) {
    std::vector<bool> told_already(size, false);
    for (int d : chosen)
        told_already[d] = true;
    std::vector<int> more = chosen;
    for (;;) {
        for (int d : sets.back()) {
            if (told_already[d])
                return Told::NEW_SET;
            told_already[d] = true;
            more.push_back(d);
        }
        Told answer = told(more);
        if (answer == Told::FOUND)
            return Told::NEW_SET;
        if (answer != Told::NEW_SET)
            return answer;
    }
}

} // namespace

void hitting_set_explanation(const ModelPair &models, const std::vector<std::string> &robot_plan,
                             PlanCache &planner, const Deadline &deadline,
                             ExplanationSearch &search) {
    search.hitting_sets = true;
    int n = static_cast<int>(search.differences.size());
    auto robot = validate::validate_plan(models.human_domain, models.human_problem, robot_plan);
    if (!robot.valid) {
        search.status = ExplanationStatus::NONE; // and no restricting difference can mend it
        return;
    }
    Candidates candidates = candidates_of(models, search, robot_plan);
    std::vector<std::vector<int>> sets;
    if (!sets_of_known_plans(models, robot_plan, robot.cost, candidates, planner, search, sets)) {
        search.status = ExplanationStatus::NONE;
        return;
    }
    auto told = [&](const std::vector<int> &chosen) {
        return tell(models, robot_plan, chosen, candidates, planner, deadline, search, sets);
    };
    int floor = 0;
    while (!deadline.expired()) {
        // The sets only grow, so the last least hitting set's size bounds the next one's.
        // Any least hitting set serves until one is an explanation: only then is the
        // lexicographically least one sought (the costly part), and told in its turn.
        std::vector<int> chosen = some_least_hitting_set(sets, n, floor);
        floor = static_cast<int>(chosen.size());
        Told answer = told(chosen);
        if (answer == Told::FOUND) {
            std::vector<int> least = least_hitting_set(sets, n, floor);
            answer = least == chosen ? Told::FOUND : told(least);
            chosen = std::move(least);
        }
        if (answer == Told::NEW_SET)
            answer = more_disjoint_sets(chosen, told, sets, n);
        if (answer == Told::LIMIT)
            return;
        if (answer != Told::NEW_SET) {
            search.status =
                answer == Told::FOUND ? ExplanationStatus::FOUND : ExplanationStatus::NONE;
            if (answer == Told::FOUND)
                search.chosen = chosen;
            return;
        }
    }
}

} // namespace envdesign::design
