#pragma once
// Logging of the services: every line names the service instance (the logger's name) and
// the request it is about ("request client/host/42#7", or "request -").

#include <spdlog/spdlog.h>

#include <cstdint>
#include <memory>
#include <string>

namespace envdesign::bus {

// A logger named `instance` writing "[time] [level] [instance] message" to stderr.
std::shared_ptr<spdlog::logger> make_logger(const std::string &instance,
                                            spdlog::level::level_enum level = spdlog::level::info);

// "client/host/42#7": a request is named by its client and the client's id for it.
std::string request_name(const std::string &client, std::int64_t request_id);

// Microseconds since the Unix epoch, for the utime of every message.
std::int64_t now_utime();

} // namespace envdesign::bus
