// envdesign-coordinator: the design search as a service (README.md).

#include "cluster/coordinator.h"
#include "service/number_flag.h"
#include "service_main.h"
#include "store/state_dir.h"

#include <envdesign/version.h>

int main(int argc, char **argv) {
    using namespace envdesign;
    CLI::App app{"envdesign-coordinator: design requests in, progress and results out"};
    services::CommonFlags common;
    services::add_common_flags(app, common);
    app.set_version_flag("--version", version_line("envdesign-coordinator"));
    cluster::CoordinatorConfig config;
    app.add_option("--max-requests", config.max_active, "requests searched at once")
        ->check(CLI::Range(1, 1000))
        ->capture_default_str();
    app.add_option("--max-waiting", config.max_waiting,
                   "requests waiting for a search slot; beyond that new ones are answered busy")
        ->check(CLI::Range(0, 100000))
        ->capture_default_str();
    app.add_option("--max-per-client", config.max_per_client,
                   "requests searching or waiting per client; beyond that busy")
        ->check(CLI::Range(1, 100000))
        ->capture_default_str();
    app.add_option("--max-spec-bytes", config.max_spec_bytes,
                   "largest spec (text and files) a request may carry")
        ->check(CLI::Range(std::size_t{1}, cluster::MAX_SPEC_BYTES_LIMIT))
        ->capture_default_str();
    app.add_option("--planner-timeout", config.pool.planner_timeout_s,
                   "seconds of silence after which a planner is gone")
        ->check(service::number_in(service::POSITIVE_SECONDS))
        ->capture_default_str();
    app.add_option("--lost-after", config.pool.lost_after_s,
                   "seconds after which a job its planner does not list is sent again")
        ->check(service::number_in(service::POSITIVE_SECONDS))
        ->capture_default_str();
    app.add_option("--job-deadline", config.pool.job_deadline_s,
                   "least seconds a planner may hold a job before it goes to another (grows to "
                   "4x the slowest answer); planners that miss deadlines are demoted")
        ->check(service::number_in(service::POSITIVE_SECONDS))
        ->capture_default_str();
    app.add_option("--jobs-per-slot", config.pool.jobs_per_slot,
                   "jobs in flight per planner worker")
        ->check(CLI::Range(1, 64))
        ->capture_default_str();
    app.add_option("--stored-evaluations", config.stored_evaluations,
                   "task evaluations kept across requests (re-weighted when only the task "
                   "distribution or weights change; 0: none)")
        ->capture_default_str();
    app.add_option("--state-dir", config.state_dir,
                   "keep the stored evaluations in DIR/evaluations.db across restarts "
                   "(default: in memory only)")
        ->check(CLI::ExistingDirectory);
    std::size_t state_max_mb = config.state_max_bytes >> 20;
    app.add_option("--state-max-mb", state_max_mb,
                   "bound on the evaluation file's records, in MiB (least recently used go)")
        ->check(CLI::Range(1, 1 << 20))
        ->capture_default_str();
    app.add_flag("--state-fsync", config.state_sync,
                 "fsync the evaluation file at every record (survives power loss, not only a "
                 "killed process; slower)");
    config.election.discovery_s = 1.5; // hear the other coordinators' statuses (1 Hz) first
    app.add_option("--discovery", config.election.discovery_s,
                   "seconds after start spent listening for other coordinators before "
                   "running requests")
        ->check(service::number_in({0.0, 60.0}))
        ->capture_default_str();
    app.add_option("--takeover-after", config.election.takeover_after_s,
                   "standby: seconds of silence from the active coordinator before taking over")
        ->check(service::number_in({1.5, 3600.0}))
        ->capture_default_str();
    app.add_option("--max-time-limit", config.max_time_limit_s,
                   "seconds any request may search at most, its own limit when smaller (a "
                   "request without a limit gets this one)")
        ->check(service::number_in({1, design::TIME_LIMIT_S.high}))
        ->capture_default_str();
    app.add_option("--client-timeout", config.client_timeout_s,
                   "seconds without a keepalive or repeat from a request's client after which "
                   "the request is dropped (clients send one every 2 s)")
        ->check(service::number_in({3, design::TIME_LIMIT_S.high}))
        ->capture_default_str();
    auto startup = [&]() -> std::optional<std::string> {
        if (auto why = store::state_dir_problem(config.state_dir))
            return "--state-dir: " + *why;
        return std::nullopt;
    };
    if (auto code = services::parse_command_line(app, argc, argv, {}, startup))
        return *code;
    config.state_max_bytes = state_max_mb << 20;
    return services::serve("coordinator", common, [&](services::Service &service) {
        config.instance = service.instance;
        if (service.keys) // the stored records are tagged with the bus keys
            for (const bus::Key &key : service.keys->keys)
                config.state_secrets.push_back(key.secret);
        cluster::Coordinator coordinator(*service.bus, config);
        return services::run_until_signal(service,
                                          std::function<int()>([&] { return coordinator.tick(); }));
    });
}
