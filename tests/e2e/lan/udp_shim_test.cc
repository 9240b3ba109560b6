// The fault-injecting LD_PRELOAD shim (udp_shim.cc) on its own: udp_sender sends numbered
// datagrams through it to a real UDP socket here, and what arrives is counted: losses within
// binomial bounds and equal to the shim's own count, duplicates and order changes seen, the
// same faults for the same seed, every wrapped call affected, unix sockets untouched.

#include "../../support/process.h"

#include <gtest/gtest.h>

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <sys/un.h>
#include <unistd.h>

#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <map>
#include <set>
#include <thread>

namespace envdesign::testing {
namespace {

namespace fs = std::filesystem;
using namespace std::chrono_literals;

const std::string SHIM = ENVDESIGN_UDP_SHIM;
const std::string SENDER = std::string(ENVDESIGN_BIN_DIR) + "/udp_sender";
constexpr std::uint32_t N = 2000;

// What arrived, in order of arrival.
struct Received {
    std::vector<std::uint32_t> order;
    std::vector<std::chrono::steady_clock::time_point> at; // when each arrived
    std::size_t unique() const {
        return std::set<std::uint32_t>(order.begin(), order.end()).size();
    }
    std::size_t duplicates() const { return order.size() - unique(); }
    // First arrivals of a number smaller than one that arrived before it.
    std::size_t overtaken() const {
        std::set<std::uint32_t> seen;
        std::size_t n = 0;
        std::int64_t highest = -1;
        for (std::uint32_t s : order) {
            if (seen.insert(s).second && static_cast<std::int64_t>(s) < highest)
                ++n;
            highest = std::max<std::int64_t>(highest, s);
        }
        return n;
    }
};

// The shim's counts file: name=value pairs.
std::map<std::string, long long> read_counts(const fs::path &file) {
    std::ifstream in(file);
    std::map<std::string, long long> counts;
    std::string pair;
    while (in >> pair) {
        auto eq = pair.find('=');
        if (eq != std::string::npos)
            counts[pair.substr(0, eq)] = std::stoll(pair.substr(eq + 1));
    }
    return counts;
}

class UdpShimTest : public ::testing::Test {
protected:
    void SetUp() override {
        dir = fs::path(::testing::TempDir()) / ("udp-shim-" + std::to_string(getpid()));
        fs::create_directories(dir);
    }
    void TearDown() override {
        if (!HasFailure())
            fs::remove_all(dir);
    }

    // Runs udp_sender with the shim and `env`; returns what a socket here received.
    Received run(const std::vector<std::string> &env, const std::string &call = "sendmsg",
                 std::uint32_t count = N, const std::string &linger_ms = "0") {
        int fd = socket(AF_INET, SOCK_DGRAM, 0);
        int buffer = 4 << 20;
        setsockopt(fd, SOL_SOCKET, SO_RCVBUF, &buffer, sizeof buffer);
        sockaddr_in at{};
        at.sin_family = AF_INET;
        at.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
        EXPECT_EQ(bind(fd, reinterpret_cast<sockaddr *>(&at), sizeof at), 0);
        socklen_t size = sizeof at;
        getsockname(fd, reinterpret_cast<sockaddr *>(&at), &size);
        Received got = receive(fd,
                               {SENDER, "udp", std::to_string(ntohs(at.sin_port)),
                                std::to_string(count), call, linger_ms},
                               env);
        close(fd);
        return got;
    }

