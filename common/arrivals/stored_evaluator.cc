#include "arrivals/stored_evaluator.h"

namespace envdesign::arrivals {

using design::ConfigurationEvaluation;
using design::EvaluationStatus;
using design::ExplicabilityStatus;

StoredEvaluator::StoredEvaluator(const design::DesignProblem &problem, design::Evaluator &inner)
    : problem_(problem), inner_(inner) {}

const design::TaskExplicability *StoredEvaluator::find(const design::Configuration &configuration,
                                                       const std::string &task) const {
    auto it = store_.find({configuration, task});
    return it == store_.end() ? nullptr : &it->second;
}

void StoredEvaluator::forget_task(const std::string &task) {
    for (auto it = store_.begin(); it != store_.end();)
        it = it->first.second == task ? store_.erase(it) : std::next(it);
}

std::optional<ConfigurationEvaluation>
StoredEvaluator::from_store(const design::Configuration &configuration) const {
    ConfigurationEvaluation e;
    e.configuration = configuration;
    e.status = EvaluationStatus::COMPLETE;
    for (const auto &task : problem_.tasks) {
        const design::TaskExplicability *t = find(configuration, task.name);
        if (!t)
            return std::nullopt;
        e.tasks.emplace_back(*t);
        e.robot_cost_bounds.emplace_back(); // not needed: every task is known
    }
    return e;
}

void StoredEvaluator::keep(const ConfigurationEvaluation &evaluation) {
    for (std::size_t i = 0; i < evaluation.tasks.size() && i < problem_.tasks.size(); ++i) {
        const auto &t = evaluation.tasks[i];
        if (t && t->status != ExplicabilityStatus::LIMIT)
            store_.insert_or_assign({evaluation.configuration, problem_.tasks[i].name}, *t);
    }
}

void StoredEvaluator::evaluate(const std::vector<design::Configuration> &batch,
                               const design::Deadline &deadline,
                               const design::EvaluationCallbacks &callbacks) {
    std::vector<design::Configuration> missing;
    for (const auto &configuration : batch) {
        if (auto stored = from_store(configuration)) {
            ++stored_answers_;
            callbacks.done(std::move(*stored));
        } else {
            missing.push_back(configuration);
        }
    }
    if (missing.empty())
        return;
    design::EvaluationCallbacks keeping;
    keeping.abandon = callbacks.abandon;
    keeping.done = [&](ConfigurationEvaluation evaluation) {
        keep(evaluation); // partial ones too: a task evaluated before a cut-off is still known
        callbacks.done(std::move(evaluation));
    };
    inner_.evaluate(missing, deadline, keeping);
}

} // namespace envdesign::arrivals
