// The services under systemd (issue 11): --config FILE (keys are the flags' names, flags on
// the command line win, a bad line exits 2 naming FILE:LINE:COL) and the notify protocol
// (READY=1 once on the bus, WATCHDOG=1 from the loop, STOPPING=1), with real processes and
// a notify socket bound here as systemd would.

#include "local_cluster.h"

#include "../support/notify_socket.h"

namespace envdesign::e2e {
namespace {

using namespace std::chrono_literals;
using testing::NotifySocket;

struct Outcome {
    int code;
    std::string output; // stdout and stderr
};

Outcome run(const std::string &command) {
    int code = -1;
    std::string out = command_output(command + " 2>&1", &code);
    return {code, out};
}

class ServiceConfig : public ::testing::Test {
protected:
    std::filesystem::path dir = std::filesystem::path(::testing::TempDir()) /
                                ("envdesign-config-" + std::to_string(getpid()));
    void SetUp() override { std::filesystem::create_directories(dir); }
    void TearDown() override { std::filesystem::remove_all(dir); }
    std::string write(const std::string &name, const std::string &text) {
        std::string path = (dir / name).string();
        std::ofstream(path) << text;
        return path;
    }
    Outcome check(const std::string &service, const std::string &conf,
                  const std::string &flags = "") {
        return run(binary(service) + " --config " + conf + " " + flags + " --check-config");
    }
};

TEST_F(ServiceConfig, AGoodFileIsAcceptedWithCommentsQuotesAndFlags) {
    std::string conf = write("good.conf", "# the coordinator\n"
                                          "\n"
                                          "max-requests = 4   # searches at once\n"
                                          "  lcm-url = \"udpm://239.255.76.67:7667?ttl=0\"\n"
                                          "state-fsync = true\n"
                                          "log-level=warn\n");
    Outcome r = check("envdesign-coordinator", conf);
    EXPECT_EQ(r.code, 0) << r.output;
    EXPECT_NE(r.output.find("configuration OK"), std::string::npos) << r.output;
}

TEST_F(ServiceConfig, AnUnknownKeyExitsTwoNamingFileAndLine) {
    std::string conf = write("unknown.conf", "max-requests = 4\n\n  workers = 2\n");
    Outcome r = check("envdesign-coordinator", conf); // --workers is the planner's
    EXPECT_EQ(r.code, 2);
    EXPECT_NE(r.output.find(conf + ":3:3: error: unknown setting 'workers'"), std::string::npos)
        << r.output;
    // The same key is the planner's own.
    EXPECT_EQ(check("envdesign-planner", conf).code, 2); // max-requests is not
    EXPECT_EQ(check("envdesign-planner", write("p.conf", "workers = 2\n")).code, 0);
}

TEST_F(ServiceConfig, ALineWithoutEqualsOrAnUnclosedQuoteExitsTwoNamingTheColumn) {
    std::string missing = write("missing.conf", "max-requests 4\n");
    Outcome r = check("envdesign-coordinator", missing);
    EXPECT_EQ(r.code, 2);
    EXPECT_NE(r.output.find(missing + ":1:14: error: expected '=' after 'max-requests'"),
              std::string::npos)
        << r.output;
    std::string quote = write("quote.conf", "log-level = warn\nname = \"coordinator/a\n");
    r = check("envdesign-coordinator", quote);
    EXPECT_EQ(r.code, 2);
    EXPECT_NE(r.output.find(quote + ":2:7: error: unterminated quote"), std::string::npos)
        << r.output;
    r = check("envdesign-coordinator", (dir / "absent.conf").string());
    EXPECT_EQ(r.code, 2);
    EXPECT_NE(r.output.find("absent.conf: error: cannot read the config file"), std::string::npos)
        << r.output;
}

TEST_F(ServiceConfig, ValuesPassTheFlagsChecksAndTheCommandLineWins) {
    std::string conf = write("range.conf", "max-requests = 0\n"); // the flag wants 1..1000
    Outcome r = check("envdesign-coordinator", conf);
    EXPECT_EQ(r.code, 2);
    EXPECT_NE(r.output.find("max-requests"), std::string::npos) << r.output;
    // Given on the command line, the file's bad value is never used.
    EXPECT_EQ(check("envdesign-coordinator", conf, "--max-requests 3").code, 0);
    EXPECT_EQ(check("envdesign-coordinator", conf, "--max-requests=3").code, 0);
    EXPECT_EQ(check("envdesign-coordinator", write("flag.conf", "state-fsync = maybe\n")).code, 2);
}

// READY=1 after the bus is up, then WATCHDOG=1 at half of WATCHDOG_USEC, STOPPING=1 on
// SIGTERM: for the coordinator and for a planner.
void expect_notify_protocol(const std::string &service, const std::filesystem::path &dir) {
    NotifySocket socket((dir / (service + ".notify")).string());
    std::vector<std::string> argv = {binary(service), "--lcm-url", unique_url(3), "--name",
                                     service + "/notify"};
    Process process(argv, socket.env(200'000), (dir / (service + ".log")).string());
    auto ready = socket.next(10s);
    ASSERT_TRUE(ready) << "no notification\n" << process.output();
    EXPECT_NE(ready->find("READY=1"), std::string::npos) << *ready;
    EXPECT_NE(ready->find("STATUS=on udpm://"), std::string::npos) << *ready;
    // 100 ms apart: at least 5 in the next 1.2 s, and no fewer than the time allows.
    auto start = std::chrono::steady_clock::now();
    int watchdogs = 0;
    while (std::chrono::steady_clock::now() - start < 1200ms) {
        auto m = socket.next(300ms);
        ASSERT_TRUE(m) << "the watchdog stopped after " << watchdogs << "\n" << process.output();
        EXPECT_EQ(*m, "WATCHDOG=1");
        ++watchdogs;
    }
    EXPECT_GE(watchdogs, 5);
    EXPECT_LE(watchdogs, 14); // not a busy loop either
    process.signal(SIGTERM);
    EXPECT_TRUE(socket.until("STOPPING=1", 10s)) << process.output();
    EXPECT_EQ(process.wait(), 0);
}

TEST_F(ServiceConfig, CoordinatorTellsSystemdReadyThenFeedsTheWatchdog) {
    expect_notify_protocol("envdesign-coordinator", dir);
}

TEST_F(ServiceConfig, PlannerTellsSystemdReadyThenFeedsTheWatchdog) {
    expect_notify_protocol("envdesign-planner", dir);
}

TEST_F(ServiceConfig, WithoutNotifySocketTheServiceRunsAsBefore) {
    Process process({binary("envdesign-planner"), "--lcm-url", unique_url(3), "--name", "p"},
                    {"WATCHDOG_USEC=100000"}, (dir / "plain.log").string());
    std::this_thread::sleep_for(500ms);
    EXPECT_TRUE(process.running()) << process.output();
    process.signal(SIGTERM);
    EXPECT_EQ(process.wait(), 0) << process.output();
}

// Issue 21: a bad value in the file exited 2 without its line; NaN durations passed;
// `version = true` made a service print its version and exit 0; --check-config passed with a
// key file that does not exist and a URL start-up refuses.
TEST_F(ServiceConfig, BadValuesNameTheirLineAndCheckConfigCatchesWhatStartUpWould) {
    std::string nan = write("nan.conf", "log-level = info\nplanner-timeout = nan\n");
    Outcome r = check("envdesign-coordinator", nan);
    EXPECT_EQ(r.code, 2);
    EXPECT_NE(r.output.find(nan + ":2:1: error: --planner-timeout"), std::string::npos) << r.output;
    std::string inf = write("inf.conf", "heartbeat = inf\n");
    r = check("envdesign-planner", inf);
    EXPECT_EQ(r.code, 2);
    EXPECT_NE(r.output.find(inf + ":1:1: error: --heartbeat"), std::string::npos) << r.output;
    std::string version = write("version.conf", "version = true\n");
    r = check("envdesign-coordinator", version);
    EXPECT_EQ(r.code, 2);
    EXPECT_NE(r.output.find(version + ":1:1: error: unknown setting 'version'"), std::string::npos)
        << r.output;
    std::string key = write("key.conf", "key-file = " + (dir / "absent.key").string() + "\n");
    r = check("envdesign-planner", key);
    EXPECT_EQ(r.code, 2);
    EXPECT_NE(r.output.find("--key-file"), std::string::npos) << r.output;
    std::string url = write("url.conf", "lcm-url = udpm://300.1.2.3:7667\n");
    r = check("envdesign-coordinator", url);
    EXPECT_EQ(r.code, 2);
    EXPECT_NE(r.output.find("--lcm-url"), std::string::npos) << r.output;
}

// A UDP port another program holds without sharing it: LCM prints "bind: Address already in
// use" and its receiver stays deaf (a test process once crashed on it). Each service exits 1
// at start-up, naming the port, instead of running without hearing anything.
TEST_F(ServiceConfig, AServiceOnAPortAnotherProgramHoldsExitsNamingThePort) {
    int port = testing::claim_udp_port();
    int fd = testing::bind_udp_port_unshared(port);
    ASSERT_GE(fd, 0);
    for (std::string service : {"envdesign-coordinator", "envdesign-planner"}) {
        Outcome r = run("timeout 20 " + binary(service) + " --lcm-url '" +
                        testing::udpm_test_url(port) + "' --name held");
        EXPECT_EQ(r.code, 1) << service << ": " << r.output;
        EXPECT_NE(r.output.find("LCM cannot receive on UDP port " + std::to_string(port)),
                  std::string::npos)
            << service << ": " << r.output;
    }
    ::close(fd);
}

// --check-config also finds what start-up would fail on beyond the flags: a bridge --problem
// spec that does not load (named by its id and its file's line), and a --state-dir whose
// evaluation file cannot be opened (here a directory in its place), for the coordinator and
// the bridge. A state directory it can use is not changed by the check.
TEST_F(ServiceConfig, CheckConfigLoadsTheBridgesSpecsAndTheStateDir) {
    std::filesystem::path state = dir / "state";
    std::filesystem::create_directories(state / "evaluations.db");
    std::string conf = write("state.conf", "state-dir = " + state.string() + "\n");
    Outcome r = check("envdesign-coordinator", conf);
    EXPECT_EQ(r.code, 2) << r.output;
    EXPECT_NE(r.output.find("envdesign-coordinator: --state-dir: " +
                            (state / "evaluations.db").string() + " is not a regular file"),
              std::string::npos)
        << r.output;
    std::filesystem::path usable = dir / "usable";
    std::filesystem::create_directories(usable);
    r = check("envdesign-coordinator", conf, "--state-dir " + usable.string());
    EXPECT_EQ(r.code, 0) << r.output;
    EXPECT_TRUE(std::filesystem::is_empty(usable)) << "the check created the file";

    if (!std::filesystem::exists(binary("envdesign-bridge")))
        GTEST_SKIP() << "envdesign-bridge is not built (no DDS)";
    std::string good = source(RESTAURANT);
    std::string bad = write("bad.textproto", "alpha: 1\nunknown_field: 2\n");
    std::string none = write("none.conf", "log-level = info\n");
    r = check("envdesign-bridge", none, "--problem ok=" + good + " --problem broken=" + bad);
    EXPECT_EQ(r.code, 2) << r.output;
    EXPECT_NE(r.output.find("envdesign-bridge: --problem broken: " + bad + ":2:"),
              std::string::npos)
        << r.output;
    r = check("envdesign-bridge", conf, "--problem ok=" + good);
    EXPECT_EQ(r.code, 2) << r.output;
    EXPECT_NE(r.output.find("envdesign-bridge: --state-dir: "), std::string::npos) << r.output;
    r = check("envdesign-bridge", none, "--problem ok=" + good + " --state-dir " + usable.string());
    EXPECT_EQ(r.code, 0) << r.output;
    EXPECT_NE(r.output.find("configuration OK"), std::string::npos) << r.output;
}

} // namespace
} // namespace envdesign::e2e
