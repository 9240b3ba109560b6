#include "cluster/election.h"

#include <fmt/format.h>

namespace envdesign::cluster {

const char *to_string(Role role) {
    switch (role) {
    case Role::DISCOVERING:
        return "discovering";
    case Role::ACTIVE:
        return "active";
    case Role::STANDBY:
        return "standby";
    }
    return "?";
}

Election::Election(std::string instance, std::int64_t started_utime, ElectionConfig config,
                   Clock::time_point now)
    : instance_(std::move(instance)), started_utime_(started_utime), config_(config),
      discovered_(now + std::chrono::duration_cast<Clock::duration>(
                            std::chrono::duration<double>(config.discovery_s))),
      role_(config.discovery_s > 0 ? Role::DISCOVERING : Role::ACTIVE) {}

void Election::heard(const envdesign::service_status_t &status, Clock::time_point now) {
    if (status.kind != "coordinator" || status.sender == instance_ || status.sender.empty())
        return;
    peers_[status.sender] = {status.started_utime, now};
}

bool Election::outranks(const std::string &name, const Peer &peer) const {
    if (peer.started_utime != started_utime_)
        return peer.started_utime < started_utime_;
    return name < instance_;
}

std::optional<std::string> Election::update(Clock::time_point now) {
    auto silence = std::chrono::duration_cast<Clock::duration>(
        std::chrono::duration<double>(config_.takeover_after_s));
    std::erase_if(peers_, [&](const auto &p) { return now - p.second.heard > silence; });
    // The earliest outranking peer still heard: the one everybody stands by for.
    const std::string *best = nullptr;
    for (const auto &[name, peer] : peers_)
        if (outranks(name, peer) && (!best || peer.started_utime < peers_.at(*best).started_utime))
            best = &name;
    Role role = best ? Role::STANDBY : now < discovered_ ? Role::DISCOVERING : Role::ACTIVE;
    std::string was = active_;
    active_ = best ? *best : "";
    if (role == role_ && active_ == was)
        return std::nullopt;
    Role before = role_;
    role_ = role;
    if (role == Role::STANDBY)
        return "standing by: coordinator " + active_ + " started earlier and is active on this bus";
    if (role == Role::ACTIVE && before == Role::STANDBY)
        return "taking over: coordinator " + was + " has not been heard for " +
               fmt::format("{:g}", config_.takeover_after_s) + " s";
    if (role == Role::ACTIVE)
        return "active: no coordinator that started earlier is on this bus";
    return std::nullopt;
}

} // namespace envdesign::cluster
