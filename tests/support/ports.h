#pragma once
// The one allocator of UDP ports for tests that start an LCM bus (tests/support/test_ports.py is
// its Python twin over the same claims). ctest runs many test processes at once, and LCM
// cannot receive on a port another socket holds without SO_REUSEADDR ("bind: Address already
// in use"), so each test process claims ports no other running test holds:
//   - a claim is an flock on /tmp/envdesign-test-ports/<port>, held until the process exits
//     (the kernel drops it then, even after a crash);
//   - a claimed port is also checked free by binding it;
//   - ports come from 20000-32767: below Linux's ephemeral range (32768-60999), where any
//     socket's automatic port may land, and off Cyclone DDS's domain ports (7400 + 250 d +
//     0..111 with up to 50 participants, deploy/cyclonedds-loopback.xml).
//
//   std::string url = testing::udpm_test_url(testing::claim_udp_port());

#include <fcntl.h>
#include <netinet/in.h>
#include <sys/file.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdint>
#include <stdexcept>
#include <string>

namespace envdesign::testing {

inline constexpr int TEST_PORT_FIRST = 20000;
inline constexpr int TEST_PORT_LAST = 32767;

// A UDP socket bound to `port` on every address without SO_REUSEADDR, as a program that
// does not share its port holds it; -1 when the port is taken.
inline int bind_udp_port_unshared(int port) {
    int fd = socket(AF_INET, SOCK_DGRAM, 0);
    if (fd < 0)
        return -1;
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_port = htons(static_cast<std::uint16_t>(port));
    address.sin_addr.s_addr = htonl(INADDR_ANY);
    if (bind(fd, reinterpret_cast<sockaddr *>(&address), sizeof address) == 0)
        return fd;
    close(fd);
    return -1;
}

// True when no socket of any process is bound to UDP `port`.
inline bool udp_port_is_free(int port) {
    int fd = bind_udp_port_unshared(port);
    if (fd >= 0)
        close(fd);
    return fd >= 0;
}

// A UDP port for this process alone; throws when every port of the range is taken.
inline int claim_udp_port() {
    const std::string dir = "/tmp/envdesign-test-ports";
    mkdir(dir.c_str(), 0777); // exists already in every test but the first
    const int span = TEST_PORT_LAST - TEST_PORT_FIRST + 1;
    // Start where the process id points, so that concurrent tests rarely try the same ports.
    int start = static_cast<int>((static_cast<long>(getpid()) * 7919L) % span);
    for (int i = 0; i < span; ++i) {
        int port = TEST_PORT_FIRST + (start + i) % span;
        if ((port - 7400) % 250 < 112)
            continue;
        std::string lock = dir + "/" + std::to_string(port);
        int fd = open(lock.c_str(), O_CREAT | O_RDWR | O_CLOEXEC, 0666);
        if (fd < 0)
            continue;
        if (flock(fd, LOCK_EX | LOCK_NB) == 0 && udp_port_is_free(port))
            return port; // `fd` stays open: the claim lasts as long as the process
        close(fd);
    }
    throw std::runtime_error("no free UDP port for a test in " + std::to_string(TEST_PORT_FIRST) +
                             "-" + std::to_string(TEST_PORT_LAST));
}

// The loopback udpm URL of a test on `port` (ttl=0: nothing leaves this machine).
inline std::string udpm_test_url(int port) {
    return "udpm://239.255.76.67:" + std::to_string(port) + "?ttl=0";
}

} // namespace envdesign::testing
