// `envdesign status`: the services heard on a bus (bus/status.h), as a table or JSON lines.

#include "bus/lcm_url.h"
#include "bus/log.h"
#include "bus/status.h"
#include "client_bus.h"
#include "envdesign/client/client.h"

#include <nlohmann/json.hpp>
#include <spdlog/fmt/fmt.h>

#include <ctime>

namespace envdesign::client {
namespace {

using envdesign::service_status_t;

long long all_drops(const service_status_t &s) {
    long long n = s.malformed + s.handler_errors;
    for (auto count : s.drop_counts)
        n += count;
    return n;
}

// Seconds since it was sent, by the listener's clock.
double age_s(const service_status_t &s) { return (bus::now_utime() - s.utime) / 1e6; }

// When it started, UTC to the second ("2026-12-01T00:19:30Z"); "-" if it did not say.
std::string started(const service_status_t &s) {
    if (s.started_utime <= 0)
        return "-";
    std::time_t seconds = static_cast<std::time_t>(s.started_utime / 1000000);
    std::tm tm{};
    gmtime_r(&seconds, &tm);
    char text[32];
    std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &tm);
    return text;
}

// A coordinator's role (active, standby, discovering); "-" for the other kinds.
std::string role(const service_status_t &s) { return s.role.empty() ? "-" : s.role; }

std::string json_line(const service_status_t &s) {
    nlohmann::json drops = nlohmann::json::array();
    for (int i = 0; i < s.num_drops; ++i)
        drops.push_back({{"channel", s.drop_channels[i]},
                         {"reason", s.drop_reasons[i]},
                         {"count", s.drop_counts[i]}});
    nlohmann::json j = {{"kind", s.kind},
                        {"name", s.sender},
                        {"version", s.version},
                        {"role", s.role},
                        {"started_utime", s.started_utime},
                        {"started", started(s)},
                        {"uptime_s", s.uptime_s},
                        {"age_s", age_s(s)},
                        {"requests_open", s.requests_open},
                        {"requests_waiting", s.requests_waiting},
                        {"planners", s.planners},
                        {"jobs_in_flight", s.jobs_in_flight},
                        {"jobs_done", s.jobs_done},
                        {"stored_evaluations", s.stored_evaluations},
                        {"malformed", s.malformed},
                        {"handler_errors", s.handler_errors},
                        {"drops", drops}};
    return j.dump() + "\n";
}

std::string table(const bus::StatusBoard &board) {
    std::string out = fmt::format("{:<12} {:<28} {:<11} {:<8} {:<20} {:>9} {:>5} {:>7} {:>8} {:>7} "
                                  "{:>9} {:>9} {:>6}\n",
                                  "KIND", "NAME", "ROLE", "VERSION", "STARTED", "UPTIME_S", "OPEN",
                                  "WAITING", "PLANNERS", "JOBS", "DONE", "STORED", "DROPS");
    std::string details;
    for (const auto &[id, s] : board.services()) {
        const std::string &name = id.name;
        out += fmt::format("{:<12} {:<28} {:<11} {:<8} {:<20} {:>9.0f} {:>5} {:>7} {:>8} {:>7} "
                           "{:>9} {:>9} {:>6}\n",
                           s.kind, name, role(s), s.version, started(s), s.uptime_s,
                           s.requests_open, s.requests_waiting, s.planners, s.jobs_in_flight,
                           s.jobs_done, s.stored_evaluations, all_drops(s));
        if (s.malformed > 0)
            details += fmt::format("  {}: {} malformed\n", name, s.malformed);
        if (s.handler_errors > 0)
            details += fmt::format("  {}: {} handler errors\n", name, s.handler_errors);
        for (int i = 0; i < s.num_drops; ++i)
            details += fmt::format("  {}: {} dropped on {}: {}\n", name, s.drop_counts[i],
                                   s.drop_channels[i], s.drop_reasons[i]);
    }
    // Jobs and spec chunks are addressed by name: a repeated one reaches every process of it.
    for (const auto &[name, count] : board.repeated_names())
        details += fmt::format("  {}: {} services have this name (messages addressed to it reach "
                               "all of them); give each its own --name\n",
                               name, count);
    return out + details;
}

} // namespace

StatusReport listen_status(const std::string &lcm_url, const StatusOptions &options) {
    StatusReport report;
    auto opened = open_client_bus(lcm_url, options.key_file, bus::instance_name("status"));
    if (auto *error = std::get_if<std::pair<int, std::string>>(&opened)) {
        report.exit_code = error->first;
        report.error = error->second;
        return report;
    }
    bus::Bus &on = *std::get<std::unique_ptr<bus::Bus>>(opened);
    bus::StatusBoard board(on);
    auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(options.seconds);
    while (std::chrono::steady_clock::now() < end)
        on.handle(std::chrono::milliseconds(50));
    report.services = static_cast<int>(board.services().size());
    report.text = table(board);
    for (const auto &[id, s] : board.services())
        report.json += json_line(s);
    report.exit_code = board.heard("coordinator") ? 0 : 1;
    if (report.exit_code != 0)
        report.error = no_coordinator_message(on, options.seconds);
    return report;
}

} // namespace envdesign::client
