#include "bridge/clock.h"

#include "bus/log.h"

namespace envdesign::bridge {

double SystemClock::seconds() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

std::int64_t SystemClock::utime() const { return bus::now_utime(); }

} // namespace envdesign::bridge
