#pragma once
// Overview: the one wrapper of LCM in envdesign. A Bus owns an lcm::LCM and offers typed
// publish<T> and subscribe<T> with std::function handlers (LCM 1.3.1 has no lambda
// subscribe; we adapt through subscribeFunction and a context pointer).
//
//   bus::Bus bus("memq://", logger);                  // tests; "udpm://..." deployed
//   bus::Subscription s = bus.subscribe<envdesign::job_t>(bus::JOB,
//       [&](const envdesign::job_t &job) { ... });
//   bus.publish(bus::JOB, job);                        // any thread
//   while (running) bus.handle(std::chrono::milliseconds(20));   // one thread
//
//   auto keys = std::make_shared<const bus::KeyRing>(bus::load_key_file(path));
//   bus::Bus keyed(url, logger, keys);                 // signs and verifies everything
//
// Contract:
//   - publish() is thread-safe; handle(), subscribe() and Subscription's destruction belong
//     to one thread (the bus thread), or happen while no thread is in handle().
//   - Handlers run on the thread in handle(). They never let an exception escape: a message
//     that does not decode as T in exactly its size (garbage, a foreign type, a truncated or
//     lying length) is dropped, counted in malformed() and logged; so is one a handler
//     rejects with reject(); an exception out of a handler is logged and counted too.
//   - Each subscription queues `queue_capacity` messages between handle() calls (LCM's
//     default of 30 drops bursts of jobs and answers).
//   - In-process: "memq://" delivers only within this Bus; cores that talk in one process
//     must share it.
//   - With a KeyRing (key_file.h) every message published is signed and every message
//     received is verified before it is decoded (auth.h): one that is unauthenticated,
//     forged, stale or replayed never reaches a handler; it is counted per channel and
//     reason (auth_drops()) and logged at a rate limit. Without one, nothing is signed and
//     nothing is checked (signed messages do not decode then: all or none have the key).

#include "bus/auth.h"
#include "bus/codec.h"

#include <lcm/lcm-cpp.hpp>
#include <spdlog/spdlog.h>
#include <sys/types.h>

#include <atomic>
#include <chrono>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

namespace envdesign::bus {

class BusError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

class Bus;

// One channel's handler; unsubscribes when destroyed. Move-only.
class Subscription {
public:
    Subscription();
    Subscription(Subscription &&other) noexcept;
    Subscription &operator=(Subscription &&other) noexcept;
    Subscription(const Subscription &) = delete;
    Subscription &operator=(const Subscription &) = delete;
    ~Subscription();

private:
    friend class Bus;
    struct Slot;
    Subscription(Bus *bus, lcm::Subscription *raw, std::unique_ptr<Slot> slot);
    void reset();

    Bus *bus_ = nullptr;
    lcm::Subscription *raw_ = nullptr;
    std::unique_ptr<Slot> slot_;
};

using RawHandler = std::function<void(const void *data, int size)>;

// Messages dropped by authentication: per channel, per reason (auth.h's Drop).
struct AuthDrops {
    std::map<std::string, std::array<long long, DROP_REASONS>> by_channel;
    long long count(const std::string &channel, Drop reason) const;
    long long total() const;
};

class Bus {
public:
    static constexpr int DEFAULT_QUEUE = 10000;

    // Throws BusError when LCM cannot start on `url` (e.g. udpm without a multicast route).
    // `keys`: sign and verify with them (nullptr: an unauthenticated bus).
    Bus(const std::string &url, std::shared_ptr<spdlog::logger> logger,
        std::shared_ptr<const KeyRing> keys = nullptr);
    ~Bus();
    Bus(const Bus &) = delete;
    Bus &operator=(const Bus &) = delete;

    const std::string &url() const { return url_; }
    spdlog::logger &log() const { return *logger_; }

    // Signed with keys; without, followed by this process's origin trailer (auth.h).
    template <typename Message> void publish(const std::string &channel, const Message &message) {
        std::string bytes = encode_message(message);
        send(channel, bytes.data(), static_cast<int>(bytes.size()), true);
    }
    // The bytes as given (signed with keys, but no origin without): a relay's or a test's.
    void publish_raw(const std::string &channel, const void *data, int size) {
        send(channel, data, size, false);
    }
    // This bus's process id: the signed sender with keys, the declared origin without.
    std::uint64_t origin() const { return origin_; }

    // Throws BusError when LCM cannot receive: its udpm port is held by a socket that does not
    // share it (LCM opens its receive socket at the first subscription).
    template <typename Message>
    Subscription subscribe(const std::string &channel, std::function<void(const Message &)> handler,
                           int queue_capacity = DEFAULT_QUEUE) {
        return subscribe_raw(
            channel,
            [this, channel, handler = std::move(handler)](const void *data, int size) {
                Message message;
                if (!decode_message(data, size, message)) {
                    reject(channel, "does not decode as " + std::string(Message::getTypeName()) +
                                        " (" + std::to_string(size) + " bytes)");
                    return;
                }
                handler(message);
            },
            queue_capacity);
    }
    Subscription subscribe_raw(const std::string &channel, RawHandler handler,
                               int queue_capacity = DEFAULT_QUEUE);

    // Dispatches what arrives within `timeout`: > 0 handled a message, 0 timed out, < 0 error.
    int handle(std::chrono::milliseconds timeout);

    // Counts and logs a message on `channel` that cannot be used (thread-safe).
    void reject(const std::string &channel, const std::string &why);
    long long malformed() const { return malformed_.load(); }
    long long handler_errors() const { return handler_errors_.load(); }
    bool authenticated() const { return verifier_ != nullptr; }
    AuthDrops auth_drops() const;
    // This bus's sender id in the trailer (0 without keys).
    std::uint64_t auth_sender() const { return signer_ ? signer_->sender() : 0; }
    // In a handler (bus thread): the verified sender id of the message being handled, 0 on
    // an unauthenticated bus. Binds a later message to the process that sent an earlier one.
    std::uint64_t message_sender() const { return message_sender_; }
    // In a handler: the process the message says it comes from: the verified sender with
    // keys (this bus's own included); without, the origin it declares (auth.h: unproven), 0
    // when it declares none or is this bus's own (in-process traffic, memq://). The unit of
    // admission and fair shares (cluster/coordinator.h's client_unit).
    std::uint64_t message_origin() const { return message_origin_; }

private:
    friend class Subscription;
    static void trampoline(const lcm::ReceiveBuffer *buffer, const std::string &channel,
                           void *context);
    void run_handler(const RawHandler &handler, const void *data, int size,
                     const std::string &channel);
    void send(const std::string &channel, const void *data, int size, bool declare_origin);
    void unsubscribe(lcm::Subscription *raw);
    void count_drop(const std::string &channel, Drop reason);
    void guard_receive_socket(std::uint16_t port, const std::vector<ino_t> &sockets_before);

    std::string url_;
    std::shared_ptr<spdlog::logger> logger_;
    lcm::LCM lcm_;
    std::mutex publish_mutex_;
    std::atomic<long long> malformed_{0};
    std::atomic<long long> handler_errors_{0};
    std::unique_ptr<Signer> signer_;     // under publish_mutex_
    std::unique_ptr<Verifier> verifier_; // bus thread
    std::uint64_t message_sender_ = 0;   // bus thread
    std::uint64_t message_origin_ = 0;   // bus thread
    std::uint64_t origin_ = 0;           // declared without keys (the signer's id with)
    bool guarded_ = false;               // udpm_guard.h, once LCM has its receive socket
    mutable std::mutex drops_mutex_;
    AuthDrops drops_;
};

} // namespace envdesign::bus
