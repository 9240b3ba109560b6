#include "report_command.h"

#include "cli_error.h"
#include "local_run.h"
#include "report_html.h"

#include "design/progress.h"
#include "pddl/parse_error.h"
#include "spec/design_spec.h"

#include <spdlog/spdlog.h>

#include <filesystem>
#include <fstream>
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

int run_report(const ReportFlags &flags) {
    // Bad input throws pddl::ParseError: main() reports it (exit 2).
    std::optional<design::DesignProblem> problem = spec::load_design_problem(flags.spec);
    design::DesignSearchOptions options;
    options.max_design_size = problem->max_design_size;
    double seconds = flags.time_limit_s >= 0 ? flags.time_limit_s : problem->time_limit_s;
    options.deadline = design::Deadline::in(seconds);
    options.batch_size = 4 * flags.workers;
    options.ranking = flags.ranking;
    LocalRun run(*problem, flags.workers, flags.heuristic);
    design::ProgressPrinter printer(stderr, isatty(fileno(stderr)));
    envdesign::design_result_t message;
    try {
        design::DesignResult result =
            design::search_design(*problem, run.evaluator(), options,
                                  [&](const design::SearchProgress &p) { printer.update(p); });
        printer.finish(result);
        message = run.message(result, options.deadline);
    } catch (const pddl::ParseError &) { // a modified model that does not ground
        std::cerr << "\n";
        throw;
    }
    if (!message.has_design || !message.has_explanation)
        throw CommandError(4, "no design was evaluated in time: nothing to report");
    std::string title = std::filesystem::path(flags.spec).filename().string();
    std::string page;
    try {
        page = client::report_html(message, title);
    } catch (const client::PlotError &e) {
        throw CommandError(1, e.what());
    }
    std::ofstream file(flags.output, std::ios::binary);
    file << page;
    file.close();
    if (!file)
        throw CommandError(1, "cannot write " + flags.output);
    spdlog::info("wrote {} ({} bytes): {}", flags.output, page.size(),
                 message.status == "optimal" ? "the optimal design" : "the best design found");
    return message.limit_reached ? 4 : 0;
}

} // namespace envdesign::cli
