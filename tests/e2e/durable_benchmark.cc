// Not a test (issue 11, "Must show"): the coordinator SIGKILLed at random instants of a
// ~700-job search (paper Blocksworld 16, T=10) with --state-dir and 2 planners; each time
// the final design must be the undisturbed one, and the jobs the planners did before the
// kill plus the jobs the restarted coordinator sent must not exceed the undisturbed count
// plus the jobs in flight at the kill (counted from the planners' heartbeats). After each, a
// clean restart and a repeat must send 0 jobs.
//
//   build/bin/durable_benchmark [--kills 10] [--seed S] [--spec FILE] [--markdown OUT.md]

#include "local_cluster.h"

#include <iomanip>
#include <iostream>
#include <random>

namespace fs = std::filesystem;
using namespace envdesign::e2e;

namespace {

struct Options {
    int kills = 10;
    unsigned seed = std::random_device{}();
    std::string spec = source("tests/data/paper/blocksworld/16/design-t10.textproto");
    std::string markdown;
};

Options parse(int argc, char **argv) {
    Options o;
    for (int i = 1; i + 1 < argc; i += 2) {
        std::string flag = argv[i], value = argv[i + 1];
        if (flag == "--kills")
            o.kills = std::stoi(value);
        else if (flag == "--seed")
            o.seed = static_cast<unsigned>(std::stoul(value));
        else if (flag == "--spec")
            o.spec = value;
        else if (flag == "--markdown")
            o.markdown = value;
        else
            throw std::invalid_argument("unknown flag " + flag);
    }
    return o;
}

bool same_design(const nlohmann::json &a, const nlohmann::json &b) {
    for (const char *key : {"status", "design", "objective", "terms", "tasks"})
        if (a.at(key) != b.at(key))
            return false;
    return true;
}

double seconds_since(std::chrono::steady_clock::time_point t) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

} // namespace

int main(int argc, char **argv) {
    Options options = parse(argc, argv);
    fs::path dir = fs::temp_directory_path() / ("envdesign-durable-" + std::to_string(getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir / "undisturbed");
    std::mt19937 random(options.seed);

    nlohmann::json want;
    long long undisturbed = 0;
    double undisturbed_s = 0;
    {
        LocalCluster cluster(2, {"--state-dir", (dir / "undisturbed").string()});
        HeartbeatTally tally(cluster.url());
        auto start = std::chrono::steady_clock::now();
        want = CliRun(cluster.url(), options.spec, dir, "undisturbed").result();
        undisturbed_s = seconds_since(start);
        tally.settle();
        undisturbed = tally.done();
    }
    std::ostringstream table;
    table << "Spec `" << fs::relative(options.spec, source("")).string() << "`, seed "
          << options.seed << ". Undisturbed: " << undisturbed
          << " jobs (result: " << want.at("cluster").at("jobs_sent") << " sent) in " << std::fixed
          << std::setprecision(1) << undisturbed_s << " s, design " << want.at("design").dump()
          << ", objective " << want.at("objective") << ".\n\n"
          << "| kill | at s | jobs done at kill | in flight | sent after restart | done + sent "
             "<= undisturbed + in flight | planners computed | same design | repeat after "
             "clean restart: jobs |\n|---|---|---|---|---|---|---|---|---|\n";
    int failures = 0;
    for (int k = 1; k <= options.kills; ++k) {
        fs::path state = dir / ("killed-" + std::to_string(k));
        fs::create_directories(state);
        double at = std::uniform_real_distribution<double>(0.05, 0.95)(random) * undisturbed_s;
        LocalCluster cluster(2, {"--state-dir", state.string()});
        HeartbeatTally tally(cluster.url());
        auto start = std::chrono::steady_clock::now();
        CliRun client(cluster.url(), options.spec, dir, "killed-" + std::to_string(k));
        tally.until([&] { return seconds_since(start) >= at; }, 600);
        long long beats = tally.beats(); // kill right after a heartbeat: its counts are current
        tally.until([&] { return tally.beats() > beats; });
        long long done_at_kill = tally.done(), in_flight = tally.held();
        double killed_at = seconds_since(start);
        cluster.restart_coordinator(SIGKILL);
        nlohmann::json got = client.result();
        tally.settle();
        long long sent_after = got.at("cluster").at("jobs_sent");
        bool bound = done_at_kill + sent_after <= undisturbed + in_flight;
        bool same = same_design(got, want);
        cluster.restart_coordinator(SIGTERM);
        nlohmann::json repeat =
            CliRun(cluster.url(), options.spec, dir, "repeat-" + std::to_string(k)).result();
        long long repeat_jobs = repeat.at("cluster").at("jobs_sent");
        bool ok = bound && same && same_design(repeat, want) && repeat_jobs == 0 &&
                  tally.done() <= undisturbed + in_flight;
        failures += ok ? 0 : 1;
        table << "| " << k << " | " << std::setprecision(2) << killed_at << " | " << done_at_kill
              << " | " << in_flight << " | " << sent_after << " | " << done_at_kill + sent_after
              << " <= " << undisturbed + in_flight << (bound ? " yes" : " **NO**") << " | "
              << tally.done() << " | " << (same ? "yes" : "**NO**") << " | " << repeat_jobs
              << (ok ? "" : " **FAILED**") << " |\n";
        std::cerr << "kill " << k << " of " << options.kills << (ok ? ": ok" : ": FAILED")
                  << std::endl;
    }
    table << "\n" << options.kills - failures << " of " << options.kills << " kills passed.\n";
    std::cout << table.str();
    if (!options.markdown.empty())
        std::ofstream(options.markdown) << table.str();
    if (failures == 0)
        fs::remove_all(dir);
    else
        std::cerr << "logs kept in " << dir << "\n";
    return failures == 0 ? 0 : 1;
}
