#include "service/systemd_notify.h"

#include <systemd/sd-daemon.h>

namespace envdesign::service {

SystemdNotifier::SystemdNotifier() {
    std::uint64_t usec = 0;
    if (sd_watchdog_enabled(0, &usec) > 0 && usec > 0)
        period_ = std::chrono::microseconds(usec / 2);
}

void SystemdNotifier::ready(const std::string &status) {
    sd_notify(0, ("READY=1\nSTATUS=" + status).c_str());
    last_ = std::chrono::steady_clock::now();
    if (period_)
        sd_notify(0, "WATCHDOG=1");
}

void SystemdNotifier::tick() {
    if (!period_)
        return;
    auto now = std::chrono::steady_clock::now();
    if (now - last_ < *period_)
        return;
    last_ = now;
    sd_notify(0, "WATCHDOG=1");
}

void SystemdNotifier::stopping() { sd_notify(0, "STOPPING=1"); }

} // namespace envdesign::service
