#include "design_command.h"

#include "cli_error.h"
#include "design_warnings.h"
#include "local_run.h"
#include "progress.h"
#include "result_format.h"

#include "design/model/numbers.h"
#include "service/number_flag.h"
#include "spec/design_spec.h"
#include "wire/result_message.h"

#include <envdesign/client/client.h>
#include <spdlog/spdlog.h>

#include <atomic>
#include <csignal>
#include <cstdio>
#include <iostream>
#include <unistd.h>

namespace envdesign::cli {
namespace {

design::RunSettings run_settings(const DesignFlags &flags) {
    design::RunSettings settings;
    settings.time_limit_s = flags.time_limit_s;
    settings.max_design_size = flags.max_design_size;
    settings.method = flags.search == "exhaustive" ? design::SearchMethod::EXHAUSTIVE
                                                   : design::SearchMethod::WITNESS;
    settings.prune_relevant = flags.prune == "relevant";
    settings.ranking = flags.ranking;
    settings.ranking_all = flags.ranking_all;
    settings.batch_size = 4 * std::max(1, flags.workers);
    return settings;
}

// Set by SIGINT/SIGTERM only (a handler can reach nothing else); lock-free, so safe there.
// A second Ctrl-C ends the process at once (a planner call may take long to return).
std::atomic<bool> interrupted{false};
extern "C" void on_interrupt(int signal) {
    interrupted = true;
    std::signal(signal, SIG_DFL);
}

// A client of the coordinator at `flags.connect`: the same search, run by the cluster.
// Ctrl-C (or SIGTERM) cancels the request; the coordinator's best design so far is printed.
int run_design_remote(const DesignFlags &flags) {
    if (flags.workers != 1)
        spdlog::warn("--workers does not apply with --connect: the cluster's planners work");
    std::signal(SIGINT, on_interrupt);
    std::signal(SIGTERM, on_interrupt);
    client::Options options;
    options.time_limit_s = flags.time_limit_s;
    options.max_design_size = flags.max_design_size;
    options.ranking = flags.ranking;
    options.ranking_all = flags.ranking_all;
    options.prune = flags.prune;
    options.search = flags.search;
    options.heuristic = flags.heuristic;
    options.key_file = flags.key_file;
    options.on_progress = client::stderr_progress();
    options.stop_requested = [] { return interrupted.load(); };
    client::Result result = client::run_design_remote(flags.spec, flags.connect, options);
    if (result.status == "error")
        throw CommandError(result.exit_code, result.error);
    print_warnings(result.warnings);
    std::cout << (flags.json ? result.json + "\n" : result.text) << std::flush;
    if (result.exit_code == 4)
        spdlog::warn("{}; the design is the best found",
                     interrupted ? "interrupted" : "the time limit stopped the search");
    return result.exit_code;
}

} // namespace

void add_design_flags(CLI::App &command, DesignFlags &flags) {
    command.add_option("spec", flags.spec, "design problem file (.textproto or .json)")->required();
    command.add_flag("--json", flags.json, "print a JSON result");
    add_engine_flags(command, flags.workers, flags.time_limit_s, flags.heuristic);
    command
        .add_option("--max-design-size", flags.max_design_size,
                    "most modifications in a design (0: no limit; default: the spec's)")
        ->check(service::number_in(design::DESIGN_SIZE));
    command
        .add_option("--search", flags.search,
                    "witness (exact, grows designs where they matter) | exhaustive (every subset)")
        ->check(CLI::IsMember({"witness", "exhaustive"}));
    command
        .add_option("--ranking", flags.ranking,
                    "list the N best designs in which every modification pays for itself, best "
                    "first (0: the best alone)")
        ->check(CLI::Range(0, 100000));
    command.add_flag("--ranking-all", flags.ranking_all,
                     "with --ranking: padded designs too (a modification that does not pay)");
    command.add_option("--prune", flags.prune, "none (exact) | relevant (the paper's pruning)")
        ->check(CLI::IsMember({"none", "relevant"}));
    command.add_option("--connect", flags.connect, "LCM URL of a running coordinator");
    command.add_option("--key-file", flags.key_file,
                       "with --connect: bus keys (default: $ENVDESIGN_KEY_FILE; deploy/LAN.md)");
}

int run_design(const DesignFlags &flags) {
    if (!flags.connect.empty())
        return run_design_remote(flags);
    // Bad input throws pddl::ParseError: main() reports it (exit 2).
    design::DesignProblem problem = spec::load_design_problem(flags.spec);
    print_warnings(problem.warnings); // before a search that may take long
    design::RunSettings settings = run_settings(flags);
    // Ctrl-C (or SIGTERM) stops the search as a time limit would: the best design so far.
    std::signal(SIGINT, on_interrupt);
    std::signal(SIGTERM, on_interrupt);
    settings.stop = &interrupted;
    LocalRun local(problem, flags.workers, flags.heuristic);
    ProgressPrinter printer(stderr, isatty(fileno(stderr)));
    design::DesignRun run;
    try {
        run = local.run(settings, [&](const design::SearchProgress &p) { printer.update(p); });
    } catch (const pddl::ParseError &) { // a modified model that does not ground
        std::cerr << "\n";
        throw;
    }
    printer.finish(run.result);
    print_warnings({run.warnings.begin() + problem.warnings.size(), run.warnings.end()});
    envdesign::design_result_t message = wire::result_message(problem, run);
    std::cout << (flags.json ? client::result_json(message) + "\n" : client::result_text(message))
              << std::flush;
    const design::DesignResult &result = run.result;
    if (result.limit_reached)
        spdlog::warn("{}; the design is the best found",
                     interrupted ? "interrupted" : "the time limit stopped the search");
    return message.exit_code; // 3: proven that every design's objective is infinite
}

} // namespace envdesign::cli
