#include "bus/status.h"

#include "bus/channels.h"
#include "bus/log.h"

#include <envdesign/version.h>

#include <algorithm>

namespace envdesign::bus {

std::string version() { return envdesign::VERSION; }

void add_drop(envdesign::service_status_t &status, const std::string &channel,
              const std::string &reason, long long count) {
    status.drop_channels.push_back(channel);
    status.drop_reasons.push_back(reason);
    status.drop_counts.push_back(count);
    status.num_drops = static_cast<std::int16_t>(status.drop_counts.size());
}

StatusPublisher::StatusPublisher(Bus &bus, std::string kind, std::string instance, double period_s)
    : bus_(bus), kind_(std::move(kind)), instance_(std::move(instance)), period_s_(period_s),
      started_utime_(now_utime()) {}

bool StatusPublisher::tick(const Fill &fill) {
    auto now = Clock::now();
    if (sent_ && std::chrono::duration<double>(now - last_).count() < period_s_)
        return false;
    bus_.publish(STATUS, snapshot(fill));
    sent_ = true;
    last_ = now;
    return true;
}

envdesign::service_status_t StatusPublisher::snapshot(const Fill &fill) const {
    envdesign::service_status_t s{};
    s.utime = now_utime();
    s.sender = instance_;
    s.kind = kind_;
    s.version = version();
    s.uptime_s = std::chrono::duration<double>(Clock::now() - started_).count();
    s.started_utime = started_utime_;
    s.period_ms = static_cast<std::int32_t>(period_s_ * 1000);
    s.malformed = bus_.malformed();
    s.handler_errors = bus_.handler_errors();
    for (const auto &[channel, counts] : bus_.auth_drops().by_channel)
        for (int reason = 0; reason < DROP_REASONS; ++reason)
            if (counts[reason] > 0)
                add_drop(s, channel, drop_name(static_cast<Drop>(reason)), counts[reason]);
    if (fill)
        fill(s);
    return s;
}

StatusBoard::StatusBoard(Bus &bus) {
    subscription_ = bus.subscribe<envdesign::service_status_t>(
        STATUS, [this](const envdesign::service_status_t &s) {
            if (!s.sender.empty())
                last_[ServiceId{s.sender, s.started_utime}] = s;
        });
}

bool StatusBoard::heard(const std::string &kind) const {
    return std::any_of(last_.begin(), last_.end(),
                       [&](const auto &entry) { return entry.second.kind == kind; });
}

std::map<std::string, int> StatusBoard::repeated_names() const {
    std::map<std::string, int> count;
    for (const auto &entry : last_)
        ++count[entry.first.name];
    std::erase_if(count, [](const auto &c) { return c.second < 2; });
    return count;
}

} // namespace envdesign::bus
