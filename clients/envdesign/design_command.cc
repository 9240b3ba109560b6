#include "design_command.h"

#include "design/design_search.h"
#include "design/design_spec.h"
#include "design/explaining.h"
#include "design/local_evaluator.h"
#include "design/progress.h"
#include "design/relevance.h"
#include "design/result_json.h"

#include <envdesign/client/client.h>
#include <spdlog/spdlog.h>

#include <csignal>
#include <cstdio>
#include <iostream>
#include <unistd.h>

namespace envdesign::cli {
namespace {

std::string number(double value) { return design::json_number(value).dump(); }

void print_terms(const std::string &label, const design::EvaluatedDesign &d) {
    const auto &t = d.objective.terms;
    std::cout << label << number(d.objective.value) << " (inexplicability "
              << number(t.inexplicability) << ", design cost " << number(t.design_cost)
              << ", robot cost " << number(t.robot_cost);
    if (t.explanation != 0)
        std::cout << ", explanation " << number(t.explanation);
    std::cout << ")\n";
}

// The option taken (robot_behaviour EXPLAINING: maybe pi_R and its explanation).
void print_task(const design::DesignProblem &problem, const std::string &name,
                const design::TaskExplicability &t) {
    design::BehaviourChoice c = design::choose_behaviour(problem.weights, t);
    const auto &plan = c.explained ? t.explanation->robot_plan : t.plan;
    std::cout << "task " << name << ": ie " << number(c.ie) << ", robot cost "
              << number(c.robot_cost) << ", plan";
    for (const auto &step : plan)
        std::cout << " " << step;
    std::cout << "\n";
    if (problem.weights.behaviour != design::RobotBehaviour::EXPLAINING || !t.explanation)
        return;
    const auto &x = *t.explanation;
    std::cout << (c.explained ? "  explains" : "  acts explicably (explanation");
    if (!x.found) {
        std::cout << ": none)\n";
        return;
    }
    std::cout << ":";
    for (std::size_t i = 0; i < x.differences.size(); ++i)
        std::cout << (i ? ", " : " ") << x.differences[i];
    if (x.differences.empty())
        std::cout << " nothing to tell";
    std::cout << (c.explained ? "\n" : ")\n");
}

void print_text(const design::DesignProblem &problem, const design::DesignResult &result) {
    std::cout << "status: " << (result.optimal ? "optimal" : "best_found") << "\n";
    if (!result.best) {
        std::cout << "no configuration was evaluated in time\n";
        return;
    }
    std::cout << "design: " << design::to_string(problem, result.best->ranked.configuration)
              << "\n";
    print_terms("objective: ", *result.best);
    if (result.baseline)
        print_terms("baseline: ", *result.baseline);
    for (std::size_t i = 0; i < problem.tasks.size(); ++i)
        print_task(problem, problem.tasks[i].name, result.best->tasks[i]);
    if (result.gap)
        std::cout << "proven gap: " << number(*result.gap) << "\n";
    for (const auto &note : result.notes)
        std::cout << "note: " << note << "\n";
}

design::DesignSearchOptions search_options(const DesignFlags &flags,
                                           const design::DesignProblem &problem) {
    design::DesignSearchOptions options;
    options.max_design_size =
        flags.max_design_size >= 0 ? flags.max_design_size : problem.max_design_size;
    double seconds = flags.time_limit_s >= 0 ? flags.time_limit_s : problem.time_limit_s;
    options.deadline = design::Deadline::in(seconds);
    options.batch_size = 4 * std::max(1, flags.workers);
    options.method = flags.search == "exhaustive" ? design::SearchMethod::EXHAUSTIVE
                                                  : design::SearchMethod::WITNESS;
    return options;
}

volatile std::sig_atomic_t interrupted = 0;
void on_interrupt(int) { interrupted = 1; }

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
    options.prune = flags.prune;
    options.search = flags.search;
    options.heuristic = flags.heuristic;
    options.key_file = flags.key_file;
    options.on_progress = client::stderr_progress();
    options.stop_requested = [] { return interrupted != 0; };
    client::Result result = client::run_design_remote(flags.spec, flags.connect, options);
    if (result.status == "error") {
        std::cerr << result.error << std::endl;
        return result.exit_code;
    }
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
    command.add_option("--workers", flags.workers, "planner threads")->check(CLI::Range(1, 256));
    command
        .add_option("--time-limit", flags.time_limit_s, "seconds (0: none; default: the spec's)")
        ->check(CLI::NonNegativeNumber);
    command
        .add_option("--max-design-size", flags.max_design_size,
                    "most modifications in a design (0: no limit; default: the spec's)")
        ->check(CLI::NonNegativeNumber);
    command
        .add_option("--search", flags.search,
                    "witness (exact, grows designs where they matter) | exhaustive (every subset)")
        ->check(CLI::IsMember({"witness", "exhaustive"}));
    command.add_option("--prune", flags.prune, "none (exact) | relevant (the paper's pruning)")
        ->check(CLI::IsMember({"none", "relevant"}));
    command.add_option("--heuristic", flags.heuristic, "lmcut | hmax | blind")
        ->check(CLI::IsMember({"lmcut", "hmax", "blind"}));
    command.add_option("--connect", flags.connect, "LCM URL of a running coordinator");
    command.add_option("--key-file", flags.key_file,
                       "with --connect: bus keys (default: $ENVDESIGN_KEY_FILE; deploy/LAN.md)");
}

int run_design(const DesignFlags &flags) {
    if (!flags.connect.empty())
        return run_design_remote(flags);
    design::DesignProblem problem;
    try {
        problem = design::load_design_problem(flags.spec);
    } catch (const pddl::ParseError &e) {
        std::cerr << e.what() << std::endl;
        return 2;
    }
    design::DesignSearchOptions options = search_options(flags, problem);
    planning::PlannerOptions planner;
    planner.heuristic = heuristics::parse_heuristic_kind(flags.heuristic);
    design::LocalEvaluator evaluator(problem, flags.workers, planner);
    if (flags.prune == "relevant")
        options.relevant = [&](const design::Configuration &c) {
            return design::relevant_modifications(problem, c, evaluator.planner(),
                                                  options.deadline);
        };
    design::ProgressPrinter printer(stderr, isatty(fileno(stderr)));
    design::DesignResult result;
    try {
        result = design::search_design(problem, evaluator, options,
                                       [&](const design::SearchProgress &p) { printer.update(p); });
    } catch (const pddl::ParseError &e) { // a modified model that does not ground
        std::cerr << "\n" << e.what() << std::endl;
        return 2;
    }
    printer.finish(result);
    if (flags.json)
        std::cout << design::json_text(design::design_json(problem, result)) << std::endl;
    else
        print_text(problem, result);
    if (result.limit_reached)
        spdlog::warn("the time limit stopped the search; the design is the best found");
    return result.limit_reached ? 4 : 0;
}

} // namespace envdesign::cli
