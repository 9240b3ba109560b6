#include "evaluate_command.h"

#include "cli_error.h"
#include "design_warnings.h"
#include "local_run.h"
#include "result_format.h"

#include "design/evaluation/evaluate_design.h"
#include "spec/design_spec.h"
#include "wire/result_message.h"

#include <spdlog/spdlog.h>

#include <iostream>
#include <sstream>

namespace envdesign::cli {
namespace {

// "a,b" -> {"a", "b"}; "" -> {} (the empty design). Blanks around names are dropped.
std::vector<std::string> split_names(const std::string &list) {
    std::vector<std::string> names;
    if (list.find_first_not_of(" \t") == std::string::npos)
        return names;
    std::stringstream in(list);
    std::string name;
    while (std::getline(in, name, ',')) {
        auto first = name.find_first_not_of(" \t");
        auto last = name.find_last_not_of(" \t");
        names.push_back(first == std::string::npos ? "" : name.substr(first, last - first + 1));
    }
    if (!list.empty() && list.back() == ',')
        names.push_back("");
    return names;
}

} // namespace

void add_evaluate_flags(CLI::App &command, EvaluateFlags &flags) {
    command.add_option("spec", flags.spec, "design problem file (.textproto or .json)")->required();
    command
        .add_option("--design", flags.design,
                    "the modifications, comma-separated ('' for the empty design)")
        ->required();
    command.add_flag("--json", flags.json, "print a JSON result");
    add_engine_flags(command, flags.workers, flags.time_limit_s, flags.heuristic);
}

int run_evaluate(const EvaluateFlags &flags) {
    // Bad input throws pddl::ParseError: main() reports it (exit 2).
    std::optional<design::DesignProblem> problem = spec::load_design_problem(flags.spec);
    design::Configuration configuration;
    try {
        configuration = design::configuration_of(*problem, split_names(flags.design));
    } catch (const design::UnknownModification &e) {
        throw CommandError(2, std::string("--design: ") + e.what());
    }
    print_warnings(problem->warnings);
    design::RunSettings settings;
    settings.time_limit_s = flags.time_limit_s;
    design::Deadline deadline = design::search_options(*problem, settings).deadline;
    LocalRun run(*problem, flags.workers, flags.heuristic);
    design::DesignResult result =
        design::evaluate_design(*problem, run.evaluator(), configuration, deadline);
    envdesign::design_result_t message =
        wire::result_message(*problem, run.explained(std::move(result), deadline));
    message.status = "evaluated";
    std::cout << (flags.json ? client::result_json(message) + "\n" : client::result_text(message))
              << std::flush;
    if (message.limit_reached)
        spdlog::warn("the time limit stopped the evaluation");
    return message.limit_reached ? 4 : 0;
}

} // namespace envdesign::cli
