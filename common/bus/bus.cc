#include "bus/bus.h"

#include "bus/log.h"
#include "bus/udpm_guard.h"

#include <sys/stat.h>

#include <algorithm>
#include <bit>
#include <mutex>
#include <utility>

namespace envdesign::bus {

struct Subscription::Slot {
    Bus *bus;
    RawHandler handler;
    // Per subscription: LCM hands one message to every subscription of its channel.
    ReplayGuard replay;
};

Subscription::Subscription(Bus *bus, lcm::Subscription *raw, std::unique_ptr<Slot> slot)
    : bus_(bus), raw_(raw), slot_(std::move(slot)) {}

Subscription::Subscription() = default;

Subscription::Subscription(Subscription &&other) noexcept { *this = std::move(other); }

Subscription &Subscription::operator=(Subscription &&other) noexcept {
    if (this != &other) {
        reset();
        bus_ = std::exchange(other.bus_, nullptr);
        raw_ = std::exchange(other.raw_, nullptr);
        slot_ = std::move(other.slot_);
    }
    return *this;
}

Subscription::~Subscription() { reset(); }

void Subscription::reset() {
    if (bus_ && raw_)
        bus_->unsubscribe(raw_); // before the slot goes: LCM holds a pointer to it
    bus_ = nullptr;
    raw_ = nullptr;
    slot_.reset();
}

Bus::Bus(const std::string &url, std::shared_ptr<spdlog::logger> logger,
         std::shared_ptr<const KeyRing> keys)
    : url_(url), logger_(logger ? std::move(logger) : spdlog::default_logger()), lcm_(url) {
    if (!lcm_.good())
        throw BusError("LCM cannot start on '" + url +
                       "' (udpm needs a multicast route: ip route add 224.0.0.0/4 dev lo)");
    if (keys) {
        signer_ = std::make_unique<Signer>(*keys);
        verifier_ = std::make_unique<Verifier>(*keys);
    }
    origin_ = signer_ ? signer_->sender() : random_sender();
}

Bus::~Bus() = default;

void Bus::send(const std::string &channel, const void *data, int size, bool declare_origin) {
    std::lock_guard lock(publish_mutex_);
    // Signed under the lock (counters go out in order); without keys, the origin trailer.
    std::string wire;
    if (signer_)
        wire = signer_->sign(channel, data, static_cast<std::size_t>(size));
    else if (declare_origin)
        wire = with_origin(origin_, data, static_cast<std::size_t>(size));
    if (!wire.empty()) {
        data = wire.data();
        size = static_cast<int>(wire.size());
    }
    if (lcm_.publish(channel, data, static_cast<unsigned int>(size)) != 0)
        logger_->warn("request - | could not publish {} bytes on {}", size, channel);
}

namespace {

// The inodes of this process's receive sockets on `port` (udpm_receive_sockets).
std::vector<ino_t> receive_socket_inodes(std::uint16_t port) {
    std::vector<ino_t> inodes;
    for (int fd : udpm_receive_sockets(port)) {
        struct stat s {};
        if (fstat(fd, &s) == 0)
            inodes.push_back(s.st_ino);
    }
    return inodes;
}

} // namespace

Subscription Bus::subscribe_raw(const std::string &channel, RawHandler handler,
                                int queue_capacity) {
    auto slot = std::make_unique<Subscription::Slot>(
        Subscription::Slot{this, std::move(handler), ReplayGuard()});
    auto port = guarded_ ? std::nullopt : udpm_port(url_);
    // A first subscription opens LCM's receive socket: one at a time in the process, so that
    // the sockets before and after are this bus's doing alone.
    static std::mutex opening;
    std::unique_lock one_at_a_time(opening, std::defer_lock);
    std::vector<ino_t> sockets_before;
    if (port) {
        one_at_a_time.lock();
        sockets_before = receive_socket_inodes(*port);
    }
    lcm::Subscription *raw =
        lcm_.subscribeFunction(channel, &Bus::trampoline, static_cast<void *>(slot.get()));
    if (!raw)
        throw BusError("cannot subscribe to " + channel);
    // Before anything touches `raw`: when LCM could not bind, it holds no C subscription (a
    // null one, on which setQueueCapacity crashes) and stays inert in LCM's list.
    if (port)
        guard_receive_socket(*port, sockets_before);
    raw->setQueueCapacity(queue_capacity);
    return Subscription(this, raw, std::move(slot));
}

// LCM opens its udpm receive socket at the first subscription; the guard goes on it then.
// No new socket means LCM could not bind the port (it prints "bind: Address already in use"
// and goes on deaf): another program holds it without sharing. That is this bus's error,
// said where it starts, not a service that silently never hears a message. (Sockets are
// told apart by inode, not by descriptor: another bus may close one meanwhile and LCM's new
// one take its number.)
void Bus::guard_receive_socket(std::uint16_t port, const std::vector<ino_t> &sockets_before) {
    std::vector<ino_t> now = receive_socket_inodes(port);
    bool opened = std::any_of(now.begin(), now.end(), [&](ino_t socket) {
        return std::find(sockets_before.begin(), sockets_before.end(), socket) ==
               sockets_before.end();
    });
    if (!opened)
        throw BusError("LCM cannot receive on UDP port " + std::to_string(port) + " of '" + url_ +
                       "': another program holds the port without sharing it");
    guard_udpm_fragments(port);
    guarded_ = true;
}

void Bus::trampoline(const lcm::ReceiveBuffer *buffer, const std::string &channel, void *context) {
    auto *slot = static_cast<Subscription::Slot *>(context);
    Bus &bus = *slot->bus;
    if (!bus.verifier_) {
        std::size_t size = buffer->data_size;
        std::uint64_t origin = declared_origin(buffer->data, size);
        if (origin != 0)
            size -= ORIGIN_SIZE;
        bus.message_origin_ = origin == bus.origin_ ? 0 : origin;
        bus.run_handler(slot->handler, buffer->data, static_cast<int>(size), channel);
        bus.message_origin_ = 0;
        return;
    }
    Verdict verdict;
    try {
        verdict = bus.verifier_->verify(channel, buffer->data, buffer->data_size, slot->replay,
                                        now_utime());
    } catch (const std::exception &e) { // OpenSSL failed; nothing may escape into LCM
        bus.logger_->error("request - | cannot verify a message on {}: {}", channel, e.what());
        return;
    }
    if (!verdict.ok()) {
        bus.count_drop(channel, *verdict.drop);
        return;
    }
    bus.message_sender_ = bus.message_origin_ = verdict.sender;
    bus.run_handler(slot->handler, buffer->data, static_cast<int>(verdict.payload_size), channel);
    bus.message_sender_ = bus.message_origin_ = 0;
}

void Bus::run_handler(const RawHandler &handler, const void *data, int size,
                      const std::string &channel) {
    // Called from LCM's C code: nothing may escape.
    try {
        handler(data, size);
    } catch (const std::exception &e) {
        long long n = ++handler_errors_;
        logger_->error("request - | handler for {} failed ({} so far): {}", channel, n, e.what());
    } catch (...) {
        long long n = ++handler_errors_;
        logger_->error("request - | handler for {} failed ({} so far)", channel, n);
    }
}

void Bus::unsubscribe(lcm::Subscription *raw) { lcm_.unsubscribe(raw); }

int Bus::handle(std::chrono::milliseconds timeout) {
    return lcm_.handleTimeout(static_cast<int>(std::max<long long>(0, timeout.count())));
}

void Bus::count_drop(const std::string &channel, Drop reason) {
    long long n = 0, all = 0;
    {
        std::lock_guard lock(drops_mutex_);
        auto &counts = drops_.by_channel[channel];
        n = ++counts[static_cast<int>(reason)];
        all = drops_.total();
    }
    // As reject(): the first ten, then every power of two of the total, so a flood of forged
    // messages cannot flood the log.
    auto level = all <= 10 || std::has_single_bit(static_cast<unsigned long long>(all))
                     ? spdlog::level::warn
                     : spdlog::level::debug;
    logger_->log(level, "request - | dropped a message on {}: {} ({} such, {} dropped in all)",
                 channel, drop_name(reason), n, all);
}

AuthDrops Bus::auth_drops() const {
    std::lock_guard lock(drops_mutex_);
    return drops_;
}

long long AuthDrops::count(const std::string &channel, Drop reason) const {
    auto it = by_channel.find(channel);
    return it == by_channel.end() ? 0 : it->second[static_cast<int>(reason)];
}

long long AuthDrops::total() const {
    long long sum = 0;
    for (const auto &[channel, counts] : by_channel)
        for (long long n : counts)
            sum += n;
    return sum;
}

void Bus::reject(const std::string &channel, const std::string &why) {
    long long n = ++malformed_;
    // Every one is counted; the log shows the first ten, then every power of two, so that
    // a flood of garbage cannot flood the log.
    auto level = n <= 10 || std::has_single_bit(static_cast<unsigned long long>(n))
                     ? spdlog::level::warn
                     : spdlog::level::debug;
    logger_->log(level, "request - | malformed message on {} ({} so far): {}", channel, n, why);
}

} // namespace envdesign::bus
