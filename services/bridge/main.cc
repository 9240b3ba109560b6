// envdesign-bridge: task arrivals from DDS in, task distribution estimates and
// re-evaluations out on LCM (README.md; common/bridge/bridge.h has the overview).

#include "bridge/bridge.h"
#include "bus/status.h"
#include "dds/arrival_topic.h"
#include "pddl/parse_error.h"
#include "service/number_flag.h"
#include "service_main.h"
#include "spec/design_spec.h"
#include "store/state_dir.h"

#include <envdesign/version.h>

#include <iostream>

namespace {

using namespace envdesign;

// --min-samples (effective samples) and --holdoff (arrivals): a count of evidence, at most a
// million; more would wait forever (docs/numbers.md).
constexpr design::NumberRange EVIDENCE{0, 1e6};

struct Flags {
    std::vector<std::string> problems; // ID=SPEC
    std::string mode = "local", estimator = "window:200", heuristic = "lmcut";
    std::string state_dir;
    int domain = 0;                           // DDS domain id
    int reader_history = dds::READER_HISTORY; // per (problem, site)
};

void add_flags(CLI::App &app, Flags &f, bridge::BridgeConfig &c) {
    auto &drift = c.tracker.drift;
    auto &intake = c.tracker.intake;
    app.add_option("--problem", f.problems, "ID=SPEC: track design problem ID (repeatable)")
        ->required();
    app.add_option("--redesign", f.mode,
                   "local: re-evaluate in this process; coordinator: "
                   "ask envdesign-coordinator")
        ->check(CLI::IsMember({"local", "coordinator"}))
        ->capture_default_str();
    app.add_option("--domain", f.domain, "DDS domain id")->check(CLI::Range(0, 230));
    app.add_option("--estimator", f.estimator,
                   "window:N (last N arrivals) or decay:H "
                   "(half-life H arrivals)")
        ->capture_default_str();
    app.add_option("--threshold", drift.threshold, "TV distance that asks for a re-evaluation")
        ->check(service::number_in({0.0, 1.0}))
        ->capture_default_str();
    app.add_option("--rearm", drift.rearm_threshold, "TV below which the detector re-arms")
        ->check(service::number_in({0.0, 1.0}))
        ->capture_default_str();
    app.add_option("--min-samples", drift.min_samples, "evidence needed before a request")
        ->check(service::number_in(EVIDENCE))
        ->capture_default_str();
    app.add_option("--holdoff", drift.holdoff_arrivals, "arrivals between two requests")
        ->check(service::number_in(EVIDENCE))
        ->capture_default_str();
    app.add_option("--answer-timeout", drift.answer_timeout_s, "seconds to wait for a design")
        ->check(service::number_in(service::POSITIVE_SECONDS))
        ->capture_default_str();
    app.add_option("--resend-after", c.coordinator.resend_after_s,
                   "coordinator: send a request again after this long without word of it (s)")
        ->check(service::number_in(service::POSITIVE_SECONDS))
        ->capture_default_str();
    app.add_option("--max-rate", intake.max_rate, "arrivals/s per site (0: no limit)")
        ->check(service::number_in({0, 1e6}))
        ->capture_default_str();
    app.add_option("--burst", intake.burst, "burst allowed above --max-rate")
        ->check(service::number_in({0, 1e6}))
        ->capture_default_str();
    app.add_option("--max-future", intake.max_future_s,
                   "seconds ahead beyond which a timestamp counts as clock skew")
        ->check(service::number_in(design::TIME_LIMIT_S))
        ->capture_default_str();
    app.add_option("--max-age", intake.max_age_s, "seconds a timestamp may be behind or ahead")
        ->check(service::number_in(design::TIME_LIMIT_S))
        ->capture_default_str();
    app.add_option("--max-new-tasks", c.tracker.max_new_tasks,
                   "new tasks (arrivals carrying their problem) taken in per problem, in all")
        ->check(CLI::Range(0, 100000))
        ->capture_default_str();
    app.add_option("--new-task-interval", c.tracker.new_task_interval_s,
                   "seconds per new task taken in per problem, beyond --new-task-burst")
        ->check(service::number_in(design::TIME_LIMIT_S))
        ->capture_default_str();
    app.add_option("--new-task-burst", c.tracker.new_task_burst,
                   "new tasks taken in at once per problem")
        ->check(service::number_in({1, 1e5}))
        ->capture_default_str();
    app.add_option("--reweigh-interval", c.tracker.reweigh_interval_s,
                   "local: re-weigh stored evaluations at most this often (s; 0: never)")
        ->check(service::number_in(design::TIME_LIMIT_S))
        ->capture_default_str();
    app.add_option("--publish-hz", c.publish_hz, "estimates per problem per second, at most")
        ->check(service::number_in({1e-3, 1e3}))
        ->capture_default_str();
    app.add_option("--reader-history", f.reader_history, "DDS reader depth per site")
        ->check(CLI::PositiveNumber)
        ->capture_default_str();
    app.add_option("--workers", c.local.workers, "planner threads (--redesign local)")
        ->check(CLI::Range(1, 256));
    app.add_option("--heuristic", f.heuristic, "lmcut | hmax | blind")
        ->check(CLI::IsMember({"lmcut", "hmax", "blind"}));
    app.add_option("--state-dir", f.state_dir,
                   "keep evaluations in DIR/evaluations.db across restarts (--redesign local)")
        ->check(CLI::ExistingDirectory);
    app.add_option("--time-limit", c.local.time_limit_s,
                   "seconds per re-evaluation (default: the spec's)")
        ->check(service::number_in(design::TIME_LIMIT_S));
}

// Flags -> config; throws CLI::ValidationError for a bad --problem or --estimator.
void finish_config(const Flags &f, bridge::BridgeConfig &c) {
    for (const auto &p : f.problems) {
        auto eq = p.find('=');
        if (eq == std::string::npos || eq == 0 || eq + 1 == p.size())
            throw CLI::ValidationError("--problem", "expected ID=SPEC, got '" + p + "'");
        c.problems.push_back({p.substr(0, eq), p.substr(eq + 1)});
    }
    try {
        c.tracker.estimator = arrivals::parse_estimator_config(f.estimator);
    } catch (const std::invalid_argument &e) {
        throw CLI::ValidationError("--estimator", e.what());
    }
    if (c.tracker.drift.rearm_threshold > c.tracker.drift.threshold)
        throw CLI::ValidationError("--rearm", "must not exceed --threshold");
    c.mode = f.mode == "local" ? bridge::Mode::LOCAL : bridge::Mode::COORDINATOR;
    c.local.planner.heuristic = heuristics::parse_heuristic_kind(f.heuristic);
    c.coordinator.heuristic = static_cast<std::int8_t>(f.heuristic == "hmax"    ? 1
                                                       : f.heuristic == "blind" ? 2
                                                                                : 0);
    c.coordinator.time_limit_s = c.local.time_limit_s;
}

// What start-up would fail on (--check-config): a --problem spec that does not load, a
// --state-dir that cannot be opened.
std::optional<std::string> bridge_startup_problem(const Flags &f, const bridge::BridgeConfig &c) {
    for (const auto &source : c.problems) {
        try {
            spec::load_design_problem(source.spec_path);
        } catch (const pddl::ParseError &e) {
            return "--problem " + source.id + ": " + e.what();
        }
    }
    if (auto why = store::state_dir_problem(f.state_dir))
        return "--state-dir: " + *why;
    return std::nullopt;
}

// The bridge's part of its status: re-evaluations awaited, every arrival its intake
// rejected, by verdict, and the new tasks held back beyond --max-new-tasks or their rate.
void fill_status(const bridge::BridgeStats &stats, envdesign::service_status_t &status) {
    status.requests_open = static_cast<std::int32_t>(stats.requests - stats.answers);
    for (int v = 0; v < arrivals::VERDICTS; ++v) {
        auto verdict = static_cast<arrivals::Verdict>(v);
        if (verdict != arrivals::Verdict::ACCEPTED && stats.intake.count(verdict) > 0)
            bus::add_drop(status, "dds:arrivals", arrivals::to_string(verdict),
                          stats.intake.count(verdict));
    }
    if (stats.new_tasks_held_back > 0)
        bus::add_drop(status, "dds:arrivals", "new_task_held_back", stats.new_tasks_held_back);
}

} // namespace

