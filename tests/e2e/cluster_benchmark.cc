// cluster_benchmark [SPEC] [--repeat N] [--jobs-per-slot K] [--auth]: evaluations per second and
// the time added per evaluation by the networked services (coordinator + 1 or 2 planner processes
// over udpm on loopback, one worker each) against the in-process evaluator with one worker, on a
// design problem with many cheap evaluations (default: tests/e2e/data/warehouse-small/signs-3).
// Not run by ctest: `build/bin/cluster_benchmark`. Targets (issue 5): under 1 ms added per
// evaluation; 2 planners at least 1.8 times 1.
// --auth: the cost of bus keys instead (issue 10): the same clusters without and with a key,
// runs alternating between the two; target under 5% fewer evaluations per second.

#include "local_cluster.h"

#include "bus/auth.h"
#include "bus/log.h"

#include "design/evaluation/local_evaluator.h"
#include "design/search/design_search.h"
#include "spec/design_spec.h"

#include <envdesign/client/client.h>

#include <algorithm>
#include <cstdio>

namespace envdesign::e2e {
namespace {

struct Run {
    double seconds = 0; // the search, as the result reports it
    long long evaluations = 0;
    double transport_seconds = 0; // LCM: round trips less planner time, summed
    double job_seconds = 0;       // LCM: planner wall time on jobs, summed
    double per_second() const { return evaluations / seconds; }
};

Run local_run(const std::string &spec, int workers) {
    design::DesignProblem problem = spec::load_design_problem(spec);
    design::LocalEvaluator evaluator(problem, workers);
    design::DesignSearchOptions options;
    options.max_design_size = problem.max_design_size;
    auto result = design::search_design(problem, evaluator, options);
    return {result.counters.seconds, result.counters.evaluator.task_evaluations};
}

// A copy of `spec` (beside its files, in a scratch directory) that differs in a comment:
// another content hash, so that planners cannot answer from the caches of an earlier run.
std::string fresh_copy(const std::string &spec) {
    static int run = 0;
    namespace fs = std::filesystem;
    fs::path dir = fs::temp_directory_path() / ("envdesign-bench-" + std::to_string(getpid()));
    if (run == 0) {
        fs::remove_all(dir);
        fs::copy(fs::path(spec).parent_path(), dir, fs::copy_options::recursive);
    }
    fs::path copy = dir / ("run-" + std::to_string(++run) + ".textproto");
    std::ifstream in(spec);
    std::ofstream out(copy);
    out << in.rdbuf() << "# run " << run << "\n";
    return copy.string();
}

Run remote_run(const std::string &spec, const std::string &url, const std::string &key = "") {
    client::Options options;
    options.key_file = key;
    client::Result r = client::run_design_remote(fresh_copy(spec), url, options);
    if (r.exit_code != 0) {
        std::fprintf(stderr, "remote run failed: %s\n", r.error.c_str());
        return {1e9, 0};
    }
    auto json = nlohmann::json::parse(r.json);
    return {json.at("seconds").get<double>(), json.at("task_evaluations").get<long long>(),
            json.at("cluster").at("transport_seconds").get<double>(),
            json.at("cluster").at("job_seconds").get<double>()};
}

// The run of median time among `repeat` runs.
template <typename F> Run median_of(int repeat, F run) {
    std::vector<Run> runs;
    for (int i = 0; i < repeat; ++i)
        runs.push_back(run());
    std::sort(runs.begin(), runs.end(),
              [](const Run &a, const Run &b) { return a.seconds < b.seconds; });
    return runs[runs.size() / 2];
}

int benchmark(const std::string &spec, int repeat, const std::string &jobs_per_slot) {
    std::printf("spec: %s, median of %d runs, %s job(s) in flight per planner\n", spec.c_str(),
                repeat, jobs_per_slot.c_str());
    Run local1 = median_of(repeat, [&] { return local_run(spec, 1); });
    Run local2 = median_of(repeat, [&] { return local_run(spec, 2); });
    Run remote[2];
    for (int planners = 1; planners <= 2; ++planners) {
        // No evaluations kept across requests: every run is the planners' work again.
        LocalCluster cluster(planners,
                             {"--jobs-per-slot", jobs_per_slot, "--stored-evaluations", "0"});
        remote_run(spec, cluster.url()); // warm-up: processes started, code paged in
        remote[planners - 1] = median_of(repeat, [&] { return remote_run(spec, cluster.url()); });
    }
    auto row = [](const char *name, const Run &r) {
        std::printf("%-32s %8lld evaluations %8.3f s %9.1f evaluations/s %8.3f ms/evaluation\n",
                    name, r.evaluations, r.seconds, r.per_second(),
                    1000 * r.seconds / r.evaluations);
    };
    row("in-process, 1 worker", local1);
    row("in-process, 2 workers", local2);
    row("LCM, coordinator + 1 planner", remote[0]);
    row("LCM, coordinator + 2 planners", remote[1]);
    double added_ms =
        1000 * (remote[0].seconds / remote[0].evaluations - local1.seconds / local1.evaluations);
    double speedup = remote[1].per_second() / remote[0].per_second();
    std::printf("added per evaluation over LCM (1 planner vs 1 worker): %.3f ms (target < 1)\n",
                added_ms);
    for (int p = 0; p < 2; ++p)
        std::printf("%d planner(s): round trip less planner time %.3f ms per evaluation; planners "
                    "busy %.0f%% of the wall time\n",
                    p + 1, 1000 * remote[p].transport_seconds / remote[p].evaluations,
                    100 * remote[p].job_seconds / ((p + 1) * remote[p].seconds));
    std::printf("2 planners / 1 planner: %.2fx (target >= 1.8); in-process 2/1 workers: %.2fx\n",
                speedup, local2.per_second() / local1.per_second());
    return added_ms < 1 && speedup >= 1.8 ? 0 : 1;
}

// The CPU cost of signing and of verifying one message of `size` bytes, in microseconds.
std::pair<double, double> sign_verify_us(std::size_t size) {
    bus::KeyRing ring;
    ring.keys.push_back({"bench", std::string(32, 'b')});
    bus::Signer signer(ring);
    bus::Verifier verifier(ring);
    bus::ReplayGuard guard;
    std::string payload(size, 'x');
    constexpr int N = 20000;
    std::vector<std::string> signed_messages;
    signed_messages.reserve(N);
    auto t0 = std::chrono::steady_clock::now();
    for (int i = 0; i < N; ++i)
        signed_messages.push_back(signer.sign(bus::JOB, payload.data(), payload.size()));
    auto t1 = std::chrono::steady_clock::now();
    int ok = 0;
    for (const auto &m : signed_messages)
        ok += verifier.verify(bus::JOB, m.data(), m.size(), guard, bus::now_utime()).ok();
    auto t2 = std::chrono::steady_clock::now();
    if (ok != N)
        std::fprintf(stderr, "only %d of %d verified\n", ok, N);
    auto us = [](auto d) { return std::chrono::duration<double, std::micro>(d).count() / N; };
    return {us(t1 - t0), us(t2 - t1)};
}

// Without and with a bus key, runs alternating so that both see the same machine load.
int auth_benchmark(const std::string &spec, int repeat, const std::string &jobs_per_slot) {
    std::string key = (std::filesystem::temp_directory_path() /
                       ("envdesign-bench-key-" + std::to_string(getpid())))
                          .string();
    std::ofstream(key) << "bench " << std::string(64, 'b') << "\n";
    std::filesystem::permissions(key, std::filesystem::perms::owner_read |
                                          std::filesystem::perms::owner_write);
    for (std::size_t size : {200, 2000, 32768}) {
        auto [sign, verify] = sign_verify_us(size);
        std::printf("a %zu-byte message: signing %.2f us, verifying %.2f us\n", size, sign, verify);
    }
    std::printf("spec: %s, median of %d runs each, alternating\n", spec.c_str(), repeat);
    double worst = 0;
    for (int planners = 1; planners <= 2; ++planners) {
        std::vector<std::string> flags = {"--jobs-per-slot", jobs_per_slot, "--stored-evaluations",
                                          "0"};
        LocalCluster plain(planners, flags);
        LocalCluster keyed(planners, flags, key);
        remote_run(spec, plain.url());
        remote_run(spec, keyed.url(), key);
        std::vector<Run> without, with;
        for (int i = 0; i < repeat; ++i) {
            without.push_back(remote_run(spec, plain.url()));
            with.push_back(remote_run(spec, keyed.url(), key));
        }
        Run a = median_of(repeat, [&, i = 0]() mutable { return without[i++]; });
        Run b = median_of(repeat, [&, i = 0]() mutable { return with[i++]; });
        double slower = 100 * (1 - b.per_second() / a.per_second());
        worst = std::max(worst, slower);
        std::printf("%d planner(s): without key %9.1f evaluations/s %7.3f ms/evaluation | with "
                    "key %9.1f evaluations/s %7.3f ms/evaluation | %+.3f ms/evaluation, %.1f%% "
                    "slower\n",
                    planners, a.per_second(), 1000 * a.seconds / a.evaluations, b.per_second(),
                    1000 * b.seconds / b.evaluations,
                    1000 * (b.seconds / b.evaluations - a.seconds / a.evaluations), slower);
    }
    std::filesystem::remove(key);
    std::printf("signing costs at most %.1f%% of evaluations per second (target < 5%%)\n", worst);
    return worst < 5 ? 0 : 1;
}

} // namespace
} // namespace envdesign::e2e

int main(int argc, char **argv) {
    std::string spec = envdesign::e2e::source("tests/e2e/data/warehouse-small/signs-3.textproto");
    int repeat = 5;
    std::string jobs_per_slot = "2";
    bool auth = false;
    for (int i = 1; i < argc; ++i) {
        std::string a = argv[i];
        if (a == "--auth")
            auth = true;
        else if (a == "--repeat" && i + 1 < argc)
            repeat = std::max(1, std::atoi(argv[++i]));
        else if (a == "--jobs-per-slot" && i + 1 < argc)
            jobs_per_slot = argv[++i];
        else
            spec = a;
    }
    int code = auth ? envdesign::e2e::auth_benchmark(spec, repeat, jobs_per_slot)
                    : envdesign::e2e::benchmark(spec, repeat, jobs_per_slot);
    std::filesystem::remove_all(std::filesystem::temp_directory_path() /
                                ("envdesign-bench-" + std::to_string(getpid())));
    return code;
}
