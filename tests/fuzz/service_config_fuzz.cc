// Service config files (issue 21): the input is a --config FILE's bytes, read by
// service::read_config_file and turned into flags by services::parse_command_line, as the
// coordinator's and planner's mains do, with their number flags and checks (the lists in
// services/coordinator/main.cc and services/planner/main.cc; this target declares the same
// options with the same validators). Either the file is refused (ConfigError, exit 2) or
// every value that comes out is finite and in its range; never a crash. The first byte, when
// odd, also puts --max-requests=7 on the command line, which must win over the file.

#include "cluster/planner_pool.h"
#include "cluster/spec_chunks.h"
#include "design/model/numbers.h"
#include "service/config_file.h"
#include "service/number_flag.h"
#include "service_main.h"

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <set>
#include <string>
#include <unistd.h>
#include <vector>

namespace {

using namespace envdesign;

struct Values {
    services::CommonFlags common;
    int max_requests = 64, max_waiting = 64, max_per_client = 8, jobs_per_slot = 2;
    int workers = 1, max_specs = 16, remembered_answers = 1000;
    std::size_t max_spec_bytes = 1 << 20, state_max_mb = 1024, job_memory_mb = 512;
    double planner_timeout_s = 1, lost_after_s = 0.3, job_deadline_s = 5, discovery_s = 1.5;
    double takeover_after_s = 3, max_time_limit_s = 3600, client_timeout_s = 10;
    double heartbeat_s = 0.2;
    bool state_fsync = false;
};

void declare(CLI::App &app, Values &v) {
    using service::number_in;
    services::add_common_flags(app, v.common);
    app.set_version_flag("--version", "fuzz");
    app.add_option("--max-requests", v.max_requests)->check(CLI::Range(1, 1000));
    app.add_option("--max-waiting", v.max_waiting)->check(CLI::Range(0, 100000));
    app.add_option("--max-per-client", v.max_per_client)->check(CLI::Range(1, 100000));
    app.add_option("--max-spec-bytes", v.max_spec_bytes)
        ->check(CLI::Range(std::size_t{1}, cluster::MAX_SPEC_BYTES_LIMIT));
    app.add_option("--planner-timeout", v.planner_timeout_s)
        ->check(number_in(service::POSITIVE_SECONDS));
    app.add_option("--lost-after", v.lost_after_s)->check(number_in(service::POSITIVE_SECONDS));
    app.add_option("--job-deadline", v.job_deadline_s)->check(number_in(service::POSITIVE_SECONDS));
    app.add_option("--jobs-per-slot", v.jobs_per_slot)->check(CLI::Range(1, 64));
    app.add_option("--state-max-mb", v.state_max_mb)->check(CLI::Range(1, 1 << 20));
    app.add_flag("--state-fsync", v.state_fsync);
    app.add_option("--discovery", v.discovery_s)->check(number_in({0.0, 60.0}));
    app.add_option("--takeover-after", v.takeover_after_s)->check(number_in({1.5, 3600.0}));
    app.add_option("--max-time-limit", v.max_time_limit_s)
        ->check(number_in({1, design::TIME_LIMIT_S.high}));
    app.add_option("--client-timeout", v.client_timeout_s)
        ->check(number_in({3, design::TIME_LIMIT_S.high}));
    // The planner's.
    app.add_option("--workers", v.workers)->check(CLI::Range(1, 256));
    app.add_option("--heartbeat", v.heartbeat_s)->check(number_in(cluster::HEARTBEAT_PERIOD_S));
    app.add_option("--max-specs", v.max_specs)->check(CLI::Range(1, 1000));
    app.add_option("--remembered-answers", v.remembered_answers)->check(CLI::Range(0, 10'000'000));
    app.add_option("--job-memory-mb", v.job_memory_mb)->check(CLI::Range(16, 1 << 20));
}

bool in(double value, double low, double high) {
    return std::isfinite(value) && value >= low && value <= high;
}

bool sound(const Values &v) {
    static const std::set<std::string> LEVELS = {"trace", "debug",    "info", "warn",
                                                 "error", "critical", "off"};
    const double top = design::TIME_LIMIT_S.high, least = service::POSITIVE_SECONDS.low;
    return LEVELS.count(v.common.log_level) && !v.common.check_config &&
           in(v.max_requests, 1, 1000) && in(v.max_waiting, 0, 100000) &&
           in(v.max_per_client, 1, 100000) && v.max_spec_bytes >= 1 &&
           v.max_spec_bytes <= cluster::MAX_SPEC_BYTES_LIMIT &&
           in(v.planner_timeout_s, least, top) && in(v.lost_after_s, least, top) &&
           in(v.job_deadline_s, least, top) && in(v.jobs_per_slot, 1, 64) && v.state_max_mb >= 1 &&
           v.state_max_mb <= (1u << 20) && in(v.discovery_s, 0, 60) &&
           in(v.takeover_after_s, 1.5, 3600) && in(v.max_time_limit_s, 1, top) &&
           in(v.client_timeout_s, 3, top) && in(v.workers, 1, 256) &&
           in(v.heartbeat_s, cluster::HEARTBEAT_PERIOD_S.low, cluster::HEARTBEAT_PERIOD_S.high) &&
           in(v.max_specs, 1, 1000) && in(v.remembered_answers, 0, 10'000'000) &&
           v.job_memory_mb >= 16 && v.job_memory_mb <= (1u << 20);
}

std::string config_path() {
    static const std::string path =
        "/tmp/envdesign-fuzz-config-" + std::to_string(getpid()) + ".conf";
    return path;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
    if (size < 1 || size > 4096)
        return 0;
    bool override = data[0] % 2 == 1;
    std::string path = config_path();
    std::ofstream(path, std::ios::binary | std::ios::trunc)
        .write(reinterpret_cast<const char *>(data) + 1, static_cast<std::streamsize>(size - 1));

    // The reader alone: settings are named by key characters, with places inside the file.
    bool read = true;
    try {
        int previous_line = 0;
        for (const service::ConfigSetting &s : service::read_config_file(path)) {
            if (s.key.empty() || s.line <= previous_line || s.key_column < 1 ||
                s.key.find_first_not_of("abcdefghijklmnopqrstuvwxyz0123456789-_") !=
                    std::string::npos)
                std::abort();
            previous_line = s.line;
        }
    } catch (const service::ConfigError &) {
        read = false;
    }

    // The mains' path: its messages go nowhere (the fuzzer's output stays readable).
    Values values;
    CLI::App app{"fuzz"};
    declare(app, values);
    std::vector<std::string> args = {"envdesign-fuzz", "--config", path};
    if (override)
        args.push_back("--max-requests=7");
    std::vector<char *> argv;
    for (auto &a : args)
        argv.push_back(a.data());
    std::streambuf *err = std::cerr.rdbuf(nullptr), *out = std::cout.rdbuf(nullptr);
    std::optional<int> code =
        services::parse_command_line(app, static_cast<int>(argv.size()), argv.data());
    std::cerr.rdbuf(err);
    std::cout.rdbuf(out);
    std::cerr.clear();
    std::cout.clear();
    if (code) {
        if (*code != 2) // no --help, --version or --check-config can come from a file
            std::abort();
        return 0;
    }
    if (!read || !sound(values) || (override && values.max_requests != 7))
        std::abort();
    return 0;
}
