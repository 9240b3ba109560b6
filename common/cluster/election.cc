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
                   Clock::time_point now, std::uint64_t sender_id)
    : instance_(std::move(instance)), started_utime_(started_utime), sender_id_(sender_id),
      config_(config), discovered_(now + std::chrono::duration_cast<Clock::duration>(
                                             std::chrono::duration<double>(config.discovery_s))),
      role_(config.discovery_s > 0 ? Role::DISCOVERING : Role::ACTIVE) {}

void Election::heard(const envdesign::service_status_t &status, Clock::time_point now,
                     std::uint64_t sender_id) {
    if (status.kind != "coordinator" || status.sender.empty())
        return;
    Peer peer{status.started_utime, sender_id, status.sender};
    if (peer == Peer{started_utime_, sender_id_, instance_})
        return; // its own
    peers_[peer] = now;
}

bool Election::outranks(const Peer &peer) const {
    if (peer.started_utime != started_utime_)
        return peer.started_utime < started_utime_;
    if (peer.sender_id != sender_id_)
        return peer.sender_id < sender_id_;
    return peer.name < instance_;
}

std::optional<std::string> Election::update(Clock::time_point now) {
    auto silence = std::chrono::duration_cast<Clock::duration>(
        std::chrono::duration<double>(config_.takeover_after_s));
    std::erase_if(peers_, [&](const auto &p) { return now - p.second > silence; });
    // The earliest outranking peer still heard: the one everybody stands by for (peers are
    // ordered by start, then sender id, then name: the first that outranks).
    const Peer *best = nullptr;
    for (const auto &[peer, heard] : peers_)
        if (outranks(peer)) {
            best = &peer;
            break;
        }
    Role role = best ? Role::STANDBY : now < discovered_ ? Role::DISCOVERING : Role::ACTIVE;
    std::string was = active_;
    active_ = best ? best->name : "";
    if (role == role_ && active_ == was)
        return std::nullopt;
    Role before = role_;
    role_ = role;
    if (role == Role::STANDBY && active_ == instance_)
        return "standing by: another coordinator named " + active_ +
               " started earlier and is active on this bus; give each coordinator its own "
               "--name";
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
