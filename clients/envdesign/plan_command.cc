#include "plan_command.h"

#include "output_file.h"

#include "pddl/parse_error.h"
#include "planning/planner.h"
#include "result_format.h"
#include "service/number_flag.h"

#include <nlohmann/json.hpp>
#include <spdlog/spdlog.h>

#include <iostream>
#include <sstream>

namespace envdesign::cli {
namespace {

// --memory-limit in MiB: up to 1e9 MiB (about 1 PB), whose bytes a size_t holds exactly
// (docs/numbers.md); 0: no limit.
constexpr design::NumberRange MEMORY_LIMIT_MIB{0, 1e9};

std::string status_name(search::SearchStatus status) {
    switch (status) {
    case search::SearchStatus::SOLVED:
        return "solved";
    case search::SearchStatus::FAILED:
        return "unsolvable";
    default:
        return "limit";
    }
}

int exit_code(search::SearchStatus status) {
    switch (status) {
    case search::SearchStatus::SOLVED:
        return 0;
    case search::SearchStatus::FAILED:
        return 3;
    default:
        return 4;
    }
}

std::string sas_plan(const planning::PlanReport &report) {
    std::ostringstream out;
    for (const auto &step : report.plan)
        out << step << "\n";
    out << "; cost = " << report.cost << (report.unit_cost ? " (unit cost)" : " (general cost)")
        << "\n";
    return out.str();
}

void log_statistics(const planning::PlanReport &report) {
    const auto &s = report.statistics;
    spdlog::info("task: {} facts, {} operators; bytes per state: {}", report.facts,
                 report.operators, s.bytes_per_state);
    spdlog::info("search: {} expanded, {} generated, {} evaluated, {} reopened", s.expanded,
                 s.generated, s.evaluated, s.reopened);
    spdlog::info("time: parse {:.4f}s, ground {:.4f}s, search {:.4f}s, total {:.4f}s",
                 report.parse_seconds, report.ground_seconds, report.search_seconds,
                 report.total_seconds);
}

void print_json(const planning::PlanReport &report) {
    nlohmann::json out = {{"status", status_name(report.status)},
                          {"plan", report.plan},
                          {"cost", report.cost},
                          {"expansions", report.statistics.expanded},
                          {"generated", report.statistics.generated},
                          {"seconds", report.total_seconds},
                          // Beyond SPEC.md's keys, for the benchmark: where the time went.
                          {"parse_ground_seconds", report.parse_seconds + report.ground_seconds},
                          {"search_seconds", report.search_seconds},
                          {"bytes_per_state", report.statistics.bytes_per_state}};
    if (report.status != search::SearchStatus::SOLVED)
        out["cost"] = nullptr;
    std::cout << client::json_text(out) << std::endl;
}

} // namespace

void add_plan_flags(CLI::App &command, PlanFlags &flags) {
    command.add_option("domain", flags.domain, "PDDL domain file")->required();
    command.add_option("problem", flags.problem, "PDDL problem file")->required();
    command.add_option("--heuristic", flags.heuristic, "lmcut | hmax | blind")
        ->check(CLI::IsMember({"lmcut", "hmax", "blind"}));
    command.add_option("--time-limit", flags.time_limit_s, "seconds (0: none)")
        ->check(service::number_in(design::TIME_LIMIT_S));
    command.add_option("--memory-limit", flags.memory_limit_mb, "MiB (0: none)")
        ->check(service::number_in(MEMORY_LIMIT_MIB));
    command.add_option("--plan-file", flags.plan_file, "also write the plan to this file");
    command.add_flag("--json", flags.json, "print a JSON result instead of the plan");
}

int run_plan(const PlanFlags &flags) {
    planning::PlannerOptions options;
    options.heuristic = heuristics::parse_heuristic_kind(flags.heuristic);
    options.limits.time_limit_s = flags.time_limit_s;
    options.limits.memory_limit_bytes =
        static_cast<std::size_t>(flags.memory_limit_mb * 1024 * 1024);
    if (!flags.plan_file.empty())
        check_output_path(flags.plan_file);
    // Bad input throws pddl::ParseError: main() reports it (exit 2).
    planning::PlanReport report = planning::plan_files(flags.domain, flags.problem, options);
    log_statistics(report);
    if (report.status == search::SearchStatus::FAILED)
        spdlog::info("proven unsolvable");
    else if (report.status != search::SearchStatus::SOLVED)
        spdlog::warn("stopped at the time or memory limit");
    if (flags.json)
        print_json(report);
    else if (report.status == search::SearchStatus::SOLVED)
        std::cout << sas_plan(report);
    if (!flags.plan_file.empty() && report.status == search::SearchStatus::SOLVED) {
        write_output_file(flags.plan_file, sas_plan(report));
    }
    return exit_code(report.status);
}

} // namespace envdesign::cli
