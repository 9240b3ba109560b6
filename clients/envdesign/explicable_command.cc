#include "explicable_command.h"

#include "design/behaviour/explicability.h"
#include "pddl/parser.h"
#include "result_format.h"
#include "service/number_flag.h"

#include <iostream>

namespace envdesign::cli {
namespace {

design::ModelPair load_models(const ExplicableFlags &flags) {
    design::ModelPair models;
    models.robot_domain = pddl::parse_domain_file(flags.robot_domain);
    models.human_domain = flags.human_domain.empty() ? models.robot_domain
                                                     : pddl::parse_domain_file(flags.human_domain);
    models.robot_problem = pddl::parse_problem_file(flags.problem, models.robot_domain);
    const std::string &human = flags.human_problem.empty() ? flags.problem : flags.human_problem;
    models.human_problem =
        pddl::parse_problem_file(human, models.human_domain, models.robot_domain.name);
    return models;
}

std::string number(std::optional<double> value) { return client::json_number(value).dump(); }

std::string status_name(design::ExplicabilityStatus status) {
    switch (status) {
    case design::ExplicabilityStatus::SOLVED:
        return "solved";
    case design::ExplicabilityStatus::INEXPLICABLE:
        return "unsolvable";
    default:
        return "limit";
    }
}

// SPEC.md: {"status", "plan", "ie", "robot_cost", "human_plan_cost", "human_optimal_cost"}
nlohmann::json explicability_json(const design::TaskExplicability &r) {
    bool limit = r.status == design::ExplicabilityStatus::LIMIT;
    return {{"status", status_name(r.status)},
            {"plan", r.plan},
            {"ie", limit ? nlohmann::json() : client::json_number(r.ie)},
            {"robot_cost", client::json_number(r.robot_cost)},
            {"human_plan_cost", client::json_number(r.human_plan_cost)},
            {"human_optimal_cost", client::json_number(r.human_optimal_cost)}};
}

void print_text(const design::TaskExplicability &r) {
    for (const auto &step : r.plan)
        std::cout << step << "\n";
    std::cout << "; ie = " << number(r.ie) << ", robot cost = " << number(r.robot_cost)
              << ", human plan cost = " << number(r.human_plan_cost)
              << ", human optimal cost = " << number(r.human_optimal_cost) << "\n";
}

} // namespace

void add_explicable_flags(CLI::App &command, ExplicableFlags &flags) {
    command.add_option("--robot-domain", flags.robot_domain, "PDDL domain of the robot's model")
        ->required();
    command.add_option("--human-domain", flags.human_domain,
                       "PDDL domain of the human's model (default: the robot's)");
    command.add_option("--problem", flags.problem, "PDDL problem (the robot's)")->required();
    command.add_option("--human-problem", flags.human_problem,
                       "PDDL problem of the human's model (default: --problem)");
    command.add_option("--distance", flags.distance, "EXP_COST_DIFF | COST_DIFF")
        ->check(CLI::IsMember({"EXP_COST_DIFF", "COST_DIFF"}));
    command.add_option("--heuristic", flags.heuristic, "lmcut | hmax | blind")
        ->check(CLI::IsMember({"lmcut", "hmax", "blind"}));
    command.add_option("--time-limit", flags.time_limit_s, "seconds (0: none)")
        ->check(service::number_in(design::TIME_LIMIT_S));
    command.add_flag("--json", flags.json, "print a JSON result");
}

int run_explicable(const ExplicableFlags &flags) {
    design::ModelPair models;
    planning::PlannerOptions options;
    options.heuristic = heuristics::parse_heuristic_kind(flags.heuristic);
    design::PlanCache planner(options);
    // Bad input throws pddl::ParseError: main() reports it (exit 2).
    models = load_models(flags);
    auto distance = flags.distance == "COST_DIFF" ? design::Distance::COST_DIFF
                                                  : design::Distance::EXP_COST_DIFF;
    design::TaskExplicability result = design::evaluate_explicability(
        models, distance, planner, design::Deadline::in(flags.time_limit_s), true);
    if (flags.json)
        std::cout << client::json_text(explicability_json(result)) << std::endl;
    else
        print_text(result);
    switch (result.status) {
    case design::ExplicabilityStatus::SOLVED:
        return 0;
    case design::ExplicabilityStatus::INEXPLICABLE:
        return 3;
    default:
        return 4;
    }
}

} // namespace envdesign::cli
