#pragma once
// Designs the witness search evaluates outside its best-first order, to learn the human
// plans its bounds need and to prove optimality early (witness_search.h):
//   - probes: per task, a design that breaks every cheaper plan known;
//   - the hitting-set phase (hitting_set.h): the design of least relaxed objective that is
//     not evaluated yet, until none is left within reach of the best one.
// Every design evaluated here is a real design, compared with the best as such.

#include "design/search/design_result.h"
#include "design/search/hitting_set.h"
#include "design/search/witness.h"
#include "design/search/witness_bound.h"
#include "design/search/witness_cones.h"

#include <functional>
#include <optional>
#include <set>
#include <vector>

namespace envdesign::design::witness {

// robot_behaviour EXPLAINING: whether the hitting-set phase applies (explanation_bound.h):
// every modification restricts or adds plans and costs no less than nothing, and at most
// one design is asked for.
bool explaining_applies(const DesignProblem &problem, const TouchIndex &index,
                        const DesignSearchOptions &options);

class DesignLearner {
public:
    // All must outlive the learner; `report` shows progress after each design.
    DesignLearner(const DesignProblem &problem, Evaluator &evaluator,
                  const DesignSearchOptions &options, const TouchIndex &index, SupersetBound &bound,
                  DesignResult &result, Ranking &ranking, std::function<void()> report);

    // Remembers an evaluated configuration of the best-first search (the root first).
    void evaluated(const Node &node);

    // Evaluates a probe design per task that has cheaper plans to break, for some rounds.
    void probe_shortcuts();

    // The hitting-set phase. True when the best design is proven optimal: every design is
    // evaluated or has a relaxed objective above the best one's.
    bool prove_by_hitting_sets();

    // A lower bound on every design's objective, from the last program solved (-inf: none).
    double lower_bound() const { return lower_bound_; }
    // A planner ran out of time on a design evaluated here.
    bool limit_seen() const { return limit_seen_; }
    long long designs() const { return designs_; }

private:
    bool only_adding_added_everywhere() const;
    bool only_lanes_added_everywhere() const;
    bool applies() const;
    std::optional<RootFacts> root_facts();
    std::vector<std::vector<UseFloor>> cost_optimal_floors(const RootFacts &facts) const;
    // `inherit`: look for its tasks among smaller evaluated designs first.
    bool evaluate(const Configuration &design, bool inherit = true);
    std::optional<ConfigurationEvaluation> complete(const ConfigurationEvaluation &request);
    // Evaluates `design` for `tasks` only and learns their plans; the design is not kept.
    // Per task, the human's optimal cost there (nullopt: the deadline or a limit stopped it).
    std::optional<std::vector<double>> probe(const Configuration &design,
                                             const std::vector<int> &tasks);
    Record inherited(const Configuration &design, int task) const;
    void measure(const Configuration &design, const std::vector<Record> &records,
                 const std::vector<std::optional<double>> &robot_bounds);
    void learn_explanation_plans(const Configuration &design, const std::vector<Record> &records);
    void note_explanation_plans();

    const DesignProblem &problem_;
    Evaluator &evaluator_;
    const DesignSearchOptions &options_;
    const TouchIndex &index_;
    SupersetBound &bound_;
    DesignResult &result_;
    Ranking &ranking_;
    std::function<void()> report_;
    int tasks_;
    int max_size_;
    std::optional<Node> root_;
    std::vector<std::pair<Configuration, std::vector<Record>>>
        known_;                           // evaluated here or in the search
    std::vector<Cone> considered_;        // every design whose objective is known, and its cone
    std::vector<MeasuredFloor> measured_; // floors of evaluated designs with additions
    void consider(const Configuration &design, const std::vector<Record> &records);
    std::optional<ExplanationBound> explaining_; // EXPLAINING: built with the root facts
    double lower_bound_;
    bool limit_seen_ = false;
    long long designs_ = 0;
    long long explanation_plans_ = 0; // pooled by learn_explanation_plans
};

} // namespace envdesign::design::witness
