#pragma once
// An Evaluator in front of another that keeps the point (design_point.h) of every
// configuration evaluated in full through it, so that what a search evaluated can be
// re-weighed afterwards (break-even, plots) without planning again. Abandoned and
// time-limited configurations are passed on and not kept.
//
//   LocalEvaluator local(problem, workers);
//   EvaluationLog log(problem, local);
//   DesignResult result = search_design(problem, log, options);
//   DesignExplanation why = explain_design(problem, result, log, ...);   // design_explanation.h

#include "design/evaluation/evaluator.h"
#include "design/objective/design_point.h"

#include <map>
#include <optional>

namespace envdesign::design {

class EvaluationLog : public Evaluator {
public:
    // Both must outlive the log.
    EvaluationLog(const DesignProblem &problem, Evaluator &inner)
        : problem_(problem), inner_(inner) {}

    void evaluate(const std::vector<ConfigurationEvaluation> &batch, const Deadline &deadline,
                  const EvaluationCallbacks &callbacks) override;
    EvaluatorCounters counters() const override { return inner_.counters(); }
    std::vector<Configuration> known_configurations(std::size_t limit) override {
        return inner_.known_configurations(limit);
    }

    // Keeps a design evaluated elsewhere (e.g. one the search completed from inherited tasks).
    void keep(const DesignPoint &point) { points_[point.configuration] = point; }
    std::optional<DesignPoint> find(const Configuration &configuration) const;
    // Every kept design, in configuration order.
    std::vector<DesignPoint> points() const;

private:
    const DesignProblem &problem_;
    Evaluator &inner_;
    std::map<Configuration, DesignPoint> points_;
};

} // namespace envdesign::design
