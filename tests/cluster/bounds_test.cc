// What one client or a hostile sender can make the coordinator and planner cores hold
// (issue 10): requests open per client and waiting in total (answered "busy"), spec sizes,
// specs being assembled from chunks, progress only for searching requests, deep JSON.

#include "harness.h"

#include "cluster/planner_specs.h"

#include <atomic>

namespace envdesign::cluster::testing {
namespace {

const char *RESTAURANT = "examples/restaurant/c-two-tasks-t10.textproto";

envdesign::design_request_t from(const std::string &client, std::int64_t id) {
    auto r = request_of(in_repo(RESTAURANT), id);
    r.sender = client;
    r.time_limit_s = 30; // no planner: it stays open until the test ends
    return r;
}

// 1000 requests from one process once made a 0.06 s request wait 24 s: now a client has at
// most max_per_client open, and at most max_waiting wait in all; the rest hear "busy".
TEST(Bounds, RequestsBeyondTheLimitsAreAnsweredBusy) {
    MemqCluster cluster(0, 1, {}, [](CoordinatorConfig &c) {
        c.max_active = 1;
        c.max_waiting = 1;
        c.max_per_client = 2;
    });
    cluster.bus().publish(bus::REQUEST, from("a", 1)); // searches
    cluster.bus().publish(bus::REQUEST, from("a", 2)); // waits
    auto third = cluster.request(from("a", 3), 5);     // a has 2 open
    EXPECT_EQ(third.exit_code, 1);
    EXPECT_NE(third.error.find("busy"), std::string::npos) << third.error;
    auto other = cluster.request(from("b", 4), 5); // the one waiting slot is taken
    EXPECT_EQ(other.exit_code, 1);
    EXPECT_NE(other.error.find("requests are waiting"), std::string::npos) << other.error;
    EXPECT_FALSE(cluster.answered(1));
    EXPECT_FALSE(cluster.answered(2));
    EXPECT_EQ(cluster.coordinator().stats().busy, 2);
    EXPECT_EQ(cluster.coordinator().stats().open, 2);
}

// `r` as the process `origin` sends it (its bus's origin trailer, bus/auth.h).
void publish_from(bus::Bus &bus, std::uint64_t origin, const envdesign::design_request_t &r) {
    std::string bytes = bus::encode_message(r);
    std::string wire = bus::with_origin(origin, bytes.data(), bytes.size());
    bus.publish_raw(bus::REQUEST, wire.data(), static_cast<int>(wire.size()));
}

// --max-per-client counts by process and by name: forty names of one process once each had
// 8 (issue 21), and a name's requests from several buses (the client library opens one per
// call) are still that name's.
TEST(Bounds, APerClientLimitCountsByProcessAndByName) {
    MemqCluster cluster(0, 1, {}, [](CoordinatorConfig &c) {
        c.max_active = 1;
        c.max_per_client = 2;
    });
    constexpr std::uint64_t A = 0xa, B = 0xb, C = 0xc, D = 0xd;
    publish_from(cluster.bus(), A, from("a", 1)); // process A: searches
    publish_from(cluster.bus(), A, from("b", 2)); // process A: waits
    publish_from(cluster.bus(), A, from("c", 3));
    auto third = cluster.wait(3, 5);
    EXPECT_EQ(third.exit_code, 1);
    EXPECT_NE(third.error.find("busy"), std::string::npos) << third.error;
    EXPECT_NE(third.error.find("process 000000000000000a"), std::string::npos) << third.error;
    publish_from(cluster.bus(), B, from("c", 4)); // another process: taken
    publish_from(cluster.bus(), C, from("c", 5)); // name c's second: taken
    publish_from(cluster.bus(), D, from("c", 6));
    auto by_name = cluster.wait(6, 5);
    EXPECT_EQ(by_name.exit_code, 1);
    EXPECT_NE(by_name.error.find("requests of c "), std::string::npos) << by_name.error;
    EXPECT_EQ(cluster.coordinator().stats().busy, 2);
    EXPECT_EQ(cluster.coordinator().stats().open, 4);
    for (std::int64_t id : {1, 2, 4, 5})
        EXPECT_FALSE(cluster.answered(id)) << id;
}

// Keep-alives for the searching request only; the waiting one is told when repeated.
TEST(Bounds, ProgressOnlyForSearchingRequests) {
    MemqCluster cluster(0, 1, {}, [](CoordinatorConfig &c) { c.max_active = 1; });
    std::mutex mutex;
    std::map<std::int64_t, int> heard;
    auto sub = cluster.bus().subscribe<envdesign::design_progress_t>(
        bus::PROGRESS, [&](const envdesign::design_progress_t &p) {
            std::lock_guard lock(mutex);
            ++heard[p.request_id];
        });
    cluster.bus().publish(bus::REQUEST, from("a", 1));
    cluster.bus().publish(bus::REQUEST, from("a", 2));
    std::this_thread::sleep_for(std::chrono::milliseconds(1500));
    {
        std::lock_guard lock(mutex);
        EXPECT_GE(heard[1], 2);
        EXPECT_EQ(heard[2], 0);
    }
    cluster.bus().publish(bus::REQUEST, from("a", 2)); // the client's resend
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    std::lock_guard lock(mutex);
    EXPECT_EQ(heard[2], 1);
}

TEST(Bounds, ASpecLargerThanTheLimitIsBadInput) {
    MemqCluster cluster(1, 1, {}, [](CoordinatorConfig &c) { c.max_spec_bytes = 1 << 20; });
    auto request = request_of(in_repo(RESTAURANT), 7);
    request.spec.files[0].content += "\n;" + std::string(1 << 20, 'x');
    auto result = cluster.request(request, 10);
    EXPECT_EQ(result.exit_code, 2);
    EXPECT_NE(result.error.find("more than the 1048576 taken"), std::string::npos) << result.error;
}

// A spec named *.json nesting arrays 100 000 deep crashed the coordinator (SIGSEGV); now it
// is bad input naming the line and column, and the coordinator goes on serving.
TEST(Bounds, DeepJsonIsBadInputAndTheCoordinatorGoesOn) {
    MemqCluster cluster(1);
    auto deep = request_of(in_repo(RESTAURANT), 8);
    deep.spec.name = "deep.json";
    deep.spec.text = "{\"task\": " + std::string(100'000, '[') + std::string(100'000, ']') + "}";
    auto result = cluster.request(deep, 30);
    EXPECT_EQ(result.exit_code, 2);
    EXPECT_NE(result.error.find("deep.json:1:109: error:"), std::string::npos) << result.error;
    auto fine =
        cluster.request(request_of(in_repo("examples/restaurant/a-one-task-t1.textproto"), 9));
    EXPECT_EQ(fine.exit_code, 0) << fine.error;
}

envdesign::spec_chunk_t forged_chunk(int number, std::int32_t claimed_bytes, int index) {
    envdesign::spec_chunk_t c{};
    c.spec_hash = std::string(63, 'a') + static_cast<char>('a' + number % 6);
    c.spec_hash[0] = static_cast<char>('0' + number % 10);
    c.spec_hash[1] = static_cast<char>('0' + number / 10 % 10);
    c.total_bytes = claimed_bytes;
    c.num_chunks = static_cast<std::int16_t>((claimed_bytes + CHUNK_BYTES - 1) / CHUNK_BYTES);
    c.chunk_index = static_cast<std::int16_t>(index);
    c.num_bytes = static_cast<std::int16_t>(std::min<long long>(
        CHUNK_BYTES, claimed_bytes - static_cast<long long>(index) * CHUNK_BYTES));
    c.data.assign(static_cast<std::size_t>(c.num_bytes), 'x');
    return c;
}

// Two 213-byte chunks claiming 1 GB each once made a planner allocate 2 GB for good.
TEST(Bounds, ChunksClaimingHugeSpecsAreRefused) {
    PlannerSpecs specs(4);
    std::string why;
    // The last chunk of a spec claiming ~1 GB: 200 bytes of data.
    std::int32_t claimed = 31'249 * CHUNK_BYTES + 200;
    EXPECT_EQ(specs.add_chunk(forged_chunk(1, claimed, 31'249), why), PlannerSpecs::Added::BAD);
    EXPECT_NE(why.find("more than the"), std::string::npos) << why;
    EXPECT_EQ(specs.incomplete_bytes(), 0u);
}

// Within the size limit: only what arrived is held, for at most max_incomplete specs and
// max_incomplete_bytes together, and not for longer than expire_s.
TEST(Bounds, SpecsBeingAssembledAreBounded) {
    SpecLimits limits;
    limits.max_spec_bytes = 100 * CHUNK_BYTES;
    limits.max_incomplete = 3;
    limits.max_incomplete_bytes = 5 * CHUNK_BYTES;
    limits.expire_s = 0.2;
    PlannerSpecs specs(4, limits);
    std::string why;
    for (int n = 0; n < 20; ++n)
        for (int i = 0; i < 3; ++i)
            specs.add_chunk(forged_chunk(n, 100 * CHUNK_BYTES, i), why);
    EXPECT_LE(specs.incomplete(), 3);
    EXPECT_LE(specs.incomplete_bytes(), 5u * CHUNK_BYTES);
    EXPECT_GT(specs.incomplete_bytes(), 0u);
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    specs.expire();
    EXPECT_EQ(specs.incomplete(), 0);
    EXPECT_EQ(specs.incomplete_bytes(), 0u);
}

} // namespace
} // namespace envdesign::cluster::testing
