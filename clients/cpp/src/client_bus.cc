#include "client_bus.h"

#include "bus/lcm_url.h"
#include "bus/log.h"

#include <spdlog/fmt/fmt.h>
#include <spdlog/sinks/stdout_color_sinks.h>

namespace envdesign::client {
namespace {

std::shared_ptr<spdlog::logger> client_logger(const std::string &instance) {
    auto logger = std::make_shared<spdlog::logger>(
        instance, std::make_shared<spdlog::sinks::stderr_color_sink_mt>());
    logger->set_pattern("[%H:%M:%S.%e] [%^%l%$] [%n] %v");
    logger->set_level(spdlog::level::warn);
    return logger;
}

} // namespace

BusOrError open_client_bus(const std::string &url, const std::string &key_file,
                           const std::string &instance) {
    std::string where = url.empty() ? bus::default_url() : url;
    if (auto problem = bus::url_problem(where))
        return std::make_pair(2, *problem);
    std::shared_ptr<const bus::KeyRing> keys;
    try {
        if (auto path = bus::key_file_path(key_file))
            keys = std::make_shared<const bus::KeyRing>(bus::load_key_file(*path));
    } catch (const bus::KeyFileError &e) {
        return std::make_pair(2, std::string("--key-file: ") + e.what());
    }
    try {
        return std::make_unique<bus::Bus>(bus::with_receive_buffer(where), client_logger(instance),
                                          keys);
    } catch (const std::exception &e) {
        return std::make_pair(1, std::string(e.what()));
    }
}

std::string no_coordinator_message(const bus::Bus &bus, double seconds) {
    std::string message = fmt::format("no coordinator on this bus ({}): no status or answer "
                                      "heard in {:g} s",
                                      bus.url(), seconds);
    if (long long dropped = bus.auth_drops().total(); dropped > 0)
        message += fmt::format("; {} message(s) dropped by authentication: is the key file "
                               "the bus's?",
                               dropped);
    return message;
}

} // namespace envdesign::client
