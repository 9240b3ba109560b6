#pragma once
// LCM URLs: the default of SPEC.md and the receive buffer every udpm URL should ask for.

#include <optional>
#include <string>

namespace envdesign::bus {

// LCM's own default: $LCM_DEFAULT_URL, else "udpm://239.255.76.67:7667?ttl=0".
std::string default_url();

// `url` with "recv_buf_size=4194304" added when it is udpm and sets no receive buffer. LCM
// 1.3.1 loses messages above ~64 KB with the kernel's default buffer (PLATFORM.md §3); the
// option changes only this process's socket, so peers need not agree on it.
std::string with_receive_buffer(const std::string &url);

// Why `url` is not an LCM URL (its provider is none of LCM's), or nothing. A bad URL is a
// usage error (exit 2); a good one LCM still cannot open is the machine's (exit 1).
std::optional<std::string> url_problem(const std::string &url);

// A name for this process on the bus: "ROLE/HOST/PID".
std::string instance_name(const std::string &role);

} // namespace envdesign::bus
