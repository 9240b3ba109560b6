#pragma once
// systemd's side of the notify protocol, for tests: a datagram socket bound where
// NOTIFY_SOCKET tells a service to send READY=1, WATCHDOG=1 and STOPPING=1 (sd_notify(3)).

#include <chrono>
#include <cstring>
#include <filesystem>
#include <optional>
#include <poll.h>
#include <stdexcept>
#include <string>
#include <sys/socket.h>
#include <sys/un.h>
#include <unistd.h>
#include <vector>

namespace envdesign::testing {

class NotifySocket {
public:
    explicit NotifySocket(std::string path) : path_(std::move(path)) {
        std::filesystem::remove(path_);
        fd_ = ::socket(AF_UNIX, SOCK_DGRAM | SOCK_CLOEXEC, 0);
        sockaddr_un address{};
        address.sun_family = AF_UNIX;
        if (fd_ < 0 || path_.size() >= sizeof(address.sun_path))
            throw std::runtime_error("cannot make a notify socket at " + path_);
        std::strcpy(address.sun_path, path_.c_str());
        if (::bind(fd_, reinterpret_cast<sockaddr *>(&address), sizeof(address)) != 0)
            throw std::runtime_error("cannot bind " + path_ + ": " + std::strerror(errno));
    }
    ~NotifySocket() {
        ::close(fd_);
        std::filesystem::remove(path_);
    }
    NotifySocket(const NotifySocket &) = delete;
    NotifySocket &operator=(const NotifySocket &) = delete;

    // The environment that points a service here, with a watchdog of `watchdog_usec`.
    std::vector<std::string> env(long long watchdog_usec) const {
        return {"NOTIFY_SOCKET=" + path_, "WATCHDOG_USEC=" + std::to_string(watchdog_usec)};
    }

    // The next datagram, or nothing within `timeout`.
    std::optional<std::string> next(std::chrono::milliseconds timeout) {
        pollfd p{fd_, POLLIN, 0};
        if (::poll(&p, 1, static_cast<int>(timeout.count())) <= 0)
            return std::nullopt;
        char buffer[4096];
        ssize_t n = ::recv(fd_, buffer, sizeof(buffer), 0);
        if (n < 0)
            return std::nullopt;
        return std::string(buffer, static_cast<std::size_t>(n));
    }

    // Datagrams until one contains `what` (returned with the number of WATCHDOG=1 before it
    // in `watchdogs`), or nothing within `timeout`.
    std::optional<std::string> until(const std::string &what, std::chrono::milliseconds timeout,
                                     int *watchdogs = nullptr) {
        auto end = std::chrono::steady_clock::now() + timeout;
        while (std::chrono::steady_clock::now() < end) {
            auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
                end - std::chrono::steady_clock::now());
            auto m = next(std::max(left, std::chrono::milliseconds(1)));
            if (!m)
                return std::nullopt;
            if (m->find(what) != std::string::npos)
                return m;
            if (watchdogs && m->find("WATCHDOG=1") != std::string::npos)
                ++*watchdogs;
        }
        return std::nullopt;
    }

private:
    std::string path_;
    int fd_ = -1;
};

} // namespace envdesign::testing
