// Hostile traffic against real service processes (issue 10, the crash and memory findings;
// authentication is tested on its own): a deep JSON spec must not crash the coordinator,
// forged spec chunks claiming huge specs must not grow a planner, and neither must forged or
// whole LCM messages of hundreds of megabytes (issue 21).

#include "local_cluster.h"

#include "bus/codec.h"
#include "bus/udpm_guard.h"
#include "envdesign/design_request_t.hpp"
#include "envdesign/design_result_t.hpp"
#include "envdesign/evaluation_t.hpp"
#include "envdesign/job_t.hpp"
#include "envdesign/spec_chunk_t.hpp"

#include <envdesign/client/client.h>

#include <arpa/inet.h>
#include <atomic>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iostream>
#include <netinet/in.h>
#include <sys/socket.h>

namespace envdesign::e2e {
namespace {

client::Result restaurant_design(const LocalCluster &cluster) {
    client::Options options;
    options.give_up_after_s = 10;
    return client::run_design_remote(source(RESTAURANT), cluster.url(), options);
}

TEST(Hostile, DeepJsonRequestIsBadInputAndTheCoordinatorLives) {
    LocalCluster cluster(1);
    bus::Bus bus(cluster.url(), std::make_shared<spdlog::logger>(
                                    "attacker", std::make_shared<spdlog::sinks::null_sink_mt>()));
    std::optional<envdesign::design_result_t> answer;
    auto sub = bus.subscribe<envdesign::design_result_t>(bus::RESULT,
                                                         [&](const envdesign::design_result_t &r) {
                                                             if (r.request_id == 77)
                                                                 answer = r;
                                                         });
    envdesign::design_request_t request{};
    request.request_id = 77;
    request.sender = "attacker";
    request.spec.name = "deep.json";
    request.spec.text = "{\"task\": " + std::string(100'000, '[') + std::string(100'000, ']') + "}";
    request.time_limit_s = -1;
    request.max_design_size = -1;
    bus.publish(bus::REQUEST, request);
    auto until = std::chrono::steady_clock::now() + std::chrono::seconds(20);
    while (!answer && std::chrono::steady_clock::now() < until)
        bus.handle(std::chrono::milliseconds(50));
    ASSERT_TRUE(answer) << cluster.logs();
    EXPECT_EQ(answer->exit_code, 2);
    EXPECT_NE(answer->error.find("deep.json:1:109: error:"), std::string::npos) << answer->error;
    EXPECT_TRUE(cluster.coordinator().running()) << cluster.logs();
    EXPECT_EQ(restaurant_design(cluster).exit_code, 0) << cluster.logs();
}

envdesign::spec_chunk_t last_chunk_of(int number, std::int32_t claimed_bytes) {
    envdesign::spec_chunk_t c{};
    c.sender = "attacker";
    c.spec_hash = std::string(64, 'b');
    c.spec_hash.replace(0, std::to_string(number).size(), std::to_string(number));
    c.total_bytes = claimed_bytes;
    c.num_chunks = static_cast<std::int16_t>((claimed_bytes + 31'999) / 32'000);
    c.chunk_index = static_cast<std::int16_t>(c.num_chunks - 1);
    c.num_bytes = static_cast<std::int16_t>(claimed_bytes - c.chunk_index * 32'000);
    c.data.assign(static_cast<std::size_t>(c.num_bytes), 'x');
    return c;
}

// Two forged chunks of ~213 bytes claiming 1 GB each took a planner from 9 MB to 2 GB.
// Now: chunks of specs beyond the limit are refused, and within it only what arrived is held.
TEST(Hostile, ChunkBombLeavesThePlannerSmall) {
    LocalCluster cluster(1);
    pid_t planner = cluster.planner(0).pid();
    long before = resident_kib(planner);
    ASSERT_GT(before, 0);
    bus::Bus bus(cluster.url(), std::make_shared<spdlog::logger>(
                                    "attacker", std::make_shared<spdlog::sinks::null_sink_mt>()));
    bus.publish(bus::SPEC, last_chunk_of(1, 31'249 * 32'000 + 100)); // ~1 GB
    bus.publish(bus::SPEC, last_chunk_of(2, 31'249 * 32'000 + 100));
    for (int n = 3; n < 200; ++n) // within the default 16 MiB each
        bus.publish(bus::SPEC, last_chunk_of(n, 500 * 32'000 + 100));
    bus.handle(std::chrono::milliseconds(1000));
    long after = resident_kib(planner);
    EXPECT_LT(after - before, 50 * 1024)
        << "planner grew from " << before << " to " << after << " KiB";
    EXPECT_TRUE(cluster.planner(0).running()) << cluster.logs();
    EXPECT_EQ(restaurant_design(cluster).exit_code, 0) << cluster.logs();
}

// A string length of INT_MIN in a message: lcm-gen 1.3.1's decoder overflowed and read
// gigabytes past the datagram (found by the planner fuzz target). Now it is a malformed
// message: counted and dropped, by the coordinator and a planner alike.
TEST(Hostile, NegativeStringLengthIsMalformedNotACrash) {
    LocalCluster cluster(1);
    bus::Bus bus(cluster.url(), std::make_shared<spdlog::logger>(
                                    "attacker", std::make_shared<spdlog::sinks::null_sink_mt>()));
    envdesign::job_t job{};
    job.sender = "coordinator";
    job.planner = "planner-0";
    envdesign::design_request_t request{};
    request.request_id = 5;
    request.sender = "attacker";
    // Fingerprint (8), utime (8), request_id (8), then the sender's length.
    auto forged = [](std::string bytes) { return bytes.replace(24, 4, "\x80\0\0\0", 4); };
    std::string bad_job = forged(bus::encode_message(job));
    std::string bad_request = forged(bus::encode_message(request));
    bus.publish_raw(bus::JOB, bad_job.data(), static_cast<int>(bad_job.size()));
    bus.publish_raw(bus::REQUEST, bad_request.data(), static_cast<int>(bad_request.size()));
    bus.handle(std::chrono::milliseconds(500));
    EXPECT_TRUE(cluster.coordinator().running()) << cluster.logs();
    EXPECT_TRUE(cluster.planner(0).running()) << cluster.logs();
    EXPECT_EQ(restaurant_design(cluster).exit_code, 0) << cluster.logs();
}

// An array length of 0x15000000 in a 200-byte evaluation_t: lcm-gen's decoder resized
// optimal_actions to it before reading a byte of them, 11 GB of std::string (found by the
// wire_numbers fuzz target). Now a length above the bytes left is a malformed message: the
// coordinator stays small and keeps working.
TEST(Hostile, AnArrayLengthBeyondTheMessageIsMalformedNotAnAllocation) {
    LocalCluster cluster(1);
    bus::Bus bus(cluster.url(), std::make_shared<spdlog::logger>(
                                    "attacker", std::make_shared<spdlog::sinks::null_sink_mt>()));
    envdesign::evaluation_t e{};
    e.sender = "planner-0";
    e.coordinator = "coordinator";
    e.has_optimal_actions = true;
    e.optimal_actions = {"a"};
    e.optimal_actions_length = 1;
    std::string bytes = bus::encode_message(e);
    // has_optimal_actions, the length 1, then "a" (its length 2 counts the NUL).
    const std::string actions("\x01\0\0\0\x01\0\0\0\x02"
                              "a\0",
                              11);
    auto at = bytes.find(actions);
    ASSERT_NE(at, std::string::npos);
    ASSERT_EQ(bytes.find(actions, at + 1), std::string::npos);
    bytes.replace(at + 1, 4, "\x15\0\0\0", 4);
    ASSERT_LT(bytes.size(), 300u);
    for (int i = 0; i < 3; ++i)
        bus.publish_raw(bus::EVALUATION, bytes.data(), static_cast<int>(bytes.size()));
    bus.handle(std::chrono::milliseconds(500));
    ASSERT_TRUE(cluster.coordinator().running()) << cluster.logs();
    EXPECT_LT(resident_kib(cluster.coordinator().pid()), 400 * 1024) << cluster.logs();
    EXPECT_EQ(restaurant_design(cluster).exit_code, 0) << cluster.logs();
}

// LCM's own fragment reassembly (LCM 1.3.1's udpm transport, below the bus): the first
// fragment of a message names its total size, and LCM sets aside a buffer of that size per
// sender. Forged messages from 300 senders that never complete, each claiming 1.5 MB and
// filling 600 KB of it, would hold 180 MB if nothing bounded the buffers; LCM's store keeps
// at most 16 MiB of claimed buffers (least recently updated dropped first), and a claim of
// 200 MB (below LCM's 256 MiB limit) only reserves address space, so the services stay
// small and keep working.
class FragmentForger {
public:
    explicit FragmentForger(const std::string &url) {
        // udpm://GROUP:PORT?...
        auto host = url.find("//") + 2, colon = url.find(':', host);
        group_.sin_family = AF_INET;
        group_.sin_port = htons(static_cast<std::uint16_t>(std::stoi(url.substr(colon + 1))));
        inet_pton(AF_INET, url.substr(host, colon - host).c_str(), &group_.sin_addr);
    }
    // One sender (its own socket, so its own source port): the first fragment of a
    // `claimed`-byte message on `channel`, then `more` fragments of `size` bytes spread over it.
    void send_message(const std::string &channel, std::uint32_t claimed, int more,
                      std::size_t size) {
        int fd = ::socket(AF_INET, SOCK_DGRAM, 0);
        unsigned char ttl = 0;
        ::setsockopt(fd, IPPROTO_IP, IP_MULTICAST_TTL, &ttl, sizeof ttl);
        std::uint16_t fragments = static_cast<std::uint16_t>(claimed / size + 1);
        send(fd, fragment(0, fragments, claimed, 0, channel + std::string(1, '\0') + "x"));
        // The rest carry the same sequence number: LCM drops a buffer at a new one.
        for (int i = 1; i <= more; ++i) {
            auto no = static_cast<std::uint16_t>(i * (fragments - 2) / more); // all inside
            send(fd, fragment(no, fragments, claimed, static_cast<std::uint32_t>(no * size),
                              std::string(size, 'y'), false));
        }
        ::close(fd);
    }

    // A real fragmented message: `payload` in fragments of `size` bytes.
    void send_complete(const std::string &channel, const std::string &payload, std::size_t size) {
        int fd = ::socket(AF_INET, SOCK_DGRAM, 0);
        unsigned char ttl = 0;
        ::setsockopt(fd, IPPROTO_IP, IP_MULTICAST_TTL, &ttl, sizeof ttl);
        auto of = static_cast<std::uint16_t>((payload.size() + size - 1) / size);
        auto total = static_cast<std::uint32_t>(payload.size());
        ++seqno_;
        for (std::uint16_t no = 0; no < of; ++no) {
            std::string part = payload.substr(no * size, size);
            if (no == 0)
                part = channel + std::string(1, '\0') + part;
            send(fd, fragment(no, of, total, static_cast<std::uint32_t>(no * size), part, false));
        }
        ::close(fd);
    }

private:
    std::string fragment(std::uint16_t no, std::uint16_t of, std::uint32_t size,
                         std::uint32_t offset, const std::string &payload, bool next = true) {
        std::string d(20, '\0');
        auto put32 = [&](int at, std::uint32_t v) {
            v = htonl(v);
            std::memcpy(d.data() + at, &v, 4);
        };
        auto put16 = [&](int at, std::uint16_t v) {
            v = htons(v);
            std::memcpy(d.data() + at, &v, 2);
        };
        put32(0, 0x4c433033); // "LC03": a fragment
        put32(4, next ? ++seqno_ : seqno_);
        put32(8, size);
        put32(12, offset);
        put16(16, no);
        put16(18, of);
        return d + payload;
    }
    void send(int fd, const std::string &datagram) {
        ::sendto(fd, datagram.data(), datagram.size(), 0, reinterpret_cast<sockaddr *>(&group_),
                 sizeof group_);
        std::this_thread::sleep_for(std::chrono::microseconds(300)); // within the socket buffer
    }
    sockaddr_in group_{};
    std::uint32_t seqno_ = 1000;
};

TEST(Hostile, ForgedLcmFragmentsClaimingHugeMessagesLeaveTheServicesSmall) {
    LocalCluster cluster(1);
    pid_t planner = cluster.planner(0).pid(), coordinator = cluster.coordinator().pid();
    long planner_before = resident_kib(planner), coordinator_before = resident_kib(coordinator);
    ASSERT_GT(planner_before, 0);
    FragmentForger forger(cluster.url());
    // The framing is LCM's: a real fragmented message in the same form is delivered whole.
    bus::Bus listener(cluster.url(),
                      std::make_shared<spdlog::logger>(
                          "listener", std::make_shared<spdlog::sinks::null_sink_mt>()));
    std::string heard;
    auto sub = listener.subscribe_raw("FORGER_CHECK", [&](const void *data, int size) {
        heard.assign(static_cast<const char *>(data), static_cast<std::size_t>(size));
    });
    std::string payload(150'000, 'p');
    payload[149'999] = 'q';
    forger.send_complete("FORGER_CHECK", payload, 60'000);
    for (int i = 0; i < 50 && heard.empty(); ++i)
        listener.handle(std::chrono::milliseconds(20));
    ASSERT_EQ(heard, payload);
    for (int sender = 0; sender < 300; ++sender)
        forger.send_message(sender % 2 ? bus::SPEC : bus::REQUEST,
                            sender % 10 ? 1'500'000 : 200u << 20, 10, 60'000);
    std::this_thread::sleep_for(std::chrono::milliseconds(500));
    long planner_after = resident_kib(planner), coordinator_after = resident_kib(coordinator);
    std::cerr << "resident KiB, planner " << planner_before << " -> " << planner_after
              << ", coordinator " << coordinator_before << " -> " << coordinator_after << "\n";
    EXPECT_LT(planner_after - planner_before, 64 * 1024)
        << "planner grew from " << planner_before << " to " << planner_after << " KiB";
    EXPECT_LT(coordinator_after - coordinator_before, 64 * 1024)
        << "coordinator grew from " << coordinator_before << " to " << coordinator_after << " KiB";
    EXPECT_TRUE(cluster.planner(0).running()) << cluster.logs();
    EXPECT_TRUE(cluster.coordinator().running()) << cluster.logs();
    EXPECT_EQ(restaurant_design(cluster).exit_code, 0) << cluster.logs();
}

// Datagrams the kernel dropped at process `pid`'s UDP sockets bound to `port` on the wildcard
// address (LCM's receive socket): by its socket filter, or with its receive buffer full. The
// last column of /proc/PID/net/udp, for the inodes of the process's sockets.
long long udp_drops(pid_t pid, std::uint16_t port) {
    const std::string proc = "/proc/" + std::to_string(pid);
    std::set<std::string> inodes;
    for (const auto &fd : std::filesystem::directory_iterator(proc + "/fd")) {
        std::error_code error;
        std::string target = std::filesystem::read_symlink(fd.path(), error).string();
        if (target.rfind("socket:[", 0) == 0)
            inodes.insert(target.substr(8, target.size() - 9));
    }
    char wildcard[16];
    std::snprintf(wildcard, sizeof wildcard, "00000000:%04X", port);
    std::ifstream table(proc + "/net/udp");
    std::string line;
    std::getline(table, line); // the header
    long long drops = 0;
    while (std::getline(table, line)) {
        // sl local remote st tx:rx tr:when retrnsmt uid timeout inode ref pointer drops
        std::istringstream fields(line);
        std::string field[12];
        long long dropped = 0;
        for (auto &f : field)
            fields >> f;
        fields >> dropped;
        if (field[1] == wildcard && inodes.count(field[9]))
            drops += dropped;
    }
    return drops;
}

// One whole LCM message of 250 MB (unsigned) on the channel the coordinator takes requests
// on, in LCM's fragments, paced so that none is lost on the way: LCM reassembled it before any
// check of ours, and the coordinator went to 506 MB and stalled for over a second. The bus's
// socket filter (bus/udpm_guard.h) drops every fragment of a message beyond BUS_MAX_MESSAGE
// (64 MiB) in the kernel, which counts them as drops of the coordinator's sockets.
TEST(Hostile, AWhole250MegabyteMessageIsDroppedUnassembledAndTheCoordinatorAnswers) {
    LocalCluster cluster(1);
    pid_t coordinator = cluster.coordinator().pid();
    const std::uint16_t port = *bus::udpm_port(cluster.url());
    std::string bytes;
    {
        envdesign::design_request_t request{};
        request.utime = bus::now_utime();
        request.request_id = 9;
        request.sender = "big";
        request.spec.name = "big.textproto";
        request.spec.text.assign(250'000'000, 'x');
        request.time_limit_s = -1;
        request.max_design_size = -1;
        bytes = bus::encode_message(request);
    }
    ASSERT_GT(bytes.size(), bus::BUS_MAX_MESSAGE);
    ASSERT_LT(bytes.size(), bus::LCM_MAX_MESSAGE);
    const long before = resident_kib(coordinator);
    const long long drops_before = udp_drops(coordinator, port);
    std::atomic<bool> done{false};
    std::atomic<long> most{before};
    std::thread sampler([&] {
        while (!done) {
            most = std::max(most.load(), resident_kib(coordinator));
            std::this_thread::sleep_for(std::chrono::milliseconds(10));
        }
    });
    auto start = std::chrono::steady_clock::now();
    FragmentForger(cluster.url()).send_complete(bus::REQUEST, bytes, 60'000);
    const double send_s = seconds_since(start);
    std::this_thread::sleep_for(std::chrono::milliseconds(500)); // what arrived is handled
    const long long dropped = udp_drops(coordinator, port) - drops_before;

    // A small design right after: answered at once.
    client::Options options;
    options.give_up_after_s = 10;
    start = std::chrono::steady_clock::now();
    client::Result result = client::run_design_remote(source(RESTAURANT), cluster.url(), options);
    const double design_s = seconds_since(start);
    done = true;
    sampler.join();
    const long after = resident_kib(coordinator);
    std::cout << "a " << bytes.size() << "-byte message sent in " << send_s << " s: " << dropped
              << " fragments dropped at the coordinator's socket; coordinator RSS " << before / 1024
              << " -> at most " << most / 1024 << " -> " << after / 1024
              << " MiB; the restaurant answered " << design_s << " s after\n";
    // Every fragment was dropped (at each receive socket of the coordinator), none reassembled.
    EXPECT_GE(dropped, static_cast<long long>(bytes.size() / 60'000)) << cluster.logs();
    EXPECT_LT(most - before, 64 * 1024) << "KiB" << cluster.logs();
    EXPECT_LT(most, 400 * 1024) << "KiB" << cluster.logs();
    EXPECT_TRUE(cluster.coordinator().running()) << cluster.logs();
    EXPECT_EQ(result.exit_code, 0) << result.error << cluster.logs();
    EXPECT_LT(design_s, 5.0) << cluster.logs();
}

} // namespace
} // namespace envdesign::e2e
