#pragma once
// Message authentication on the bus: every message carries, after its LCM bytes, a 68-byte
// trailer that names the key, the sending process and a counter, and holds an HMAC-SHA256.
// LCM's decoders read a message from its start and ignore what follows (lcm-spy shows signed
// messages as usual); our Bus strips the trailer before decoding.
//
//   offset  size  field (integers big-endian, like LCM's)
//        0     8  key id, ASCII, NUL-padded
//        8     8  sender: random per process (per Bus), so a restarted process is new
//       16     8  counter: 1, 2, ... per sender, over all channels
//       24     8  utime: microseconds since the Unix epoch when signed
//       32    32  HMAC-SHA256(secret, u16 len(channel) | channel | LCM bytes | bytes 0-31)
//       64     4  "EDA1"
//
// A receiver accepts a message only if the key id is one it has, the MAC matches, utime is
// within `tolerance` of its clock, and (sender, counter) is new (ReplayGuard).
//
//   Signer signer(ring);                      // one per Bus; call under the publish lock
//   std::string wire = signer.sign(channel, data, size);
//   Verifier verifier(ring);
//   ReplayGuard guard;                        // one per subscription
//   Verdict v = verifier.verify(channel, wire.data(), wire.size(), guard, bus::now_utime());
//   if (v.ok()) use(wire.data(), v.payload_size);

#include "bus/key_file.h"

#include <array>
#include <bitset>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

namespace envdesign::bus {

inline constexpr int TRAILER_SIZE = 68;
inline constexpr char TRAILER_MAGIC[4] = {'E', 'D', 'A', '1'};

// Without keys a message carries a 12-byte origin trailer instead: the sending process's
// random id (8 bytes, big-endian, as the signed sender) and "EDO1". Nothing proves it: it
// lets a coordinator count one process's many client names as one client (admission and
// fair shares, cluster/coordinator.h); anyone on an unkeyed bus can forge it.
inline constexpr int ORIGIN_SIZE = 12;
inline constexpr char ORIGIN_MAGIC[4] = {'E', 'D', 'O', '1'};
std::string with_origin(std::uint64_t origin, const void *data, std::size_t size);
// The origin `data` declares, or 0 when it ends in no origin trailer.
std::uint64_t declared_origin(const void *data, std::size_t size);
// A random non-zero id for a process's bus (the signed sender, or the declared origin).
std::uint64_t random_sender();

// Why a message was dropped; the order is that of the checks.
enum class Drop : int { UNAUTHENTICATED, UNKNOWN_KEY, BAD_MAC, STALE, REPLAYED };
inline constexpr int DROP_REASONS = 5;
const char *drop_name(Drop reason); // "unauthenticated", "unknown-key", ...

// HMAC-SHA256 with one key, its OpenSSL state prepared once. Thread-safe (serialised).
class Mac {
public:
    explicit Mac(const std::string &secret);
    ~Mac();
    Mac(const Mac &) = delete;
    Mac &operator=(const Mac &) = delete;
    std::array<unsigned char, 32> compute(const std::string &channel, const void *payload,
                                          std::size_t size, const unsigned char *header) const;

private:
    struct State;
    std::unique_ptr<State> state_;
};

class Signer {
public:
    explicit Signer(const KeyRing &ring);
    std::uint64_t sender() const { return sender_; }
    // The LCM bytes followed by their trailer. Not thread-safe (the counter): one caller.
    std::string sign(const std::string &channel, const void *data, std::size_t size);
    // The same at a given counter and time (tests forge replays and stale messages with it).
    std::string sign_at(const std::string &channel, const void *data, std::size_t size,
                        std::uint64_t counter, std::int64_t utime) const;

private:
    std::string key_id_;
    Mac mac_;
    std::uint64_t sender_;
    std::uint64_t counter_ = 0;
};

// Which (sender, counter) pairs were seen: per sender the newest counter and a window of
// the WINDOW before it. At most `max_senders` senders are kept; the least recently heard
// goes first, and from then on no message older than its last one is taken from a sender
// not in the table (it could be a replay of the forgotten sender).
class ReplayGuard {
public:
    static constexpr std::uint64_t WINDOW = 256;
    explicit ReplayGuard(std::size_t max_senders = 1024) : max_senders_(max_senders) {}
    // True (and remembered) if new; false for a replay or a message too far behind.
    bool accept(std::uint64_t sender, std::uint64_t counter, std::int64_t utime);
    std::size_t senders() const { return senders_.size(); }

private:
    struct Seen {
        std::uint64_t newest = 0;
        std::bitset<WINDOW> window; // bit i: newest - i was seen
        std::int64_t last_utime = 0;
        std::uint64_t last_heard = 0; // tick of the last accept, for eviction
    };
    void evict_one();

    std::size_t max_senders_;
    std::unordered_map<std::uint64_t, Seen> senders_;
    std::uint64_t tick_ = 0;
    std::int64_t forgotten_until_ = 0; // utime floor for senders not in the table
};

struct Verdict {
    std::optional<Drop> drop; // empty: accepted
    std::size_t payload_size = 0;
    std::uint64_t sender = 0;
    bool ok() const { return !drop; }
};

class Verifier {
public:
    static constexpr std::int64_t DEFAULT_TOLERANCE_US = 30'000'000;
    explicit Verifier(const KeyRing &ring, std::int64_t tolerance_us = DEFAULT_TOLERANCE_US);
    Verdict verify(const std::string &channel, const void *data, std::size_t size,
                   ReplayGuard &guard, std::int64_t now_utime) const;

private:
    struct Entry {
        std::string id;
        std::unique_ptr<Mac> mac;
    };
    std::vector<Entry> keys_;
    std::int64_t tolerance_us_;
};

} // namespace envdesign::bus