    Received receive(int fd, std::vector<std::string> argv, std::vector<std::string> env) {
        env.push_back("LD_PRELOAD=" + SHIM);
        env.push_back("ENVDESIGN_SHIM_COUNTS=" + counts_file().string());
        timeval timeout{0, 100000};
        setsockopt(fd, SOL_SOCKET, SO_RCVTIMEO, &timeout, sizeof timeout);
        Received got;
        std::atomic<bool> sender_done{false};
        std::thread receiver([&] {
            // Until the sender is done and 300 ms passed without a datagram.
            int quiet = 0;
            while (!sender_done || quiet < 3) {
                std::uint32_t sequence = 0;
                if (recv(fd, &sequence, sizeof sequence, 0) == sizeof sequence) {
                    got.order.push_back(sequence);
                    got.at.push_back(std::chrono::steady_clock::now());
                    quiet = 0;
                } else {
                    quiet += sender_done ? 1 : 0;
                }
            }
        });
        Process sender(argv, env, (dir / "sender.log").string());
        auto code = sender.wait(30s);
        sender_done = true;
        receiver.join();
        EXPECT_EQ(code, std::optional<int>(0)) << sender.output();
        last_output = sender.output();
        return got;
    }

    fs::path counts_file() const { return dir / "counts.txt"; }

