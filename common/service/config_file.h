#pragma once
// Service config files (--config FILE, e.g. /etc/envdesign/coordinator.conf): one setting a
// line, named like the service's flags without the dashes; flags on the command line win.
//
//   # /etc/envdesign/coordinator.conf
//   max-requests = 4
//   state-fsync = true          # a flag: true or false
//   problem = restaurant=/etc/envdesign/restaurant.textproto   # repeatable: one line each
//
// Blank lines and lines starting with '#' are skipped; a value may be wrapped in double
// quotes (to keep a '#' or spaces at its ends); an unquoted value ends at " #".

#include <stdexcept>
#include <string>
#include <vector>

namespace envdesign::service {

// "FILE:LINE:COL: error: ..." (or "FILE: error: ..." when the file cannot be read).
class ConfigError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

struct ConfigSetting {
    std::string key, value;
    int line = 0;
    int key_column = 0; // 1-based
};

// Reads `path`. Throws ConfigError for an unreadable file or a line that is not
// "key = value".
std::vector<ConfigSetting> read_config_file(const std::string &path);

} // namespace envdesign::service
