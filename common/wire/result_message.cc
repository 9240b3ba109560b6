#include "wire/result_message.h"

#include "wire/explanation_message.h"

#include <limits>

namespace envdesign::wire {
namespace {

constexpr double NOT_KNOWN = std::numeric_limits<double>::quiet_NaN();

envdesign::design_counters_t counters_message(const design::DesignCounters &c,
                                              const TransportCounters &transport) {
    envdesign::design_counters_t m;
    m.configurations_total = c.configurations_total;
    m.configurations_evaluated = c.configurations_evaluated;
    m.configurations_abandoned = c.configurations_abandoned;
    m.configurations_skipped = c.configurations_skipped;
    m.configurations_pruned = c.configurations_pruned;
    m.tasks_inherited = c.tasks_inherited;
    m.configurations_probed = c.configurations_probed;
    m.task_evaluations = c.evaluator.task_evaluations;
    m.planner_runs = c.evaluator.planner_runs;
    m.cache_hits = c.evaluator.cache_hits;
    m.groundings_skipped = c.evaluator.groundings_skipped;
    m.planner_seconds = c.evaluator.planner_seconds;
    m.seconds = c.seconds;
    m.jobs_sent = transport.jobs_sent;
    m.jobs_resent = transport.jobs_resent;
    m.duplicates_ignored = transport.duplicates_ignored;
    m.planners_used = static_cast<std::int16_t>(transport.planners_used);
    m.transport_seconds = transport.transport_seconds;
    m.job_seconds = transport.job_seconds;
    m.stored_answers = transport.stored_answers;
    return m;
}

// The ranking: with an explanation, each design's point; without, objective and cost only
// (the expectations are NaN: not known).
std::vector<envdesign::design_point_t>
ranking_message(const design::DesignProblem &problem, const design::DesignResult &result,
                const design::DesignExplanation *explanation) {
    std::vector<envdesign::design_point_t> out;
    for (const auto &r : result.ranking) {
        const design::DesignPoint *point = nullptr;
        if (explanation)
            for (const auto &p : explanation->ranking)
                if (p.configuration == r.configuration)
                    point = &p;
        if (point) {
            out.push_back(point_message(problem, *point));
            continue;
        }
        design::DesignPoint unknown;
        unknown.configuration = r.configuration;
        unknown.design_cost = r.design_cost;
        unknown.expected_ie = NOT_KNOWN;
        unknown.expected_robot_cost = NOT_KNOWN;
        envdesign::design_point_t m = point_message(problem, unknown);
        m.terms.objective = r.objective;
        out.push_back(std::move(m));
    }
    return out;
}

// The search proved that no design has a finite objective: which tasks the best design
// (every design is as bad) leaves without a finite IE or robot cost.
std::string no_finite_design(const design::DesignProblem &problem,
                             const design::EvaluatedDesign &best) {
    std::string tasks;
    for (std::size_t i = 0; i < best.tasks.size() && i < problem.tasks.size(); ++i)
        if (!(best.tasks[i].ie < design::INF) || !(best.tasks[i].robot_cost < design::INF))
            tasks += (tasks.empty() ? "'" : ", '") + problem.tasks[i].name + "'";
    std::string why = "every design has an infinite objective";
    return tasks.empty() ? why : why + ": no design gives task(s) " + tasks + " a finite IE";
}

std::vector<std::string> warnings_message(const std::vector<std::string> &warnings) {
    std::vector<std::string> out;
    for (const auto &line : warnings) {
        if (out.size() + 1 == MAX_WARNINGS && warnings.size() > MAX_WARNINGS) {
            out.push_back("... and " + std::to_string(warnings.size() - out.size()) +
                          " more warnings");
            break;
        }
        if (line.size() <= MAX_WARNING_BYTES) {
            out.push_back(line);
            continue;
        }
        std::string cut = line.substr(0, MAX_WARNING_BYTES);
        while (!cut.empty() && (static_cast<unsigned char>(cut.back()) & 0xC0) == 0x80)
            cut.pop_back(); // not inside a UTF-8 character
        if (!cut.empty() && static_cast<unsigned char>(cut.back()) >= 0xC0)
            cut.pop_back();
        out.push_back(cut + " ... (" + std::to_string(line.size() - cut.size()) + " bytes more)");
    }
    return out;
}

} // namespace

envdesign::design_result_t result_message(const design::DesignProblem &problem,
                                          const design::DesignRun &run,
                                          const TransportCounters &transport) {
    const design::DesignResult &result = run.result;
    const design::DesignExplanation *explanation = run.explanation ? &*run.explanation : nullptr;
    envdesign::design_result_t m{};
    // Proven (the search is exact and complete) like `plan` on an unsolvable problem: exit 3.
    bool unsolvable = result.optimal && !result.limit_reached && result.best &&
                      !(result.best->objective.value < design::INF);
    m.exit_code = result.limit_reached ? 4 : unsolvable ? 3 : 0;
    m.status = unsolvable ? "unsolvable" : result.optimal ? "optimal" : "best_found";
    if (unsolvable)
        m.error = no_finite_design(problem, *result.best);
    m.has_design = result.best.has_value();
    if (result.best) {
        m.design = design::design_names(problem, result.best->ranked.configuration);
        m.design_size = static_cast<std::int16_t>(m.design.size());
        m.best = terms_message(result.best->objective);
        for (std::size_t i = 0; i < result.best->tasks.size(); ++i)
            m.tasks.push_back(task_message(problem, static_cast<int>(i), result.best->tasks[i]));
        m.num_tasks = static_cast<std::int16_t>(m.tasks.size());
    }
    m.has_baseline = result.baseline.has_value();
    if (result.baseline)
        m.baseline = terms_message(result.baseline->objective);
    m.counters = counters_message(result.counters, transport);
    m.limit_reached = result.limit_reached;
    m.has_gap = result.gap.has_value();
    m.gap = result.gap.value_or(0);
    m.notes = result.notes;
    m.num_notes = static_cast<std::int16_t>(m.notes.size());
    m.has_explanation = explanation && result.best;
    m.explanation =
        m.has_explanation ? explanation_message(problem, *explanation) : empty_explanation();
    m.ranking = ranking_message(problem, result, explanation);
    m.ranking_size = static_cast<std::int16_t>(m.ranking.size());
    m.warnings = warnings_message(run.warnings);
    m.num_warnings = static_cast<std::int16_t>(m.warnings.size());
    return m;
}

envdesign::design_result_t error_result(int exit_code, const std::string &message) {
    envdesign::design_result_t m{};
    m.exit_code = static_cast<std::int8_t>(exit_code);
    m.status = "error";
    m.error = message;
    m.explanation = empty_explanation();
    return m;
}

} // namespace envdesign::wire
