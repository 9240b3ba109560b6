#include "design/evaluation/evaluation_log.h"

namespace envdesign::design {

void EvaluationLog::evaluate(const std::vector<ConfigurationEvaluation> &batch,
                             const Deadline &deadline, const EvaluationCallbacks &callbacks) {
    EvaluationCallbacks wrapped;
    wrapped.abandon = callbacks.abandon;
    wrapped.done = [&](ConfigurationEvaluation evaluation) {
        if (evaluation.status == EvaluationStatus::COMPLETE) {
            std::vector<TaskExplicability> tasks;
            for (const auto &t : evaluation.tasks)
                tasks.push_back(t.value_or(TaskExplicability{}));
            keep(design_point(problem_, evaluation.configuration, tasks));
        }
        if (callbacks.done)
            callbacks.done(std::move(evaluation));
    };
    inner_.evaluate(batch, deadline, wrapped);
}

std::optional<DesignPoint> EvaluationLog::find(const Configuration &configuration) const {
    auto it = points_.find(configuration);
    if (it == points_.end())
        return std::nullopt;
    return it->second;
}

std::vector<DesignPoint> EvaluationLog::points() const {
    std::vector<DesignPoint> out;
    for (const auto &[configuration, point] : points_)
        out.push_back(point);
    return out;
}

} // namespace envdesign::design
