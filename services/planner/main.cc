// envdesign-planner: evaluates candidate designs for coordinators (README.md).

#include "cluster/planner.h"
#include "cluster/planner_pool.h"
#include "service/number_flag.h"
#include "service_main.h"

#include <envdesign/version.h>

int main(int argc, char **argv) {
    using namespace envdesign;
    CLI::App app{"envdesign-planner: jobs in, evaluations out"};
    services::CommonFlags common;
    services::add_common_flags(app, common);
    app.set_version_flag("--version", version_line("envdesign-planner"));
    cluster::PlannerConfig config;
    app.add_option("--workers", config.workers, "jobs worked on at once (threads)")
        ->check(CLI::Range(1, 256))
        ->capture_default_str();
    app.add_option("--heartbeat", config.heartbeat_period_s, "seconds between heartbeats")
        ->check(service::number_in(cluster::HEARTBEAT_PERIOD_S))
        ->capture_default_str();
    app.add_option("--max-specs", config.max_specs, "specs kept loaded")
        ->check(CLI::Range(1, 1000))
        ->capture_default_str();
    app.add_option("--remembered-answers", config.remembered_answers,
                   "answers remembered by content, for any coordinator's jobs (0: none)")
        ->check(CLI::Range(0, 10'000'000))
        ->capture_default_str();
    app.add_option("--max-spec-bytes", config.spec_limits.max_spec_bytes,
                   "largest spec encoding taken from the bus (chunks of larger ones are dropped)")
        ->check(CLI::Range(std::size_t{1}, cluster::MAX_SPEC_BYTES_LIMIT))
        ->capture_default_str();
    std::size_t job_memory_mb = config.job_memory_bytes >> 20;
    app.add_option("--job-memory-mb", job_memory_mb,
                   "the planner's resident memory stays under --workers x this, in MiB: a "
                   "job's search gets this less its share of the process (beyond it the job "
                   "is answered as out of limits)")
        ->check(CLI::Range(16, 1 << 20))
        ->capture_default_str();
    if (auto code = services::parse_command_line(app, argc, argv))
        return *code;
    config.job_memory_bytes = job_memory_mb << 20;
    return services::serve("planner", common, [&](services::Service &service) {
        config.instance = service.instance;
        cluster::Planner planner(*service.bus, config);
        int code = services::run_until_signal(service, [&] { planner.tick(); });
        planner.stop(); // coordinators move its jobs at once; running searches stop
        return code;
    });
}
