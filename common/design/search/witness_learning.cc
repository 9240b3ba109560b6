#include "design/search/witness_learning.h"

#include "design/behaviour/behaviour.h"
#include "design/behaviour/explicability.h"
#include "design/search/addition_floors.h"
#include "design/search/hitting_set.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iterator>
#include <map>
#include <sstream>

namespace envdesign::design::witness {

DesignLearner::DesignLearner(const DesignProblem &problem, Evaluator &evaluator,
                             const DesignSearchOptions &options, const TouchIndex &index,
                             SupersetBound &bound, DesignResult &result, Ranking &ranking,
                             std::function<void()> report)
    : problem_(problem), evaluator_(evaluator), options_(options), index_(index), bound_(bound),
      result_(result), ranking_(ranking), report_(std::move(report)),
      tasks_(static_cast<int>(problem.tasks.size())),
      max_size_(options.max_design_size > 0 ? options.max_design_size : index.size()),
      lower_bound_(-INF) {}

void DesignLearner::evaluated(const Node &node) {
    if (node.configuration.empty())
        root_ = node;
    consider(node.configuration, node.tasks);
    known_.emplace_back(node.configuration, node.tasks);
    measure(node.configuration, node.tasks, node.robot_bounds);
}

// Keeps the floors of an evaluated design with additions (measured_floors.h): c_R* always,
// c_H(pi) where the robot takes the most explicable plan.
void DesignLearner::measure(const Configuration &design, const std::vector<Record> &records,
                            const std::vector<std::optional<double>> &robot_bounds) {
    const Behaviour &b = behaviour_of(problem_.weights.behaviour);
    std::vector<const TaskExplicability *> tasks;
    for (const Record &r : records)
        tasks.push_back(r ? &r->evaluation : nullptr);
    std::vector<bool> edits_robot(index_.size());
    for (int m = 0; m < index_.size(); ++m)
        edits_robot[m] = index_.of(m).edits_robot;
    auto floor = measured_floor(design, bound_.always(), edits_robot, tasks, robot_bounds,
                                b.takes_most_explicable_plan && !b.may_explain);
    if (floor)
        measured_.push_back(std::move(*floor));
}

// Meets each task's plans of the human's model that are cheaper than its most explicable
// plan. A probe design breaks every such plan known (one breaker each, the one most tasks'
// plans share); the human's optimal plan there is either another cheaper one, which joins
// the pool, or none, and then breaking the known ones is enough.
void DesignLearner::probe_shortcuts() {
    if (!only_adding_added_everywhere() || !result_.baseline)
        return;
    std::set<int> active;
    for (int t = 0; t < tasks_; ++t)
        if (problem_.tasks[t].probability > 0 &&
            result_.baseline->tasks[t].status == ExplicabilityStatus::SOLVED)
            active.insert(t);
    std::set<Configuration> tried{{}};
    for (int round = 0; round < 64 && !active.empty() && !options_.deadline.expired(); ++round) {
        std::map<Configuration, std::vector<int>> probes; // design -> the tasks it probes
        std::vector<int> shared(index_.size(), 0);        // how many tasks' plans each breaks
        for (int t = 0; t < tasks_; ++t) {
            std::set<int> mods;
            for (const PooledPlan &plan : bound_.plans(t))
                mods.insert(plan.breakers.begin(), plan.breakers.end());
            for (int m : mods)
                ++shared[m];
        }
        for (int t : std::set<int>(active)) {
            // A cheap way to break every known cheaper plan: per plan not broken yet, the
            // breaker that the most tasks' plans share.
            double floor = result_.baseline->tasks[t].human_plan_cost;
            std::set<int> design_set;
            for (const PooledPlan &plan : bound_.plans(t)) {
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
        for (const auto &[design, probed] : probes) {
            if (options_.deadline.expired())
                break;
            auto optimal = probe(design, probed);
            if (!optimal) {
                for (int t : probed)
                    active.erase(t);
                continue;
            }
            ++result_.counters.configurations_probed;
            for (std::size_t i = 0; i < probed.size(); ++i)
                if (!((*optimal)[i] < result_.baseline->tasks[probed[i]].human_plan_cost))
                    active.erase(probed[i]); // no cheaper plan is left
        }
    }
}

// Excludes `design` and the supersets that rank after it from the hitting-set phase.
void DesignLearner::consider(const Configuration &design, const std::vector<Record> &records) {
    considered_.push_back(cone_of(problem_, bound_, design, records));
}

// Whether every modification added everywhere only adds plans and costs nothing less than
// zero (the others are restricting: hitting_set.h).
bool DesignLearner::only_adding_added_everywhere() const {
    return std::all_of(bound_.always().begin(), bound_.always().end(), [&](int m) {
        return index_.of(m).adding && problem_.weights.beta * problem_.modifications[m].cost >= 0;
    });
}

// Whether every modification added everywhere is a lane: it adds plans to the robot's model
// alone.
bool DesignLearner::only_lanes_added_everywhere() const {
    return std::all_of(bound_.always().begin(), bound_.always().end(),
                       [&](int m) { return index_.of(m).adding && !index_.of(m).edits_human; });
}

// The relaxation of hitting_set.h holds when every modification is restricting or adding,
// of non-negative cost, the weights are non-negative and the empty design's objective is
// finite (its floors are known). For EXPLICABLE robots the floors are floors on the most
// explicable plan's human cost; for COST_OPTIMAL(_BEST_CASE) robots on the worst (best)
// optimal plan's, with restricting modifications and lanes only (cost_optimal_floors).
bool DesignLearner::applies() const {
    const ObjectiveWeights &w = problem_.weights;
    const Behaviour &b = behaviour_of(w.behaviour);
    bool behaviour = b.takes_most_explicable_plan ||
                     (b.runs_an_optimal_plan && only_lanes_added_everywhere()) ||
                     explaining_applies(problem_, index_, options_);
    return options_.hitting_sets && behaviour && root_ && result_.best &&
           std::isfinite(result_.best->objective.value) && only_adding_added_everywhere() &&
           w.alpha >= 0 && w.beta >= 0 && w.kappa >= 0 && result_.baseline &&
           std::isfinite(result_.baseline->objective.value);
}

bool explaining_applies(const DesignProblem &problem, const TouchIndex &index,
                        const DesignSearchOptions &options) {
    if (!behaviour_of(problem.weights.behaviour).may_explain || !options.hitting_sets ||
        options.ranking > 1)
        return false;
    for (int m = 0; m < index.size(); ++m)
        if (!(index.of(m).restricting || index.of(m).adding) ||
            problem.weights.beta * problem.modifications[m].cost < 0)
            return false;
    return true;
}

// COST_OPTIMAL(_BEST_CASE), every modification restricting or a lane: per task, the modifications
// under which the empty design's worst (best) optimal plan's human cost is no floor. That
// plan, pi_0, is a floor while it stays a robot plan and no lane below lowers c_R*: then it is
// still optimal (c_R* does not drop), so the worst case is at least its IE; for the best case c_R*
// is unchanged, so the optimal plans are some of the empty design's, none cheaper for people than
// pi_0. Its human cost only rises under restricting edits, and the human's optimum is bounded by
// the pool as for EXPLICABLE robots. A modification that can break pi_0 as a robot plan drops the
// floor, to nothing (docs/design-search.md). So does a lane (adding, robot-only) whose plans may
// cost no more than c_R* (addition_floors.h's robot floors): it may bring optimal plans of its own.
// Any other lane leaves the optimal plans as they are: each of its plans costs more than c_R*,
// which restricting edits never lower.
std::vector<std::vector<UseFloor>>
DesignLearner::cost_optimal_floors(const RootFacts &facts) const {
    std::vector<std::vector<UseFloor>> out(tasks_);
    for (int t = 0; t < tasks_; ++t) {
        const Record &r = root_->tasks[t];
        if (problem_.tasks[t].probability <= 0 || !r)
            continue;
        auto breakers = index_.touching_robot_plan({}, t, r->evaluation.plan);
        for (int m = 0; m < index_.size(); ++m)
            if (index_.of(m).restricting &&
                (breakers ? contains(*breakers, m) : index_.of(m).edits_robot))
                out[t].push_back(UseFloor{m, -INF});
        // A lane whose plans may cost no more than c_R* may bring optimal plans of its own.
        for (int m : bound_.always()) {
            const auto &lanes = facts.lower_robot_floors[t];
            if (!facts.robot_bounds[t] ||
                std::any_of(lanes.begin(), lanes.end(),
                            [&](const UseFloor &f) { return f.modification == m; }))
                out[t].push_back(UseFloor{m, -INF});
        }
    }
    return out;
}

// The facts of hitting_set.h from the empty design, with the floors that adding
// modifications can bring (addition_floors.h); nullopt when those cannot be computed.
std::optional<RootFacts> DesignLearner::root_facts() {
    RootFacts facts;
    bool optimal_plan = behaviour_of(problem_.weights.behaviour).runs_an_optimal_plan;
    // Every modification is restricting or adding (applies()): the root's c_R* is a floor
    // on the robot's cost except where an adding one lowers it (addition_floors.h).
    for (int t = 0; t < tasks_; ++t) {
        facts.floor.push_back(result_.baseline->tasks[t].human_plan_cost);
        std::optional<double> robot = root_->robot_bounds[t];
        const Record &r = root_->tasks[t];
        // Without kappa no bound is asked for; an optimal plan's cost is c_R* all the same.
        if (!robot && optimal_plan && r && r->evaluation.status == ExplicabilityStatus::SOLVED)
            robot = r->evaluation.robot_cost;
        facts.robot_bounds.push_back(robot);
    }
    facts.lower_floors.resize(tasks_);
    facts.lower_robot_floors.resize(tasks_);
    facts.robot_floor_bounds_human = ie_floors_hold(problem_);
    if (!bound_.always().empty()) {
        std::string why;
        // COST_OPTIMAL(_BEST_CASE) reads only the robot's floors (cost_optimal_floors).
        std::vector<double> floor = optimal_plan ? std::vector<double>(tasks_, -INF) : facts.floor;
        auto floors = addition_floors(problem_, bound_.always(), floor, facts.robot_bounds,
                                      options_.deadline, why);
        if (!floors) {
            result_.notes.push_back("the hitting-set phase was not used: " + why);
            return std::nullopt;
        }
        std::ostringstream seconds;
        seconds << std::setprecision(3) << floors->seconds;
        result_.notes.push_back(
            "floors of the adding modifications: " + std::to_string(floors->searches) +
            " searches in " + seconds.str() + " s (docs/design-search.md)");
        facts.lower_floors = std::move(floors->below);
        facts.lower_robot_floors = std::move(floors->robot_below);
    }
    if (optimal_plan)
        facts.lower_floors = cost_optimal_floors(facts);
    const Behaviour &behaviour = behaviour_of(problem_.weights.behaviour);
    for (int t = 0; t < tasks_; ++t) {
        const Record &r = root_->tasks[t];
        bool settled = behaviour.value_follows_witnesses && r && r->touch.known &&
                       r->touch.all.empty() && facts.lower_floors[t].empty();
        facts.settled.push_back(settled ? &r->evaluation : nullptr);
    }
    if (behaviour.may_explain) {
        try {
            explaining_.emplace(problem_, index_, root_->tasks);
        } catch (const pddl::ParseError &e) {
            result_.notes.push_back(std::string("the hitting-set phase was not used: ") + e.what());
            return std::nullopt;
        }
        facts.explaining = &*explaining_;
    }
    return facts;
}

bool DesignLearner::prove_by_hitting_sets() {
    if (!applies())
        return false;
    auto facts = root_facts();
    if (!facts)
        return false;
    HittingSetMaster master(problem_, bound_, std::move(*facts), options_.max_design_size);
    learn_explanation_plans({}, root_->tasks); // the root was evaluated before the phase
    // Designs the evaluator answers without planning (stored from earlier searches of the
    // same models) teach their plans first, so a re-design after drift plans little.
    std::set<Configuration> seen;
    for (const Cone &cone : considered_)
        seen.insert(cone.design);
    for (const Configuration &design : evaluator_.known_configurations(1024)) {
        if (options_.deadline.expired())
            return false;
        if (static_cast<int>(design.size()) > max_size_ || seen.count(design))
            continue;
        if (!evaluate(design, false))
            return false;
        ++result_.counters.configurations_probed;
    }
    while (!options_.deadline.expired()) {
        double best = result_.best->objective.value;
        // With a ranking, every design that may enter it must be evaluated (or lie in a
        // cone, whose members are offered as they are found): the cutoff is the N-th best.
        double limit = ranking_limit(result_, ranking_);
        auto answer = master.least(considered_, measured_, limit + HittingSetMaster::margin(limit),
                                   options_.deadline);
        if (answer.status == HittingSetMaster::Answer::NONE) {
            // A design a limit stopped earlier (a probe) is in no cone: it was picked again,
            // or its relaxed objective is above the best. Either way the proof holds.
            limit_seen_ = false;
            lower_bound_ = best;
            note_explanation_plans();
            if (!measured_.empty())
                result_.notes.push_back("floors measured in " + std::to_string(measured_.size()) +
                                        " designs with additions bound the others "
                                        "(docs/design-search.md)");
            return true;
        }
        if (answer.status == HittingSetMaster::Answer::FAILED) {
            if (answer.out_of_range)
                result_.notes.push_back("the hitting-set phase was not used: the objective's "
                                        "numbers exceed what its solver takes exactly "
                                        "(docs/numbers.md); the search proved the design alone");
            return false;
        }
        lower_bound_ = std::min(best, answer.bound);
        if (!evaluate(answer.design))
            return false;
        learn_explanation_plans(answer.design, known_.back().second);
        ++designs_;
        ++result_.counters.configurations_evaluated;
    }
    return false;
}

// EXPLAINING: pools the human plans the design's explanations meet (explanation_bound.h),
// which tighten the explaining option's bound on every design that keeps them.
void DesignLearner::learn_explanation_plans(const Configuration &design,
                                            const std::vector<Record> &records) {
    if (!explaining_)
        return;
    for (int t = 0; t < tasks_; ++t) {
        if (!records[t] || records[t]->evaluation.status != ExplicabilityStatus::SOLVED ||
            !records[t]->evaluation.explanation)
            continue;
        const TaskExplicability &e = records[t]->evaluation;
        auto plans =
            explaining_->explanation_plans(problem_, design, t, *e.explanation, options_.deadline);
        explanation_plans_ += static_cast<long long>(plans.size());
        for (auto &[plan, cost] : plans) {
            TaskExplicability met; // learn() pools human_plan at human_optimal_cost
            met.status = ExplicabilityStatus::SOLVED;
            met.human_plan = std::move(plan);
            met.human_optimal_cost = cost;
            bound_.learn(design, t, met);
        }
    }
}

void DesignLearner::note_explanation_plans() {
    if (!explaining_)
        return;
    CacheCounters c = explaining_->planner_counters();
    std::ostringstream seconds;
    seconds << std::setprecision(3) << c.planner_seconds;
    result_.notes.push_back(
        "the explaining bound pooled " + std::to_string(explanation_plans_) +
        " plans its explanation searches met: " + std::to_string(c.planner_runs) +
        " planner runs in " + seconds.str() + " s, not among planner_runs (docs/design-search.md)");
}

// The record of `task` under `design` from a smaller evaluated configuration, when every
// modification added since is restricting and touches none of its witnesses.
Record DesignLearner::inherited(const Configuration &design, int task) const {
    if (!behaviour_of(problem_.weights.behaviour).value_follows_witnesses)
        return nullptr; // an explanation may change without a witness touched
    for (const auto &known : known_) {
        const Configuration &configuration = known.first; // a lambda below uses it: clang 14
        const Record &r = known.second[task];             // captures no structured binding
        if (!r || !r->touch.known || configuration.size() > design.size() ||
            !std::includes(design.begin(), design.end(), configuration.begin(),
                           configuration.end()))
            continue;
        if (std::none_of(design.begin(), design.end(), [&](int m) {
                return !contains(configuration, m) &&
                       (!index_.of(m).restricting || contains(r->touch.all, m));
            }))
            return r;
    }
    return nullptr;
}

// Evaluates `design` in full, learns its plans and compares it with the best; false when a
// limit or the deadline stopped it.
// The evaluator's answer to one configuration, every task known; nullopt when a limit or the
// deadline stopped it.
std::optional<ConfigurationEvaluation>
DesignLearner::complete(const ConfigurationEvaluation &request) {
    ConfigurationEvaluation answer;
    EvaluationCallbacks callbacks;
    callbacks.abandon = [](const ConfigurationEvaluation &) { return false; };
    callbacks.done = [&](ConfigurationEvaluation e) { answer = std::move(e); };
    evaluator_.evaluate({request}, options_.deadline, callbacks);
    if (answer.status != EvaluationStatus::COMPLETE) {
        limit_seen_ = limit_seen_ || answer.status == EvaluationStatus::LIMIT;
        return std::nullopt;
    }
    return answer;
}

// A probe asks about the plans of its own tasks. Where the design's other tasks need a few
// evaluations more, the design is evaluated whole (it then bounds the search as any design
// does: its cone, its place in the ranking); where they need tens (a floor's tape crosses
// the routes of many tasks), they are given the empty design's values, which nothing reads
// back, and the hitting-set phase finds the design if it is worth evaluating whole.
std::optional<std::vector<double>> DesignLearner::probe(const Configuration &design,
                                                        const std::vector<int> &tasks) {
    std::vector<Record> records(tasks_);
    int planned = 0;
    for (int t = 0; t < tasks_; ++t)
        if (problem_.tasks[t].probability > 0 && !(records[t] = inherited(design, t)))
            ++planned;
    if (planned <= 2 * static_cast<int>(tasks.size()) + 4) {
        if (!evaluate(design))
            return std::nullopt;
        std::vector<double> optimal;
        for (int t : tasks)
            optimal.push_back(known_.back().second[t]->evaluation.human_optimal_cost.value_or(INF));
        return optimal;
    }
    ConfigurationEvaluation request = unevaluated(design);
    request.tasks.resize(tasks_);
    for (int t = 0; t < tasks_; ++t)
        request.tasks[t] = values_only(result_.baseline->tasks[t]);
    for (int t : tasks) {
        request.tasks[t].reset();
        if (records[t]) {
            request.tasks[t] = values_only(records[t]->evaluation);
            ++result_.counters.tasks_inherited;
        }
    }
    auto answer = complete(request);
    if (!answer)
        return std::nullopt;
    std::vector<double> optimal;
    for (int t : tasks) {
        if (!records[t])
            bound_.learn(design, t, *answer->tasks[t]);
        const TaskExplicability &e = records[t] ? records[t]->evaluation : *answer->tasks[t];
        optimal.push_back(e.human_optimal_cost.value_or(INF));
    }
    return optimal;
}

bool DesignLearner::evaluate(const Configuration &design, bool inherit) {
    ConfigurationEvaluation request = unevaluated(design);
    std::vector<Record> records(tasks_);
    request.tasks.resize(tasks_);
    for (int t = 0; t < tasks_; ++t)
        if (inherit && (records[t] = inherited(design, t))) {
            request.tasks[t] = values_only(records[t]->evaluation);
            ++result_.counters.tasks_inherited;
        }
    auto answer = complete(request);
    if (!answer)
        return false;
    std::vector<TaskExplicability> tasks;
    for (int t = 0; t < tasks_; ++t) {
        if (!records[t]) {
            auto record = std::make_shared<TaskRecord>();
            record->evaluation = std::move(*answer->tasks[t]);
            record->touch = index_.touching(design, t, record->evaluation);
            bound_.learn(design, t, record->evaluation);
            records[t] = std::move(record);
        }
        tasks.push_back(records[t]->evaluation);
    }
    known_.emplace_back(design, std::move(records));
    measure(design, known_.back().second, answer->robot_cost_bounds);
    if (report_)
        report_();
    if (static_cast<int>(design.size()) <= max_size_) {
        consider(design, known_.back().second);
        consider_design(problem_, design, std::move(tasks), result_, ranking_);
        if (ranking_.size() > 1)
            offer_cone_of(problem_, bound_, design, known_.back().second, max_size_, ranking_);
    }
    return true;
}

} // namespace envdesign::design::witness