int main(int argc, char **argv) {
    CLI::App app{"envdesign-bridge: task arrivals (DDS) -> task distribution and designs (LCM)"};
    services::CommonFlags common;
    services::add_common_flags(app, common);
    app.set_version_flag("--version", version_line("envdesign-bridge"));
    Flags flags;
    bridge::BridgeConfig config;
    add_flags(app, flags, config);
    if (auto code = services::parse_command_line(
            app, argc, argv, [&] { finish_config(flags, config); },
            [&] { return bridge_startup_problem(flags, config); }))
        return *code;
    return services::serve("bridge", common, [&](services::Service &service) {
        config.instance = service.instance;
        if (!dds::security_configured())
            service.log->warn(
                "request - | DDS Security is off (CYCLONEDDS_URI configures no <Security>): "
                "anyone on DDS domain {} can publish arrivals and new tasks (taken in: at most "
                "{} per problem, {} at once, then one per {} s); see deploy/LAN.md",
                flags.domain, config.tracker.max_new_tasks, config.tracker.new_task_burst,
                config.tracker.new_task_interval_s);
        if (config.mode == bridge::Mode::LOCAL) {
            store::RecordDbOptions options;
            options.sync = false; // survives a killed bridge; --state-fsync is the coordinator's
            config.local.evaluations =
                store::open_state_file(flags.state_dir, options, *service.log);
        }
        try {
            dds::ArrivalReader reader(flags.domain, flags.reader_history);
            bridge::SystemClock clock;
            bridge::Bridge bridge(*service.bus, config, reader, clock);
            bus::StatusPublisher status(*service.bus, "bridge", service.instance);
            return services::run_until_signal(service, [&] {
                bridge.tick();
                status.tick(
                    [&](envdesign::service_status_t &s) { fill_status(bridge.stats(), s); });
            });
        } catch (const pddl::ParseError &e) { // a --problem spec that does not load
            std::cerr << e.what() << std::endl;
            return 2;
        }
    });
}
