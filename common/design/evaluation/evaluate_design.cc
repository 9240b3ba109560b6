#include "design/evaluation/evaluate_design.h"

#include "design/search/ranking.h"

#include <algorithm>
#include <chrono>

namespace envdesign::design {
namespace {

std::string known_names(const DesignProblem &problem) {
    std::string out;
    for (const auto &m : problem.modifications)
        out += (out.empty() ? "" : ", ") + m.name;
    return out.empty() ? "no modifications" : out;
}

} // namespace

Configuration configuration_of(const DesignProblem &problem,
                               const std::vector<std::string> &names) {
    Configuration out;
    for (const auto &name : names) {
        auto it = std::find_if(problem.modifications.begin(), problem.modifications.end(),
                               [&](const Modification &m) { return m.name == name; });
        if (it == problem.modifications.end())
            throw UnknownModification("no modification named '" + name + "' in " + problem.file +
                                      " (it has: " + known_names(problem) + ")");
        int index = static_cast<int>(it - problem.modifications.begin());
        if (std::find(out.begin(), out.end(), index) != out.end())
            throw UnknownModification("modification '" + name + "' is named twice");
        out.push_back(index);
    }
    std::sort(out.begin(), out.end());
    return out;
}

DesignResult evaluate_design(const DesignProblem &problem, Evaluator &evaluator,
                             const Configuration &configuration, const Deadline &deadline) {
    auto start = std::chrono::steady_clock::now();
    DesignResult result;
    std::vector<ConfigurationEvaluation> batch{unevaluated(configuration)};
    if (!configuration.empty())
        batch.push_back(unevaluated({}));
    EvaluationCallbacks callbacks;
    callbacks.abandon = [](const ConfigurationEvaluation &) { return false; };
    std::optional<EvaluatedDesign> proposed;
    callbacks.done = [&](ConfigurationEvaluation e) {
        if (e.status != EvaluationStatus::COMPLETE) {
            result.limit_reached = true;
            return;
        }
        ++result.counters.configurations_evaluated;
        std::vector<TaskExplicability> tasks;
        for (auto &t : e.tasks)
            tasks.push_back(std::move(*t));
        DesignResult single; // consider_design() keeps the better; here each is its own
        Ranking unranked;
        consider_design(problem, e.configuration, std::move(tasks), single, unranked);
        if (e.configuration == configuration)
            proposed = single.best;
        if (e.configuration.empty())
            result.baseline = single.best;
    };
    evaluator.evaluate(batch, deadline, callbacks);
    result.best = proposed;
    result.counters.configurations_total = 1;
    close_counters(result.counters, evaluator, start);
    return result;
}

} // namespace envdesign::design
