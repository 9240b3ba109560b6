#pragma once
// Helpers shared by the bus tests: a logger that prints nothing, and handling every message
// already received.

#include "bus/bus.h"

#include <spdlog/sinks/null_sink.h>
#include <spdlog/spdlog.h>

#include <chrono>
#include <memory>

namespace envdesign::bus {

inline std::shared_ptr<spdlog::logger> quiet() {
    return std::make_shared<spdlog::logger>("test",
                                            std::make_shared<spdlog::sinks::null_sink_mt>());
}

inline void drain(Bus &bus) {
    while (bus.handle(std::chrono::milliseconds(0)) > 0) {
    }
}

} // namespace envdesign::bus
