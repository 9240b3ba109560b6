#include "bus/bus.h"

#include <bit>
#include <utility>

namespace envdesign::bus {

struct Subscription::Slot {
    Bus *bus;
    RawHandler handler;
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

Bus::Bus(const std::string &url, std::shared_ptr<spdlog::logger> logger)
    : url_(url), logger_(logger ? std::move(logger) : spdlog::default_logger()), lcm_(url) {
    if (!lcm_.good())
        throw BusError("LCM cannot start on '" + url +
                       "' (udpm needs a multicast route: ip route add 224.0.0.0/4 dev lo)");
}

Bus::~Bus() = default;

void Bus::publish_raw(const std::string &channel, const void *data, int size) {
    std::lock_guard lock(publish_mutex_);
    if (lcm_.publish(channel, data, static_cast<unsigned int>(size)) != 0)
        logger_->warn("request - | could not publish {} bytes on {}", size, channel);
}

Subscription Bus::subscribe_raw(const std::string &channel, RawHandler handler,
                                int queue_capacity) {
    auto slot = std::make_unique<Subscription::Slot>(Subscription::Slot{this, std::move(handler)});
    lcm::Subscription *raw =
        lcm_.subscribeFunction(channel, &Bus::trampoline, static_cast<void *>(slot.get()));
    if (!raw)
        throw BusError("cannot subscribe to " + channel);
    raw->setQueueCapacity(queue_capacity);
    return Subscription(this, raw, std::move(slot));
}

void Bus::trampoline(const lcm::ReceiveBuffer *buffer, const std::string &channel, void *context) {
    auto *slot = static_cast<Subscription::Slot *>(context);
    slot->bus->run_handler(slot->handler, buffer, channel);
}

void Bus::run_handler(const RawHandler &handler, const lcm::ReceiveBuffer *buffer,
                      const std::string &channel) {
    // Called from LCM's C code: nothing may escape.
    try {
        handler(buffer->data, static_cast<int>(buffer->data_size));
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
