#include "bus/log.h"

#include <spdlog/sinks/stdout_color_sinks.h>

#include <chrono>

namespace envdesign::bus {

std::shared_ptr<spdlog::logger> make_logger(const std::string &instance,
                                            spdlog::level::level_enum level) {
    auto sink = std::make_shared<spdlog::sinks::stderr_color_sink_mt>();
    auto logger = std::make_shared<spdlog::logger>(instance, sink);
    logger->set_pattern("[%H:%M:%S.%e] [%^%l%$] [%n] %v");
    logger->set_level(level);
    return logger;
}

std::string request_name(const std::string &client, std::int64_t request_id) {
    return client + "#" + std::to_string(request_id);
}

std::int64_t now_utime() {
    return std::chrono::duration_cast<std::chrono::microseconds>(
               std::chrono::system_clock::now().time_since_epoch())
        .count();
}

} // namespace envdesign::bus
