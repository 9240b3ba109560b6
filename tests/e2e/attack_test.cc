// Attacks on a real coordinator and planners over loopback (issue 10): forged evaluations, a
// forged result, a spoofed cancel, replayed messages. A rogue is a Bus of its own on the
// cluster's URL: without the key, or with a key of its own. With the cluster's key every
// attack is dropped and counted, and the design and exit code are the undisturbed run's.
// Without a key, the sender checks still stop answers under a name the job or request was
// not sent to; what a rogue that takes a real name can do then is why keys exist.

#include "local_cluster.h"

#include "bus/codec.h"
#include "bus/log.h"
#include "envdesign/cancel_t.hpp"
#include "envdesign/design_progress_t.hpp"
#include "envdesign/design_request_t.hpp"
#include "envdesign/design_result_t.hpp"
#include "envdesign/evaluation_t.hpp"
#include "envdesign/job_t.hpp"
#include "envdesign/planner_heartbeat_t.hpp"

#include <envdesign/client/client.h>

#include <algorithm>
#include <atomic>
#include <fstream>
#include <limits>
#include <mutex>
#include <sys/stat.h>

namespace envdesign::e2e {
namespace {

std::string write_key_file(const std::string &name, const std::string &line) {
    std::string path = (std::filesystem::temp_directory_path() /
                        ("envdesign-attack-" + std::to_string(getpid()) + "-" + name))
                           .string();
    std::ofstream(path) << line << "\n";
    ::chmod(path.c_str(), 0600);
    return path;
}

// The deployment's key, and a key of the same id that is not it (a guess).
std::string cluster_key() { return write_key_file("cluster", "k1 " + std::string(64, '5')); }
std::string wrong_key() { return write_key_file("wrong", "k1 " + std::string(64, '6')); }

// What the wire says, whether signed or not: the trailer is not secret, so a rogue reads
// signed messages by dropping their last TRAILER_SIZE bytes.
template <typename Message> bool peek(const void *data, int size, Message &m) {
    return bus::decode_message(data, size, m) ||
           (size > bus::TRAILER_SIZE && bus::decode_message(data, size - bus::TRAILER_SIZE, m));
}

std::shared_ptr<spdlog::logger> quiet(const char *name) {
    return std::make_shared<spdlog::logger>(name, std::make_shared<spdlog::sinks::null_sink_mt>());
}

std::shared_ptr<const bus::KeyRing> keys_of(const std::string &key_file) {
    return key_file.empty() ? nullptr
                            : std::make_shared<const bus::KeyRing>(bus::load_key_file(key_file));
}

// An attacker on the bus: hears everything (unverified unless `hear_with_key`), reacts on a
// thread of its own, and speaks signed with `key_file` if given.
class Rogue {
public:
    explicit Rogue(const std::string &url, const std::string &key_file = "",
                   bool hear_with_key = false)
        : ears_(url, quiet("rogue"), hear_with_key ? keys_of(key_file) : nullptr),
          mouth_(key_file.empty() || hear_with_key
                     ? nullptr
                     : std::make_unique<bus::Bus>(url, quiet("rogue"), keys_of(key_file))) {}
    ~Rogue() { stop(); }
    template <typename Message>
    void on(const char *channel, std::function<void(const Message &, const std::string &)> act) {
        subs_.push_back(ears_.subscribe_raw(channel, [act](const void *data, int size) {
            Message m;
            if (peek(data, size, m))
                act(m, std::string(static_cast<const char *>(data), size));
        }));
    }
    void start() {
        thread_ = std::thread([this] {
            while (!stop_)
                ears_.handle(std::chrono::milliseconds(10));
        });
    }
    void stop() {
        stop_ = true;
        if (thread_.joinable())
            thread_.join();
    }
    bus::Bus &bus() { return ears_; }                      // raw bytes in and out
    bus::Bus &mouth() { return mouth_ ? *mouth_ : ears_; } // signed with its key, if any

private:
    bus::Bus ears_;
    std::unique_ptr<bus::Bus> mouth_;
    std::vector<bus::Subscription> subs_;
    std::atomic<bool> stop_{false};
    std::thread thread_;
};

client::Result keyed_design(const LocalCluster &cluster, const std::string &spec,
                            const std::string &search = "witness") {
    client::Options options;
    options.search = search;
    options.give_up_after_s = 20;
    options.key_file = cluster.key_file();
    return client::run_design_remote(source(spec), cluster.url(), options);
}

void expect_undisturbed(const client::Result &result, const std::string &spec) {
    ASSERT_EQ(result.exit_code, 0) << result.error;
    expect_same_design(nlohmann::json::parse(result.json), self_contained(source(spec)));
}

bool logged(Process &process, const std::string &text) {
    return process.output().find(text) != std::string::npos;
}

// A SOLVED answer to `job` from `sender`, its values left to the caller.
envdesign::evaluation_t forged_answer(const envdesign::job_t &job, const std::string &sender) {
    envdesign::evaluation_t e{};
    e.utime = bus::now_utime();
    e.request_id = job.request_id;
    e.sender = sender;
    e.coordinator = job.sender;
    e.job_id = job.job_id;
    e.kind = job.kind;
    e.status = envdesign::evaluation_t::STATUS_SOLVED;
    return e;
}

// Answers every job at once with the best possible evaluation (ie 1, cost 0): the issue's
// forgery that made the restaurant's design {}.
void forge_evaluations(Rogue &rogue, std::function<std::string(const envdesign::job_t &)> as) {
    rogue.on<envdesign::job_t>(
        bus::JOB, [&rogue, as](const envdesign::job_t &job, const std::string &) {
            envdesign::evaluation_t e = forged_answer(job, as(job));
            e.ie = 1;
            e.has_human_optimal_cost = true;
            e.has_robot_bound = job.kind == envdesign::job_t::KIND_ROBOT_BOUND;
            rogue.mouth().publish(bus::EVALUATION, e);
        });
    rogue.start();
}

TEST(Attack, ForgedEvaluationsWithoutAKeyUnderAnotherNameAreNotTaken) {
    LocalCluster cluster(2);
    Rogue rogue(cluster.url());
    forge_evaluations(rogue, [](const envdesign::job_t &) { return "planner-rogue"; });
    expect_undisturbed(keyed_design(cluster, RESTAURANT), RESTAURANT);
    EXPECT_TRUE(logged(cluster.coordinator(), "answered by planner-rogue, which it was not sent"))
        << cluster.logs();
}

TEST(Attack, ForgedEvaluationsInThePlannersNameAreDroppedWithAKey) {
    LocalCluster cluster(2, {}, cluster_key());
    Rogue unsigned_rogue(cluster.url());
    Rogue guessing_rogue(cluster.url(), wrong_key());
    auto as_holder = [](const envdesign::job_t &job) { return job.planner; };
    forge_evaluations(unsigned_rogue, as_holder);
    forge_evaluations(guessing_rogue, as_holder);
    expect_undisturbed(keyed_design(cluster, RESTAURANT), RESTAURANT);
    // The forged answers stayed out of the evaluation store too: a repeat sends jobs again
    // only if nothing was stored, and gets the same design either way.
    expect_undisturbed(keyed_design(cluster, RESTAURANT), RESTAURANT);
    for (const char *why : {"unauthenticated", "bad-mac"})
        EXPECT_TRUE(logged(cluster.coordinator(),
                           std::string("dropped a message on ENVDESIGN_EVALUATION: ") + why))
            << why << "\n"
            << cluster.logs();
}

// Sends a forged result with design ["FORGED-DESIGN"] once the coordinator has taken the
// request (its first progress), under `name`.
void forge_result(Rogue &rogue, const std::string &name) {
    rogue.on<envdesign::design_progress_t>(
        bus::PROGRESS, [&rogue, name, sent = false](const envdesign::design_progress_t &p,
                                                    const std::string &) mutable {
            if (std::exchange(sent, true))
                return;
            envdesign::design_result_t r{};
            r.utime = bus::now_utime();
            r.request_id = p.request_id;
            r.sender = name;
            r.client = p.client;
            r.status = "optimal";
            r.has_design = true;
            r.design = {"FORGED-DESIGN"};
            r.design_size = 1;
            rogue.mouth().publish(bus::RESULT, r);
        });
    rogue.start();
}

TEST(Attack, AForgedResultFromAnotherCoordinatorIsIgnoredWithoutAKey) {
    LocalCluster cluster(2);
    Rogue rogue(cluster.url());
    forge_result(rogue, "coordinator-rogue");
    expect_undisturbed(keyed_design(cluster, RESTAURANT), RESTAURANT);
}

TEST(Attack, AForgedResultInTheCoordinatorsNameIsDroppedWithAKey) {
    LocalCluster cluster(2, {}, cluster_key());
    Rogue rogue(cluster.url(), wrong_key());
    forge_result(rogue, "coordinator");
    Rogue listener(cluster.url(), cluster.key_file(), true); // drops what a keyed client does
    std::atomic<int> forged_seen{0};
    listener.on<envdesign::design_result_t>(
        bus::RESULT, [&](const envdesign::design_result_t &r, const std::string &) {
            forged_seen += r.design == std::vector<std::string>{"FORGED-DESIGN"};
        });
    listener.start();
    expect_undisturbed(keyed_design(cluster, RESTAURANT), RESTAURANT);
    listener.stop();
    EXPECT_EQ(forged_seen, 0);
    EXPECT_EQ(listener.bus().auth_drops().count(bus::RESULT, bus::Drop::BAD_MAC), 1);
}

// Cancels every request it sees in the client's name, once the coordinator works on it.
void spoof_cancel(Rogue &rogue) {
    rogue.on<envdesign::design_progress_t>(
        bus::PROGRESS,
        [&rogue, sent = false](const envdesign::design_progress_t &p, const std::string &) mutable {
            if (std::exchange(sent, true))
                return;
            envdesign::cancel_t c{};
            c.utime = bus::now_utime();
            c.request_id = p.request_id;
            c.sender = p.client;
            c.reason = "spoofed";
            rogue.mouth().publish(bus::CANCEL, c);
        });
    rogue.start();
}

TEST(Attack, ASpoofedCancelStopsTheSearchWithoutAKey) {
    LocalCluster cluster(2);
    Rogue rogue(cluster.url());
    spoof_cancel(rogue);
    client::Result result = keyed_design(cluster, WAREHOUSE, "exhaustive");
    EXPECT_EQ(result.exit_code, 4) << "the reason for keys: a name is all it takes";
    EXPECT_TRUE(logged(cluster.coordinator(), "cancelled by the client: spoofed"));
}

TEST(Attack, ASpoofedCancelIsDroppedWithAKeyEvenFromAKeyHolder) {
    LocalCluster cluster(2, {}, cluster_key());
    Rogue outsider(cluster.url());
    Rogue insider(cluster.url(), cluster.key_file()); // another process with the key
    spoof_cancel(outsider);
    spoof_cancel(insider);
    expect_undisturbed(keyed_design(cluster, WAREHOUSE, "exhaustive"), WAREHOUSE);
    EXPECT_TRUE(
        logged(cluster.coordinator(), "dropped a message on ENVDESIGN_CANCEL: unauthenticated"))
        << cluster.logs();
    EXPECT_TRUE(logged(cluster.coordinator(), "a cancel from another process")) << cluster.logs();
    EXPECT_FALSE(logged(cluster.coordinator(), "cancelled by the client"));
}

// Records every message on the channels a rogue would replay, as sent (signed or not).
struct Capture {
    std::mutex mutex;
    std::vector<std::pair<std::string, std::string>> messages; // channel, bytes
    void record(Rogue &rogue) {
        for (const char *channel : {bus::REQUEST, bus::EVALUATION, bus::JOB}) {
            subs.push_back(
                rogue.bus().subscribe_raw(channel, [this, channel](const void *d, int n) {
                    std::lock_guard lock(mutex);
                    messages.emplace_back(channel, std::string(static_cast<const char *>(d), n));
                }));
        }
    }
    std::vector<bus::Subscription> subs;
};

void replay_test(const std::string &key_file) {
    LocalCluster cluster(2, {}, key_file);
    Rogue rogue(cluster.url());
    Capture capture;
    capture.record(rogue);
    rogue.start();
    expect_undisturbed(keyed_design(cluster, RESTAURANT), RESTAURANT);
    rogue.stop();
    ASSERT_FALSE(capture.messages.empty());
    // Everything again, twice, while a second request runs.
    std::thread replayer([&] {
        for (int round = 0; round < 2; ++round)
            for (const auto &[channel, bytes] : capture.messages)
                rogue.bus().publish_raw(channel, bytes.data(), static_cast<int>(bytes.size()));
    });
    expect_undisturbed(keyed_design(cluster, RESTAURANT), RESTAURANT);
    replayer.join();
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    if (key_file.empty()) {
        // The replayed request is a repeat: its result goes out again.
        EXPECT_TRUE(logged(cluster.coordinator(), "repeated; its result is sent again"));
        return;
    }
    EXPECT_FALSE(logged(cluster.coordinator(), "repeated"));
    for (const char *channel : {"ENVDESIGN_REQUEST", "ENVDESIGN_EVALUATION"})
        EXPECT_TRUE(logged(cluster.coordinator(),
                           std::string("dropped a message on ") + channel + ": replayed"))
            << channel << "\n"
            << cluster.logs();
    EXPECT_TRUE(logged(cluster.planner(0), "dropped a message on ENVDESIGN_JOB: replayed"))
        << cluster.logs();
    // Its heartbeats count them, for whoever watches the bus.
    Rogue watcher(cluster.url(), key_file, true);
    std::atomic<long long> counted{0};
    watcher.on<envdesign::planner_heartbeat_t>(
        bus::HEARTBEAT, [&](const envdesign::planner_heartbeat_t &b, const std::string &) {
            if (b.sender == "planner-0")
                counted = b.malformed;
        });
    watcher.start();
    std::this_thread::sleep_for(std::chrono::milliseconds(500));
    watcher.stop();
    long long jobs = std::count_if(capture.messages.begin(), capture.messages.end(),
                                   [](const auto &m) { return m.first == bus::JOB; });
    EXPECT_GE(counted, 2 * jobs) << "every replayed job, twice";
}

TEST(Attack, ReplaysWithoutAKeyAreRepeats) { replay_test(""); }

TEST(Attack, ReplaysOfCapturedSignedMessagesAreDroppedWithAKey) { replay_test(cluster_key()); }

// A planner that lists every job it is given and never answers (the stall): its jobs
// are taken at their deadline, it is demoted, and the design is the undisturbed one, long
// before the request's time limit. With a key it never joins.
void fake_planner_test(const std::string &key_file) {
    LocalCluster cluster(1, {"--job-deadline", "0.5"}, key_file);
    Rogue fake(cluster.url());
    std::mutex mutex;
    std::vector<std::int64_t> held;
    fake.on<envdesign::job_t>(bus::JOB, [&](const envdesign::job_t &job, const std::string &) {
        std::lock_guard lock(mutex);
        if (job.planner == "planner-fake")
            held.push_back(job.job_id);
    });
    fake.start();
    std::atomic<bool> done{false};
    std::thread beats([&] {
        while (!done) {
            envdesign::planner_heartbeat_t beat{};
            beat.utime = bus::now_utime();
            beat.sender = "planner-fake";
            beat.period_ms = 100;
            beat.capacity = 4;
            {
                std::lock_guard lock(mutex);
                beat.jobs = held;
            }
            beat.num_jobs = static_cast<std::int16_t>(beat.jobs.size());
            fake.mouth().publish(bus::HEARTBEAT, beat);
            std::this_thread::sleep_for(std::chrono::milliseconds(100));
        }
    });
    std::this_thread::sleep_for(std::chrono::milliseconds(500)); // it joins (without a key)
    auto start = std::chrono::steady_clock::now();
    client::Options options;
    options.time_limit_s = 60;
    options.key_file = cluster.key_file();
    client::Result result = client::run_design_remote(source(RESTAURANT), cluster.url(), options);
    double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    done = true;
    beats.join();
    expect_undisturbed(result, RESTAURANT);
    EXPECT_LT(seconds, 30) << cluster.logs();
    if (key_file.empty()) {
        EXPECT_TRUE(logged(cluster.coordinator(), "missed its deadline at planner-fake"))
            << cluster.logs();
        EXPECT_TRUE(logged(cluster.coordinator(), "planner planner-fake missed 2 job deadlines"))
            << cluster.logs();
    } else {
        EXPECT_FALSE(logged(cluster.coordinator(), "planner planner-fake joined"));
        EXPECT_TRUE(logged(cluster.coordinator(),
                           "dropped a message on ENVDESIGN_HEARTBEAT: unauthenticated"));
    }
}

TEST(Attack, APlannerThatNeverAnswersLosesItsJobsWithoutAKey) { fake_planner_test(""); }

TEST(Attack, APlannerThatNeverAnswersCannotJoinWithAKey) { fake_planner_test(cluster_key()); }

// Answers every robot-bound job in the planner's name with `bound` (issue 21: 1e308 and inf
// passed the wire check, and CBC aborted the coordinator; stored, at every start again).
void forge_robot_bounds(Rogue &rogue, double bound) {
    rogue.on<envdesign::job_t>(bus::JOB,
                               [&rogue, bound](const envdesign::job_t &job, const std::string &) {
                                   if (job.kind != envdesign::job_t::KIND_ROBOT_BOUND)
                                       return;
                                   envdesign::evaluation_t e = forged_answer(job, job.planner);
                                   e.has_robot_bound = true;
                                   e.robot_bound = bound;
                                   rogue.mouth().publish(bus::EVALUATION, e);
                               });
    rogue.start();
}

std::vector<std::string> state_dir_flags(const std::string &name) {
    auto dir = std::filesystem::temp_directory_path() /
               ("envdesign-poison-" + std::to_string(getpid()) + "-" + name);
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return {"--state-dir", dir.string()};
}

// 1e308 is no plan cost: refused at the wire, so the design is the undisturbed one.
TEST(Poison, AHugeRobotBoundIsRefusedAndTheCoordinatorLives) {
    LocalCluster cluster(1, state_dir_flags("huge"));
    {
        Rogue rogue(cluster.url());
        forge_robot_bounds(rogue, 1e308);
        expect_undisturbed(keyed_design(cluster, RESTAURANT), RESTAURANT);
    }
    EXPECT_TRUE(cluster.coordinator().running()) << cluster.logs();
    EXPECT_TRUE(logged(cluster.coordinator(), "the robot bound is not a cost")) << cluster.logs();
    cluster.restart_coordinator(SIGTERM);
    expect_undisturbed(keyed_design(cluster, RESTAURANT), RESTAURANT);
    EXPECT_TRUE(cluster.coordinator().running()) << cluster.logs();
}

// inf means "no plan": taken from a planner's name on a bus without keys (what keys are
// for), but neither then nor after a restart on the stored value may it stop the service.
TEST(Poison, AnInfiniteRobotBoundNeverAbortsTheCoordinatorNorItsRestarts) {
    LocalCluster cluster(1, state_dir_flags("inf"));
    {
        Rogue rogue(cluster.url());
        forge_robot_bounds(rogue, std::numeric_limits<double>::infinity());
        client::Result forged = keyed_design(cluster, RESTAURANT);
        EXPECT_EQ(forged.exit_code, 0) << forged.error << cluster.logs();
    }
    EXPECT_TRUE(cluster.coordinator().running()) << cluster.logs();
    cluster.restart_coordinator(SIGTERM);
    client::Result after = keyed_design(cluster, RESTAURANT);
    EXPECT_EQ(after.exit_code, 0) << after.error << cluster.logs();
    EXPECT_TRUE(cluster.coordinator().running()) << cluster.logs();
}

TEST(Attack, AKeyFileOthersCanReadIsRefused) {
    std::string key = cluster_key();
    ::chmod(key.c_str(), 0644);
    Process planner({binary("envdesign-planner"), "--lcm-url", unique_url(), "--key-file", key},
                    (std::filesystem::temp_directory_path() /
                     ("envdesign-attack-" + std::to_string(getpid()) + ".log"))
                        .string());
    EXPECT_EQ(planner.wait(), 2);
    EXPECT_NE(planner.output().find("accessible by group or others"), std::string::npos)
        << planner.output();
}

} // namespace
} // namespace envdesign::e2e
