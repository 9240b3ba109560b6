// The services as deployed: envdesign-coordinator and envdesign-planner processes over udpm
// on loopback, the C++ client library in this process. Whatever happens to the planners or
// on the channels, the answer is the self-contained run's.

#include "local_cluster.h"

#include "bus/codec.h"
#include "envdesign/cancel_t.hpp"
#include "envdesign/design_request_t.hpp"
#include "envdesign/evaluation_t.hpp"
#include "envdesign/job_t.hpp"
#include "envdesign/spec_chunk_t.hpp"

#include <envdesign/client/client.h>

#include <atomic>
#include <cmath>
#include <random>

namespace envdesign::e2e {
namespace {

client::Result design(const LocalCluster &cluster, const std::string &spec,
                      std::function<void(const client::Progress &)> on_progress = {},
                      const std::string &search = "witness") {
    client::Options options;
    options.on_progress = std::move(on_progress);
    options.search = search;
    options.give_up_after_s = 10;
    return client::run_design_remote(source(spec), cluster.url(), options);
}

void expect_self_contained(const client::Result &result, const std::string &spec) {
    ASSERT_EQ(result.exit_code, 0) << result.error;
    expect_same_design(nlohmann::json::parse(result.json), self_contained(source(spec)));
}

// The witness search and the exhaustive one through the cluster: the same design.
TEST(EndToEnd, BothSearchesGiveTheSameDesignThroughTheCoordinator) {
    LocalCluster cluster(2);
    client::Result witness = design(cluster, WAREHOUSE);
    client::Result exhaustive = design(cluster, WAREHOUSE, {}, "exhaustive");
    ASSERT_EQ(witness.exit_code, 0) << witness.error;
    ASSERT_EQ(exhaustive.exit_code, 0) << exhaustive.error;
    auto w = nlohmann::json::parse(witness.json), e = nlohmann::json::parse(exhaustive.json);
    for (const char *key : {"status", "design", "objective", "tasks"})
        EXPECT_EQ(w.at(key), e.at(key)) << key;
    EXPECT_LT(w.at("configurations_total"), e.at("configurations_total"));
}

TEST(EndToEnd, CoordinatorAndTwoPlannersGiveTheSelfContainedResult) {
    LocalCluster cluster(2);
    for (const char *spec : {RESTAURANT, WAREHOUSE}) {
        SCOPED_TRACE(spec);
        client::Result result = design(cluster, spec);
        expect_self_contained(result, spec);
        auto counters = nlohmann::json::parse(result.json).at("cluster");
        EXPECT_EQ(counters.at("planners_used"), 2);
        EXPECT_EQ(counters.at("jobs_resent"), 0);
    }
    EXPECT_TRUE(cluster.coordinator().running());
}

// A robot that is not an explicable planner (issue 14): the spec's robot_behaviour travels
// with it, the planners evaluate the worst optimal plan, the evaluations carry the optimal
// actions, and the answer is the self-contained one: take the hop away ({no-hop}, objective
// 0.9 * 1 + 0.1 * 1 + 5 = 6; an explicable robot would choose nothing; the spec's comment).
TEST(EndToEnd, CostOptimalSpecGivesTheSelfContainedResult) {
    const char *spec = "tests/e2e/data/cost-optimal/two-ways.textproto";
    LocalCluster cluster(2);
    for (const std::string search : {"witness", "exhaustive"}) {
        client::Result result = design(cluster, spec, {}, search);
        expect_self_contained(result, spec);
        auto json = nlohmann::json::parse(result.json);
        EXPECT_EQ(json.at("design"), nlohmann::json::array({"no-hop"})) << search;
        EXPECT_NEAR(json.at("objective").get<double>(), 6.0, 1e-9) << search;
        EXPECT_NEAR(json.at("baseline").at("objective").get<double>(),
                    0.9 * std::exp(3.0) + 0.1 * 1.0, 1e-9)
            << search;
    }
}

TEST(EndToEnd, PlannerKilledMidRun) {
    LocalCluster cluster(2);
    std::atomic<bool> killed{false};
    client::Result result = design(
        cluster, WAREHOUSE,
        [&](const client::Progress &p) {
            if (p.evaluations >= 40 && !killed.exchange(true))
                cluster.planner(0).signal(SIGKILL);
        },
        "exhaustive"); // the long search, so that the planner dies mid-run
    ASSERT_TRUE(killed);
    expect_self_contained(result, WAREHOUSE);
    EXPECT_EQ(cluster.planner(0).wait(), 128 + SIGKILL);
    EXPECT_NE(cluster.coordinator().output().find("planner-0 went silent"), std::string::npos)
        << cluster.logs();
    EXPECT_GE(nlohmann::json::parse(result.json).at("cluster").at("jobs_resent"), 1);
}

TEST(EndToEnd, PlannerStartedMidRunTakesWork) {
    LocalCluster cluster(1);
    std::atomic<bool> started{false};
    std::thread starter;
    client::Result result = design(
        cluster, WAREHOUSE,
        [&](const client::Progress &p) {
            if (p.evaluations >= 30 && !started.exchange(true))
                starter = std::thread([&] { cluster.add_planner(); });
        },
        "exhaustive");
    if (starter.joinable())
        starter.join();
    ASSERT_TRUE(started);
    expect_self_contained(result, WAREHOUSE);
    EXPECT_EQ(nlohmann::json::parse(result.json).at("cluster").at("planners_used"), 2)
        << cluster.logs();
    EXPECT_NE(cluster.planner(1).output().find("spec"), std::string::npos); // it asked for it
}

// Publishes junk on every ENVDESIGN_ channel until stopped: random bytes, messages of the
// wrong type, truncated ones, and well-typed ones that make no sense.
class Garbage {
public:
    explicit Garbage(const std::string &url)
        : bus_(url, std::make_shared<spdlog::logger>(
                        "garbage", std::make_shared<spdlog::sinks::null_sink_mt>())),
          thread_([this] { run(); }) {}
    ~Garbage() {
        stop_ = true;
        thread_.join();
    }
    long long sent() const { return sent_; }

private:
    void run() {
        std::mt19937 random(7);
        while (!stop_) {
            for (const char *channel : bus::ALL_CHANNELS)
                junk(channel, random);
            std::this_thread::sleep_for(std::chrono::milliseconds(5));
        }
    }
    void junk(const char *channel, std::mt19937 &random) {
        std::string bytes(random() % 3000, '\0');
        for (auto &c : bytes)
            c = static_cast<char>(random());
        bus_.publish_raw(channel, bytes.data(), static_cast<int>(bytes.size()));
        envdesign::cancel_t wrong_type{};
        bus_.publish(channel, wrong_type);
        std::string job = bus::encode_message(nonsense_job());
        bus_.publish_raw(channel, job.data(), static_cast<int>(job.size()) / 2);
        if (std::string(channel) == bus::JOB)
            bus_.publish(channel, nonsense_job());
        if (std::string(channel) == bus::SPEC) {
            envdesign::spec_chunk_t chunk{};
            chunk.spec_hash = std::string(64, 'a');
            chunk.total_bytes = 10;
            chunk.num_chunks = 5;
            bus_.publish(channel, chunk);
        }
        if (std::string(channel) == bus::EVALUATION) {
            envdesign::evaluation_t e{};
            e.coordinator = "coordinator";
            e.job_id = static_cast<std::int64_t>(random());
            e.status = 42;
            bus_.publish(channel, e);
        }
        sent_ += 3;
    }
    static envdesign::job_t nonsense_job() {
        envdesign::job_t j{};
        j.sender = "coordinator";
        j.planner = "planner-0";
        j.job_id = 12345;
        j.spec_hash = std::string(64, 'b');
        j.kind = 77;
        j.task = -3;
        return j;
    }

