#pragma once
// systemd's notify protocol for Type=notify units (sd_notify(3)): READY=1 once the service
// is on the bus, WATCHDOG=1 from its main loop at half of WatchdogSec=, STOPPING=1 on the
// way out. Every call is a no-op when NOTIFY_SOCKET is unset (not started by systemd).

#include <chrono>
#include <optional>
#include <string>

namespace envdesign::service {

class SystemdNotifier {
public:
    SystemdNotifier(); // reads WATCHDOG_USEC (and WATCHDOG_PID) from the environment

    void ready(const std::string &status);
    // From the main loop: WATCHDOG=1 when half the watchdog period has passed since the last.
    void tick();
    void stopping();

    // Half of WatchdogSec=, or unset when systemd runs no watchdog for this process.
    std::optional<std::chrono::microseconds> period() const { return period_; }

private:
    std::optional<std::chrono::microseconds> period_;
    std::chrono::steady_clock::time_point last_;
};

} // namespace envdesign::service
