// Signing and verifying bus messages: tampering, foreign keys, replays, clocks, rotation, the
// bounded replay table; and a Bus with keys over real UDP that drops what a key did not sign.

#include "bus/auth.h"
#include "bus/bus.h"
#include "bus/channels.h"
#include "bus/log.h"
#include "envdesign/cancel_t.hpp"

#include "../support/ports.h"
#include "bus_test_support.h"

#include <gtest/gtest.h>
#include <spdlog/sinks/null_sink.h>

#include <unistd.h>

namespace envdesign::bus {
namespace {

KeyRing ring(std::initializer_list<std::pair<const char *, char>> keys) {
    KeyRing r;
    for (auto [id, fill] : keys)
        r.keys.push_back(Key{id, std::string(32, fill)});
    return r;
}

const std::string PAYLOAD = "an LCM message";
const std::string CH = "ENVDESIGN_RESULT";

std::optional<Drop> check(const Verifier &verifier, const std::string &wire, ReplayGuard &guard,
                          const std::string &channel = CH) {
    return verifier.verify(channel, wire.data(), wire.size(), guard, now_utime()).drop;
}

TEST(Auth, SignedMessageVerifiesAndKeepsItsPayloadInFront) {
    Signer signer(ring({{"k1", 'a'}}));
    Verifier verifier(ring({{"k1", 'a'}}));
    ReplayGuard guard;
    std::string wire = signer.sign(CH, PAYLOAD.data(), PAYLOAD.size());
    ASSERT_EQ(wire.size(), PAYLOAD.size() + TRAILER_SIZE);
    EXPECT_EQ(wire.substr(0, PAYLOAD.size()), PAYLOAD); // what lcm-spy decodes
    Verdict v = verifier.verify(CH, wire.data(), wire.size(), guard, now_utime());
    EXPECT_TRUE(v.ok());
    EXPECT_EQ(v.payload_size, PAYLOAD.size());
    EXPECT_EQ(v.sender, signer.sender());
}

TEST(Auth, EveryTamperedByteIsABadMac) {
    Signer signer(ring({{"k1", 'a'}}));
    Verifier verifier(ring({{"k1", 'a'}}));
    std::string wire = signer.sign(CH, PAYLOAD.data(), PAYLOAD.size());
    // Every byte but the key id (another id is unknown) and the magic (then unsigned).
    for (std::size_t i = 0; i < wire.size() - 4; ++i) {
        if (i >= PAYLOAD.size() && i < PAYLOAD.size() + 8)
            continue;
        std::string forged = wire;
        forged[i] ^= 0x01;
        ReplayGuard guard;
        EXPECT_EQ(check(verifier, forged, guard), Drop::BAD_MAC) << "byte " << i;
    }
    ReplayGuard guard;
    EXPECT_EQ(check(verifier, wire, guard, "ENVDESIGN_EVALUATION"), Drop::BAD_MAC)
        << "a message moved to another channel";
}

TEST(Auth, UnsignedShortOrForeignKeyedMessagesAreDropped) {
    Verifier verifier(ring({{"k1", 'a'}}));
    ReplayGuard guard;
    EXPECT_EQ(check(verifier, PAYLOAD, guard), Drop::UNAUTHENTICATED);
    EXPECT_EQ(check(verifier, "EDA1", guard), Drop::UNAUTHENTICATED);
    Signer same_id_other_secret(ring({{"k1", 'b'}}));
    EXPECT_EQ(check(verifier, same_id_other_secret.sign(CH, "x", 1), guard), Drop::BAD_MAC);
    Signer other_id(ring({{"k2", 'a'}}));
    EXPECT_EQ(check(verifier, other_id.sign(CH, "x", 1), guard), Drop::UNKNOWN_KEY);
}

TEST(Auth, ReplaysAreDroppedReorderingWithinTheWindowIsNot) {
    Signer signer(ring({{"k1", 'a'}}));
    Verifier verifier(ring({{"k1", 'a'}}));
    ReplayGuard guard;
    std::string first = signer.sign(CH, "1", 1);
    std::string second = signer.sign(CH, "2", 1);
    std::string third = signer.sign(CH, "3", 1);
    EXPECT_FALSE(check(verifier, first, guard));
    EXPECT_FALSE(check(verifier, third, guard));
    EXPECT_FALSE(check(verifier, second, guard)); // late, but new
    EXPECT_EQ(check(verifier, first, guard), Drop::REPLAYED);
    EXPECT_EQ(check(verifier, second, guard), Drop::REPLAYED);
    EXPECT_EQ(check(verifier, third, guard), Drop::REPLAYED);
    auto now = now_utime();
    std::string ancient = signer.sign_at(CH, "x", 1, 4, now);
    std::string ahead = signer.sign_at(CH, "x", 1, 4 + ReplayGuard::WINDOW, now);
    EXPECT_FALSE(check(verifier, ahead, guard));
    EXPECT_EQ(check(verifier, ancient, guard), Drop::REPLAYED) << "behind the window";
    ReplayGuard fresh; // another subscription (or process) sees it once
    EXPECT_FALSE(check(verifier, first, fresh));
}

TEST(Auth, MessagesOutsideTheClockToleranceAreStale) {
    Signer signer(ring({{"k1", 'a'}}));
    Verifier verifier(ring({{"k1", 'a'}}), 1'000'000);
    ReplayGuard guard;
    auto now = now_utime();
    EXPECT_EQ(check(verifier, signer.sign_at(CH, "x", 1, 1, now - 2'000'000), guard), Drop::STALE);
    EXPECT_EQ(check(verifier, signer.sign_at(CH, "x", 1, 2, now + 2'000'000), guard), Drop::STALE);
    EXPECT_FALSE(check(verifier, signer.sign_at(CH, "x", 1, 3, now - 500'000), guard));
}

TEST(Auth, RotationSignsWithTheFirstKeyAndVerifiesWithAny) {
    Signer old_sender(ring({{"old", 'o'}}));
    Signer rotated_sender(ring({{"new", 'n'}, {"old", 'o'}}));
    Verifier during(ring({{"new", 'n'}, {"old", 'o'}}));
    Verifier old_only(ring({{"old", 'o'}, {"new", 'n'}}));
    Verifier after(ring({{"new", 'n'}}));
    ReplayGuard g1, g2, g3;
    std::string from_old = old_sender.sign(CH, "x", 1);
    std::string from_new = rotated_sender.sign(CH, "x", 1);
    EXPECT_FALSE(check(during, from_old, g1));
    EXPECT_FALSE(check(during, from_new, g1));
    EXPECT_FALSE(check(old_only, from_new, g2)) << "step 1 of the rotation: every peer knows both";
    EXPECT_FALSE(check(after, from_new, g3));
    EXPECT_EQ(check(after, from_old, g3), Drop::UNKNOWN_KEY) << "the retired key";
}

TEST(Auth, TheReplayTableIsBoundedAndForgetsNoReplay) {
    Verifier verifier(ring({{"k1", 'a'}}));
    ReplayGuard guard(4);
    std::vector<std::unique_ptr<Signer>> senders;
    std::vector<std::string> captured;
    for (int i = 0; i < 10; ++i) {
        senders.push_back(std::make_unique<Signer>(ring({{"k1", 'a'}})));
        captured.push_back(senders.back()->sign(CH, "x", 1));
        EXPECT_FALSE(check(verifier, captured.back(), guard));
        EXPECT_LE(guard.senders(), 4u);
    }
    for (const auto &wire : captured) // the forgotten ones included
        EXPECT_EQ(check(verifier, wire, guard), Drop::REPLAYED);
    EXPECT_FALSE(check(verifier, senders[0]->sign(CH, "y", 1), guard)) << "still heard later";
}

std::string udp_url() {
    static const std::string url = testing::udpm_test_url(testing::claim_udp_port());
    return url;
}

void pump(Bus &a, Bus &b) {
    for (int i = 0; i < 10; ++i) {
        a.handle(std::chrono::milliseconds(10));
        b.handle(std::chrono::milliseconds(10));
    }
}

TEST(AuthBus, OnlyMessagesSignedWithTheKeyReachHandlersTheRestAreCounted) {
    auto keys = std::make_shared<KeyRing>(ring({{"k1", 'a'}}));
    Bus receiver(udp_url(), quiet(), keys);
    Bus signed_sender(udp_url(), quiet(), keys);
    Bus unsigned_sender(udp_url(), quiet());
    Bus foreign_sender(udp_url(), quiet(), std::make_shared<KeyRing>(ring({{"k9", 'a'}})));
    ASSERT_TRUE(receiver.authenticated());
    std::vector<std::string> reasons;
    auto sub = receiver.subscribe<envdesign::cancel_t>(
        CANCEL, [&](const envdesign::cancel_t &c) { reasons.push_back(c.reason); });
    std::vector<std::string> captured; // what a listener without the key records
    auto tap = unsigned_sender.subscribe_raw(CANCEL, [&](const void *data, int size) {
        captured.emplace_back(static_cast<const char *>(data), size);
    });
    envdesign::cancel_t cancel{};
    cancel.sender = "client/a";
    for (auto [bus, reason] : {std::pair{&signed_sender, "signed"},
                               {&unsigned_sender, "plain"},
                               {&foreign_sender, "foreign"}}) {
        cancel.reason = reason;
        bus->publish(CANCEL, cancel);
        pump(receiver, unsigned_sender);
    }
    ASSERT_EQ(captured.size(), 3u);
    unsigned_sender.publish_raw(CANCEL, captured[0].data(), static_cast<int>(captured[0].size()));
    pump(receiver, unsigned_sender);

    EXPECT_EQ(reasons, std::vector<std::string>{"signed"});
    AuthDrops drops = receiver.auth_drops();
    EXPECT_EQ(drops.count(CANCEL, Drop::UNAUTHENTICATED), 1);
    EXPECT_EQ(drops.count(CANCEL, Drop::UNKNOWN_KEY), 1);
    EXPECT_EQ(drops.count(CANCEL, Drop::REPLAYED), 1);
    EXPECT_EQ(drops.total(), 3);
    EXPECT_EQ(receiver.malformed(), 0);
}

// Without keys a typed message declares its process (auth.h's origin trailer): another bus
// reads it as message_origin() and its handlers get the message alone; its own bus reads 0
// (in-process traffic); raw bytes declare nothing; a forged trailer is believed (unproven:
// only keys make a process's id hard to forge).
TEST(AuthBus, WithoutKeysATypedMessageDeclaresItsProcess) {
    Bus receiver(udp_url(), quiet());
    Bus sender(udp_url(), quiet());
    ASSERT_NE(sender.origin(), 0u);
    ASSERT_NE(sender.origin(), receiver.origin());
    std::vector<std::pair<std::string, std::uint64_t>> heard;
    auto sub = receiver.subscribe<envdesign::cancel_t>(CANCEL, [&](const envdesign::cancel_t &c) {
        heard.emplace_back(c.reason, receiver.message_origin());
    });
    envdesign::cancel_t cancel{};
    cancel.sender = "client/a";
    cancel.reason = "typed";
    sender.publish(CANCEL, cancel);
    pump(receiver, sender);
    cancel.reason = "own";
    receiver.publish(CANCEL, cancel);
    pump(receiver, sender);
    cancel.reason = "raw";
    std::string bytes = encode_message(cancel);
    sender.publish_raw(CANCEL, bytes.data(), static_cast<int>(bytes.size()));
    pump(receiver, sender);
    cancel.reason = "forged";
    std::string forged = with_origin(12345, encode_message(cancel).data(),
                                     static_cast<std::size_t>(encode_message(cancel).size()));
    sender.publish_raw(CANCEL, forged.data(), static_cast<int>(forged.size()));
    pump(receiver, sender);
    using Heard = std::vector<std::pair<std::string, std::uint64_t>>;
    EXPECT_EQ(heard,
              (Heard{{"typed", sender.origin()}, {"own", 0}, {"raw", 0}, {"forged", 12345}}));
    EXPECT_EQ(receiver.malformed(), 0);
    EXPECT_EQ(declared_origin(bytes.data(), bytes.size()), 0u);
}

} // namespace
} // namespace envdesign::bus