    bus::Bus bus_;
    std::atomic<bool> stop_{false};
    std::atomic<long long> sent_{0};
    std::thread thread_;
};

TEST(EndToEnd, GarbageOnEveryChannelChangesNothing) {
    LocalCluster cluster(2);
    client::Result result;
    long long sent = 0;
    {
        Garbage garbage(cluster.url());
        std::this_thread::sleep_for(std::chrono::milliseconds(200));
        result = design(cluster, WAREHOUSE);
        sent = garbage.sent();
    }
    EXPECT_GT(sent, 100);
    expect_self_contained(result, WAREHOUSE);
    EXPECT_TRUE(cluster.coordinator().running()) << cluster.logs();
    EXPECT_TRUE(cluster.planner(0).running()) << cluster.logs();
    EXPECT_TRUE(cluster.planner(1).running()) << cluster.logs();
    EXPECT_NE(cluster.coordinator().output().find("malformed message on ENVDESIGN_REQUEST"),
              std::string::npos);
    EXPECT_NE(cluster.planner(0).output().find("malformed message on ENVDESIGN_JOB"),
              std::string::npos);
    // And the services stop cleanly afterwards.
    cluster.planner(1).signal(SIGTERM);
    EXPECT_EQ(cluster.planner(1).wait(), 0);
    cluster.coordinator().signal(SIGTERM);
    EXPECT_EQ(cluster.coordinator().wait(), 0);
}

// A spec of ~400 KB: the request spans several datagrams (LCM fragments it; the receive
// buffer of the URL keeps them), the spec reaches planners in 32 KB chunks.
TEST(EndToEnd, SpecFarLargerThanADatagram) {
    namespace fs = std::filesystem;
    fs::path copy = fs::temp_directory_path() / ("envdesign-big-" + std::to_string(getpid()));
    fs::remove_all(copy);
    fs::copy(source("examples/restaurant"), copy);
    {
        std::ofstream domain(copy / "domain.pddl", std::ios::app);
        for (int i = 0; i < 5000; ++i)
            domain << "; padding " << i << " " << std::string(60, 'x') << "\n";
    }
    std::string spec = (copy / "c-two-tasks-t10.textproto").string();
    LocalCluster cluster(2);
    client::Result result = client::run_design_remote(spec, cluster.url());
    ASSERT_EQ(result.exit_code, 0) << result.error << cluster.logs();
    expect_same_design(nlohmann::json::parse(result.json), self_contained(spec));
    EXPECT_NE(cluster.planner(0).output().find("received"), std::string::npos);
    fs::remove_all(copy);
}

// `envdesign design --connect URL`: the CLI as a client of the cluster.
TEST(EndToEnd, CliConnectGivesTheSelfContainedResult) {
    LocalCluster cluster(2);
    std::string connect = " --connect '" + cluster.url() + "'";
    expect_connect_gives_self_contained(cluster.url(), cluster.logs());
    int exit_code = -1;

    std::string error = command_output(binary("envdesign") + " design " +
                                           source("tests/data/design/bad/missing-file.textproto") +
                                           connect + " 2>&1",
                                       &exit_code);
    EXPECT_EQ(exit_code, 2);
    EXPECT_NE(error.find("missing-file.textproto:4:"), std::string::npos) << error;
}

// --ranking N travels in the request, and the coordinator's result ranks (and explains) as
// the local run does: the restaurant's 3 best, a tie of the symmetric barrier pairs first.
TEST(EndToEnd, CliConnectRanksAsTheLocalRun) {
    LocalCluster cluster(1);
    int exit_code = -1;
    std::string command =
        binary("envdesign") + " design " + source(RESTAURANT) + " --json --ranking 3 2>/dev/null";
    std::string local = command_output(command, &exit_code);
    ASSERT_EQ(exit_code, 0) << local;
    std::string remote =
        command_output(binary("envdesign") + " design " + source(RESTAURANT) +
                           " --json --ranking 3 --connect '" + cluster.url() + "' 2>/dev/null",
                       &exit_code);
    ASSERT_EQ(exit_code, 0) << remote << cluster.logs();
    nlohmann::json want = nlohmann::json::parse(local), got = nlohmann::json::parse(remote);
    expect_same_design(got, want);
    ASSERT_EQ(got.at("ranking").size(), 3u);
    EXPECT_EQ(got.at("ranking"), want.at("ranking"));
    EXPECT_EQ(got.at("ranking")[1].at("design"),
              nlohmann::json({"barrier-01-02", "barrier-11-12"}));
}

// --ranking-all travels too (design_request_t.ranking_all): on tests/data/ranking/padded.textproto
// the coordinator lists the designs padded with a free modification that changes nothing only
// when asked, as the local run does.
TEST(EndToEnd, CliConnectRankingAllAsTheLocalRun) {
    LocalCluster cluster(1);
    const std::string spec = source("tests/data/ranking/padded.textproto");
    for (const char *all : {"", " --ranking-all"}) {
        SCOPED_TRACE(all);
        int exit_code = -1;
        std::string flags = std::string(" --json --ranking 4") + all;
        std::string local = command_output(
            binary("envdesign") + " design " + spec + flags + " 2>/dev/null", &exit_code);
        ASSERT_EQ(exit_code, 0) << local;
        std::string remote = command_output(binary("envdesign") + " design " + spec + flags +
                                                " --connect '" + cluster.url() + "' 2>/dev/null",
                                            &exit_code);
        ASSERT_EQ(exit_code, 0) << remote << cluster.logs();
        nlohmann::json want = nlohmann::json::parse(local), got = nlohmann::json::parse(remote);
        ASSERT_EQ(got.at("ranking").size(), 4u);
        EXPECT_EQ(got.at("ranking"), want.at("ranking"));
        bool padded = false;
        for (const auto &point : got.at("ranking"))
            for (const auto &name : point.at("design"))
                padded = padded || name == "paint-wall";
        EXPECT_EQ(padded, !std::string(all).empty());
    }
}

// Ctrl-C on `envdesign design --connect`: the request is cancelled on the coordinator (it
// does not keep a slot searching for nobody) and the best design so far is printed, exit 4.
TEST(EndToEnd, CliInterruptedCancelsTheRequest) {
    LocalCluster cluster(1);
    std::string spec = source("tests/e2e/data/warehouse-small/signs-3.textproto");
    std::string out = (std::filesystem::temp_directory_path() /
                       ("envdesign-cli-" + std::to_string(getpid()) + ".out"))
                          .string();
    // The exhaustive search: long enough to be interrupted.
    Process cli({binary("envdesign"), "design", spec, "--json", "--search", "exhaustive",
                 "--connect", cluster.url()},
                out);
    auto searching = [&] {
        return cluster.coordinator().output().find("loaded:") != std::string::npos;
    };
    for (int i = 0; i < 500 && !searching(); ++i)
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    ASSERT_TRUE(searching()) << cluster.logs();
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    cli.signal(SIGINT);
    EXPECT_EQ(cli.wait(), 4) << cli.output();
    std::istringstream printed(cli.output()); // stdout and stderr: the JSON is one line of it
    std::string line;
    while (std::getline(printed, line) && (line.empty() || line[0] != '{'))
        ;
    ASSERT_FALSE(line.empty()) << cli.output();
    auto json = nlohmann::json::parse(line);
    EXPECT_EQ(json.at("status"), "best_found");
    EXPECT_EQ(json.at("limit_reached"), true);
    EXPECT_NE(
        cluster.coordinator().output().find("cancelled by the client: the client was stopped"),
        std::string::npos)
        << cluster.logs();
    std::filesystem::remove(out);
}

TEST(EndToEnd, ServicesRefuseAUrlThatIsNotLcms) {
    for (const char *service : {"envdesign-coordinator", "envdesign-planner"}) {
        int exit_code = -1;
        std::string said =
            command_output(binary(service) + " --lcm-url bogus://x 2>&1", &exit_code);
        EXPECT_EQ(exit_code, 2) << service;
        EXPECT_NE(said.find("--lcm-url: 'bogus://x' is not an LCM URL"), std::string::npos) << said;
    }
}

TEST(EndToEnd, NoCoordinatorIsExit1) {
    client::Options options;
    options.give_up_after_s = 1;
    options.resend_after_s = 0.3;
    client::Result result = client::run_design_remote(source(RESTAURANT), unique_url(), options);
    EXPECT_EQ(result.exit_code, 1);
    EXPECT_NE(result.error.find("no coordinator"), std::string::npos) << result.error;
}

TEST(EndToEnd, BadSpecIsExit2BeforeSending) {
    client::Result result = client::run_design_remote(
        source("tests/data/design/bad/missing-file.textproto"), unique_url());
    EXPECT_EQ(result.exit_code, 2);
    EXPECT_NE(result.error.find("missing-file.textproto:4:"), std::string::npos) << result.error;
}

} // namespace
} // namespace envdesign::e2e
