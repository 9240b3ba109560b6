// envdesign: the command line. Each subcommand's flags and logic live in its own file;
// this file only wires them up and maps failures to the exit codes of SPEC.md.

#include "cli_error.h"
#include "design_command.h"
#include "evaluate_command.h"
#include "explicable_command.h"
#include "floor_command.h"
#include "plan_command.h"
#include "report_command.h"
#include "status_command.h"
#include "validate_command.h"
#include "watch_command.h"

#include <CLI/CLI.hpp>
#include <envdesign/version.h>
#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>

#include <cerrno>
#include <cstring>
#include <iostream>
#include <new>

namespace {

void set_up_logging(const std::string &level) {
    auto logger = spdlog::stderr_color_mt("envdesign");
    logger->set_pattern("[%H:%M:%S.%e] [%^%l%$] %v");
    logger->set_level(spdlog::level::from_str(level));
    spdlog::set_default_logger(logger);
}

// Output that did not reach standard output (a full disk) is a failure, whatever the command
// found: exit 1 with a message instead of 0.
int with_output_checked(int code) {
    errno = 0;
    std::cout.flush();
    if (std::cout)
        return code;
    spdlog::error("cannot write to standard output{}",
                  errno ? std::string(": ") + std::strerror(errno) : std::string());
    return 1;
}

} // namespace

int main(int argc, char **argv) {
    CLI::App app{"envdesign: environment design for explicable robot behaviour", "envdesign"};
    app.require_subcommand(1);
    app.set_version_flag("--version", envdesign::version_line("envdesign"));
    // Subcommands inherit this: a flag of the app (--log-level) may come after the subcommand.
    app.fallthrough();
    const bool json = envdesign::cli::json_requested(argc, argv);
    std::string log_level = "info";
    app.add_option("--log-level", log_level, "trace|debug|info|warn|error|off")
        ->check(CLI::IsMember({"trace", "debug", "info", "warn", "error", "critical", "off"}))
        ->capture_default_str();

    envdesign::cli::PlanFlags plan_flags;
    auto *plan = app.add_subcommand("plan", "optimal plan of a PDDL problem (A*)");
    envdesign::cli::add_plan_flags(*plan, plan_flags);
    plan->fallthrough();

    envdesign::cli::ValidateFlags validate_flags;
    auto *validate = app.add_subcommand("validate", "check a plan against a PDDL problem");
    envdesign::cli::add_validate_flags(*validate, validate_flags);

    envdesign::cli::ExplicableFlags explicable_flags;
    auto *explicable =
        app.add_subcommand("explicable", "most explicable plan of a robot/human pair");
    envdesign::cli::add_explicable_flags(*explicable, explicable_flags);

    envdesign::cli::DesignFlags design_flags;
    auto *design = app.add_subcommand("design", "optimal environment design of a design problem");
    envdesign::cli::add_design_flags(*design, design_flags);

    envdesign::cli::EvaluateFlags evaluate_flags;
    auto *evaluate =
        app.add_subcommand("evaluate", "a proposed design, explained as `design` does");
    envdesign::cli::add_evaluate_flags(*evaluate, evaluate_flags);

    envdesign::cli::ReportFlags report_flags;
    auto *report =
        app.add_subcommand("report", "an HTML page of the design (plots, plans, ranking)");
    envdesign::cli::add_report_flags(*report, report_flags);

    envdesign::cli::StatusFlags status_flags;
    auto *status =
        app.add_subcommand("status", "the services on a bus (coordinator, planners, bridges)");
    envdesign::cli::add_status_flags(*status, status_flags);

    envdesign::cli::WatchFlags watch_flags;
    auto *watch = app.add_subcommand(
        "watch", "print results, progress and task distribution estimates on a bus as they pass");
    envdesign::cli::add_watch_flags(*watch, watch_flags);

    envdesign::cli::FloorFlags floor_flags;
    auto *floor = app.add_subcommand("floor", "fleet maps -> design problems (docs/floors.md)");
    envdesign::cli::add_floor_flags(*floor, floor_flags);

    try {
        app.parse(argc, argv);
    } catch (const CLI::CallForHelp &e) {
        return app.exit(e);
    } catch (const CLI::ParseError &e) {
        if (e.get_exit_code() == 0) // --version
            return app.exit(e);
        app.exit(e);
        if (json)
            envdesign::cli::print_error_json(2, e.what());
        return 2;
    }
    set_up_logging(log_level);
    try {
        if (*plan)
            return with_output_checked(envdesign::cli::run_plan(plan_flags));
        if (*validate)
            return with_output_checked(envdesign::cli::run_validate(validate_flags));
        if (*explicable)
            return with_output_checked(envdesign::cli::run_explicable(explicable_flags));
        if (*design)
            return with_output_checked(envdesign::cli::run_design(design_flags));
        if (*evaluate)
            return with_output_checked(envdesign::cli::run_evaluate(evaluate_flags));
        if (*report)
            return with_output_checked(envdesign::cli::run_report(report_flags));
        if (*status)
            return with_output_checked(envdesign::cli::run_status(status_flags));
        if (*watch)
            return with_output_checked(envdesign::cli::run_watch(watch_flags));
        if (*floor)
            return with_output_checked(envdesign::cli::run_floor(floor_flags));
    } catch (const envdesign::pddl::ParseError &e) {
        return envdesign::cli::report_failure(json, 2, e.message(), e.location());
    } catch (const envdesign::cli::CommandError &e) {
        return envdesign::cli::report_failure(json, e.exit_code(), e.what());
    } catch (const std::bad_alloc &) {
        return envdesign::cli::report_failure(json, 4, "out of memory");
    } catch (const std::exception &e) {
        return envdesign::cli::report_failure(json, 1, e.what());
    }
    return 1;
}
