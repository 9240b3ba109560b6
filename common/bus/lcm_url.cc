#include "bus/lcm_url.h"

#include <cstdlib>
#include <unistd.h>

namespace envdesign::bus {

std::string default_url() {
    const char *env = std::getenv("LCM_DEFAULT_URL");
    return env && *env ? env : "udpm://239.255.76.67:7667?ttl=0";
}

std::string with_receive_buffer(const std::string &url) {
    if (url.rfind("udpm://", 0) != 0 || url.find("recv_buf_size") != std::string::npos)
        return url;
    return url + (url.find('?') == std::string::npos ? "?" : "&") + "recv_buf_size=4194304";
}

std::optional<std::string> url_problem(const std::string &url) {
    for (const char *provider : {"udpm://", "mpudpm://", "tcpq://", "memq://", "file://"})
        if (url.rfind(provider, 0) == 0)
            return std::nullopt;
    return "'" + url + "' is not an LCM URL (udpm://, mpudpm://, tcpq://, memq:// or file://)";
}

std::string instance_name(const std::string &role) {
    char host[256] = "host";
    gethostname(host, sizeof host - 1);
    return role + "/" + host + "/" + std::to_string(getpid());
}

} // namespace envdesign::bus