    fs::path dir;
    std::string last_output;
};

// Within 5 standard deviations of a binomial(n, p) count.
void expect_binomial(double count, double n, double p, const char *what) {
    double sd = std::sqrt(n * p * (1 - p));
    EXPECT_NEAR(count, n * p, 5 * sd) << what;
}

TEST_F(UdpShimTest, WithoutRatesEverythingArrivesOnceInOrder) {
    Received got = run({});
    ASSERT_EQ(got.order.size(), N);
    for (std::uint32_t i = 0; i < N; ++i)
        ASSERT_EQ(got.order[i], i);
}

TEST_F(UdpShimTest, LossDropsTheShareAskedAndCountsEachDrop) {
    Received got = run({"ENVDESIGN_SHIM_LOSS=20", "ENVDESIGN_SHIM_SEED=1"});
    expect_binomial(N - got.unique(), N, 0.2, "datagrams lost");
    EXPECT_EQ(got.duplicates(), 0u);
    EXPECT_EQ(got.overtaken(), 0u);
    auto counts = read_counts(counts_file());
    EXPECT_EQ(counts["datagrams"], N);
    EXPECT_EQ(counts["dropped"], static_cast<long long>(N - got.unique()));
}

TEST_F(UdpShimTest, DuplicationSendsCopiesRightAfterTheOriginal) {
    Received got = run({"ENVDESIGN_SHIM_DUPLICATE=20", "ENVDESIGN_SHIM_SEED=2"});
    EXPECT_EQ(got.unique(), N);
    expect_binomial(static_cast<double>(got.duplicates()), N, 0.2, "duplicates");
    EXPECT_EQ(read_counts(counts_file())["duplicated"], static_cast<long long>(got.duplicates()));
    for (std::size_t i = 1; i < got.order.size(); ++i) {
        if (got.order[i] != got.order[i - 1] + 1) {
            ASSERT_EQ(got.order[i], got.order[i - 1]) << "a copy that is not right after";
        }
    }
}

TEST_F(UdpShimTest, ReorderingSendsAHeldDatagramAfterTheNextOne) {
    Received got = run({"ENVDESIGN_SHIM_REORDER=20", "ENVDESIGN_SHIM_SEED=3"});
    EXPECT_EQ(got.unique(), N);
    EXPECT_EQ(got.duplicates(), 0u);
    // A held datagram is not held again at once, so about p / (1 + p) of them are.
    expect_binomial(static_cast<double>(got.overtaken()), N, 0.2 / 1.2, "order changes");
    auto counts = read_counts(counts_file());
    EXPECT_EQ(counts["reordered"], static_cast<long long>(got.overtaken()));
    // Each swap is with the very next datagram.
    for (std::size_t i = 1; i < got.order.size(); ++i) {
        if (got.order[i] < got.order[i - 1]) {
            ASSERT_EQ(got.order[i] + 1, got.order[i - 1]);
        }
    }
}

// With every datagram held if it can be: pairs swap, and the last, with nothing after it,
// goes out when its hold time has passed (the sender stays 2 s more), or at the sender's exit.
TEST_F(UdpShimTest, AHeldDatagramWithNothingAfterItGoesOutAfterTheHoldTime) {
    const std::vector<std::uint32_t> swapped = {1, 0, 3, 2, 5, 4, 7, 6, 9, 8, 10};
    Received got =
        run({"ENVDESIGN_SHIM_REORDER=100", "ENVDESIGN_SHIM_HOLD_MS=200"}, "sendto", 11, "2000");
    ASSERT_EQ(got.order, swapped);
    EXPECT_LT(got.at.back() - got.at[9], 1s) << "not sent until the sender exited";
    auto counts = read_counts(counts_file());
    EXPECT_EQ(counts["reordered"], 5);
    EXPECT_EQ(counts["delayed"], 1);
    // Held far longer than the sender lives: out at its exit.
    got = run({"ENVDESIGN_SHIM_REORDER=100", "ENVDESIGN_SHIM_HOLD_MS=10000"}, "sendto", 11);
    EXPECT_EQ(got.order, swapped);
    EXPECT_EQ(read_counts(counts_file())["delayed"], 1);
}

TEST_F(UdpShimTest, TheSameSeedGivesTheSameFaults) {
    // A long hold: a held datagram goes out after the next one, never on a timer, so the
    // order does not depend on how fast a loaded machine runs the sender.
    std::vector<std::string> faults = {"ENVDESIGN_SHIM_LOSS=10", "ENVDESIGN_SHIM_DUPLICATE=10",
                                       "ENVDESIGN_SHIM_REORDER=10", "ENVDESIGN_SHIM_HOLD_MS=10000"};
    auto with_seed = [&](const std::string &seed) {
        auto env = faults;
        env.push_back("ENVDESIGN_SHIM_SEED=" + seed);
        return run(env).order;
    };
    auto first = with_seed("7");
    EXPECT_EQ(with_seed("7"), first);
    EXPECT_NE(with_seed("8"), first);
    EXPECT_NE(first.size(), N); // faults happened at all
}

TEST_F(UdpShimTest, EveryWrappedCallIsAffected) {
    for (const char *call : {"sendto", "sendmsg", "sendmmsg", "send"}) {
        Received got = run({"ENVDESIGN_SHIM_LOSS=50", "ENVDESIGN_SHIM_SEED=4"}, call, 400);
        expect_binomial(400.0 - got.unique(), 400, 0.5, call);
    }
}

// sd_notify and every other unix socket pass through untouched, whatever the rates.
TEST_F(UdpShimTest, UnixDatagramSocketsPassThrough) {
    int fd = socket(AF_UNIX, SOCK_DGRAM, 0);
    sockaddr_un at{};
    at.sun_family = AF_UNIX;
    std::string path = (dir / "unix.sock").string();
    std::strncpy(at.sun_path, path.c_str(), sizeof at.sun_path - 1);
    ASSERT_EQ(bind(fd, reinterpret_cast<sockaddr *>(&at), sizeof at), 0);
    Received got = receive(fd, {SENDER, "unix", path, "300"},
                           {"ENVDESIGN_SHIM_LOSS=100", "ENVDESIGN_SHIM_REORDER=100"});
    close(fd);
    ASSERT_EQ(got.order.size(), 300u);
    EXPECT_EQ(got.overtaken(), 0u);
}

TEST_F(UdpShimTest, ABadRateStopsTheProcessNamingTheVariable) {
    Process sender({SENDER, "udp", "9", "1", "sendto"},
                   {"LD_PRELOAD=" + SHIM, "ENVDESIGN_SHIM_LOSS=five"}, (dir / "bad.log").string());
    EXPECT_EQ(sender.wait(10s), std::optional<int>(2));
    EXPECT_NE(sender.output().find("udp_shim: ENVDESIGN_SHIM_LOSS=five: expected a percentage"),
              std::string::npos)
        << sender.output();
}

} // namespace
} // namespace envdesign::testing
