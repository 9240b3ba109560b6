#include "report_command.h"

#include "cli_error.h"
#include "local_run.h"
#include "output_file.h"
#include "progress.h"
#include "report_floor.h"
#include "report_html.h"

#include "design/behaviour/explicability.h"
#include "design/model/configuration.h"
#include "pddl/parse_error.h"
#include "spec/design_spec.h"
#include "wire/result_message.h"

#include <spdlog/spdlog.h>

#include <filesystem>
#include <iostream>
#include <unistd.h>

namespace envdesign::cli {

void add_report_flags(CLI::App &command, ReportFlags &flags) {
    command.add_option("spec", flags.spec, "design problem file (.textproto or .json)")->required();
    command.add_option("-o,--output", flags.output, "the HTML file to write")->required();
    command.add_option("--ranking", flags.ranking, "designs in the ranking and the plots")
        ->check(CLI::Range(1, 100));
    add_engine_flags(command, flags.workers, flags.time_limit_s, flags.heuristic);
}

namespace {

std::optional<client::Plan> solved(const design::PlanOutcome &outcome) {
    if (outcome.status != design::PlanStatus::SOLVED)
        return std::nullopt;
    return outcome.plan;
}

// The plans under the empty design that the message does not carry: what people expected
// (P_H) and the robot's optimal plan (P_R). The search planned both for the baseline, so
// the cache answers most; at most a few seconds in all.
client::ReportExtras plans_before(const design::DesignProblem &problem, LocalRun &run) {
    constexpr double AT_MOST_S = 10;
    design::Deadline deadline = design::Deadline::in(AT_MOST_S);
    client::ReportExtras extras;
    for (std::size_t i = 0; i < problem.tasks.size(); ++i) {
        design::ModelPair models = design::configured_models(problem, {}, static_cast<int>(i));
        design::PlanCache &planner = run.local().planner();
        extras.expected_before.push_back(solved(
            design::solve_model(models.human_domain, models.human_problem, planner, deadline)));
        extras.robot_optimal_before.push_back(solved(
            design::solve_model(models.robot_domain, models.robot_problem, planner, deadline)));
    }
    return extras;
}

} // namespace

int run_report(const ReportFlags &flags) {
    // Bad input throws pddl::ParseError: main() reports it (exit 2).
    std::optional<design::DesignProblem> problem = spec::load_design_problem(flags.spec);
    check_output_path(flags.output);
    design::RunSettings settings;
    settings.time_limit_s = flags.time_limit_s;
    settings.batch_size = 4 * flags.workers;
    settings.ranking = flags.ranking;
    LocalRun run(*problem, flags.workers, flags.heuristic);
    ProgressPrinter printer(stderr, isatty(fileno(stderr)));
    envdesign::design_result_t message;
    try {
        design::DesignRun answer =
            run.run(settings, [&](const design::SearchProgress &p) { printer.update(p); });
        printer.finish(answer.result);
        message = wire::result_message(*problem, answer);
    } catch (const pddl::ParseError &) { // a modified model that does not ground
        std::cerr << "\n";
        throw;
    }
    if (!message.has_design || !message.has_explanation)
        throw CommandError(4, "no design was evaluated in time: nothing to report");
    std::string title = std::filesystem::path(flags.spec).filename().string();
    client::ReportExtras extras = plans_before(*problem, run);
    extras.floor_section = report_floor_section(flags.spec, message, extras);
    std::string page;
    try {
        page = client::report_html(message, title, extras);
    } catch (const client::PlotError &e) {
        throw CommandError(1, e.what());
    }
    write_output_file(flags.output, page);
    spdlog::info("wrote {} ({} bytes): {}", flags.output, page.size(),
                 message.status == "optimal"      ? "the optimal design"
                 : message.status == "unsolvable" ? "no design has a finite objective"
                                                  : "the best design found");
    return message.exit_code;
}

} // namespace envdesign::cli
