#pragma once
// What the client's commands share: opening the bus a URL and key file name, and saying
// that no coordinator is on it.

#include "bus/bus.h"

#include <memory>
#include <string>
#include <variant>

namespace envdesign::client {

// A bus on `url` (empty: LCM's default) with the keys of `key_file` (empty:
// $ENVDESIGN_KEY_FILE, else none), or why not: a bad URL or key file (.first 2), LCM failing
// to start (.first 1).
using BusOrError = std::variant<std::unique_ptr<bus::Bus>, std::pair<int, std::string>>;
BusOrError open_client_bus(const std::string &url, const std::string &key_file,
                           const std::string &instance);

// "no coordinator on this bus (URL): ...", naming the authentication drops if there were
// any (a wrong key hears nothing).
std::string no_coordinator_message(const bus::Bus &bus, double seconds);

} // namespace envdesign::client
