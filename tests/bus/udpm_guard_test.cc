// The guard in front of LCM 1.3.1's fragment reassembly (bus/udpm_guard.h), over udpm on
// loopback: a forged fragment whose offset wraps LCM's 32-bit bounds check is copied ~4 GB
// past its buffer by plain LCM (shown in a child process: it delivers the forged message, or
// dies), and never reaches LCM through a Bus; genuine fragmented messages still arrive.

#include "bus/bus.h"
#include "bus/udpm_guard.h"

#include "bus_test_support.h"

#include "../support/ports.h"

#include <gtest/gtest.h>
#include <lcm/lcm-cpp.hpp>

#include <arpa/inet.h>
#include <cstring>
#include <netinet/in.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

namespace envdesign::bus {
namespace {

const std::uint16_t PORT = static_cast<std::uint16_t>(testing::claim_udp_port());
const std::string URL = testing::udpm_test_url(PORT);
const std::string CHANNEL = "GUARD_TEST";

// Raw LC03 datagrams to the test's group, from one socket (LCM keys reassembly by sender).
class Sender {
public:
    Sender() : fd_(::socket(AF_INET, SOCK_DGRAM, 0)) {
        unsigned char ttl = 0;
        ::setsockopt(fd_, IPPROTO_IP, IP_MULTICAST_TTL, &ttl, sizeof ttl);
        group_.sin_family = AF_INET;
        group_.sin_port = htons(PORT);
        inet_pton(AF_INET, "239.255.76.67", &group_.sin_addr);
    }
    ~Sender() { ::close(fd_); }
    void fragment(std::uint32_t seqno, std::uint32_t size, std::uint32_t offset, std::uint16_t no,
                  std::uint16_t of, const std::string &payload) {
        std::uint32_t words[4] = {htonl(0x4c433033), htonl(seqno), htonl(size), htonl(offset)};
        std::uint16_t shorts[2] = {htons(no), htons(of)};
        std::string d(reinterpret_cast<const char *>(words), 16);
        d.append(reinterpret_cast<const char *>(shorts), 4);
        d += no == 0 ? CHANNEL + std::string(1, '\0') + payload : payload;
        ::sendto(fd_, d.data(), d.size(), 0, reinterpret_cast<sockaddr *>(&group_), sizeof group_);
        usleep(20'000);
    }
    // A 1000-byte message whose second fragment's offset wraps: 0xFFFFFF00 + 400 = 144 (mod
    // 2^32), inside the message by LCM's check; its copy lands 4 GB past the buffer.
    void forged(std::uint32_t seqno) {
        fragment(seqno, 1000, 0, 0, 2, std::string(600, 'f'));
        fragment(seqno, 1000, 0xFFFFFF00u, 1, 2, std::string(400, 'F'));
    }
    void genuine(std::uint32_t seqno, const std::string &message) {
        fragment(seqno, static_cast<std::uint32_t>(message.size()), 0, 0, 2,
                 message.substr(0, 600));
        fragment(seqno, static_cast<std::uint32_t>(message.size()), 600, 1, 2, message.substr(600));
    }

private:
    int fd_;
    sockaddr_in group_{};
};

TEST(UdpmGuard, PortOfUrl) {
    EXPECT_EQ(udpm_port("udpm://239.255.76.67:7668?ttl=0"), std::optional<std::uint16_t>(7668));
    EXPECT_EQ(udpm_port("udpm://239.255.76.67"), std::optional<std::uint16_t>(7667));
    EXPECT_EQ(udpm_port("udpm://239.255.76.67:70000"), std::nullopt);
    EXPECT_EQ(udpm_port("memq://"), std::nullopt);
}

void on_message(const lcm::ReceiveBuffer *buffer, const std::string &, int *received) {
    *received = static_cast<int>(buffer->data_size);
}

// Plain LCM in a child: 0 if it delivered the forged message, 1 if not; killed by a signal
// if the stray copy hit unmapped memory.
int plain_lcm_child(int ready_fd) {
    lcm::LCM lcm(URL);
    int received = 0;
    lcm.subscribeFunction<int *>(CHANNEL, &on_message, &received);
    char ok = 1;
    if (::write(ready_fd, &ok, 1) != 1)
        return 3;
    for (int i = 0; i < 40 && received == 0; ++i)
        lcm.handleTimeout(50);
    return received == 1000 ? 0 : 1;
}

TEST(UdpmGuard, PlainLcmTakesTheWrappingFragment) {
    int ready[2];
    ASSERT_EQ(::pipe(ready), 0);
    pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0)
        ::_exit(plain_lcm_child(ready[1]));
    char byte = 0;
    ASSERT_EQ(::read(ready[0], &byte, 1), 1);
    Sender().forged(1);
    int status = 0;
    ASSERT_EQ(::waitpid(child, &status, 0), child);
    EXPECT_TRUE(WIFSIGNALED(status) || (WIFEXITED(status) && WEXITSTATUS(status) == 0))
        << "plain LCM ignored the wrapping fragment: exit " << WEXITSTATUS(status);
    ::close(ready[0]);
    ::close(ready[1]);
}

TEST(UdpmGuard, ABusDropsTheWrappingFragmentAndTakesGenuineOnes) {
    Bus bus(URL, quiet());
    std::vector<std::string> heard;
    auto sub = bus.subscribe_raw(CHANNEL, [&](const void *data, int size) {
        heard.emplace_back(static_cast<const char *>(data), static_cast<std::size_t>(size));
    });
    std::vector<int> sockets = udpm_receive_sockets(PORT);
    ASSERT_FALSE(sockets.empty());
    for (int fd : sockets)
        EXPECT_EQ(socket_filter_length(fd), 8);
    Sender sender;
    sender.forged(1);
    std::string message(1000, 'g');
    message[999] = 'G';
    sender.genuine(2, message);
    for (int i = 0; i < 40 && heard.empty(); ++i)
        bus.handle(std::chrono::milliseconds(50));
    drain(bus);
    EXPECT_EQ(heard, std::vector<std::string>{message});
}

// A port another program holds without SO_REUSEADDR: LCM prints "bind: Address already in
// use" and would go on deaf (a test once crashed that way when two tests met on one port).
// The subscription throws instead, naming the port, and the bus stays usable for nothing else.
TEST(UdpmGuard, APortHeldWithoutSharingIsAnErrorAtSubscription) {
    int port = testing::claim_udp_port();
    int fd = testing::bind_udp_port_unshared(port);
    ASSERT_GE(fd, 0);
    Bus bus(testing::udpm_test_url(port), quiet());
    try {
        auto sub = bus.subscribe_raw(CHANNEL, [](const void *, int) {});
        ADD_FAILURE() << "subscribed on a port another socket holds";
    } catch (const BusError &e) {
        EXPECT_NE(std::string(e.what()).find("UDP port " + std::to_string(port)), std::string::npos)
            << e.what();
    }
    ::close(fd);
}

// Issue 21: fragments of a 250 MB message (unsigned) made LCM allocate and reassemble it
// before any check of ours. The filter on a UDP socket of the port: a fragment of a message
// beyond BUS_MAX_MESSAGE never arrives, one of a message within it does.
TEST(UdpmGuard, FragmentsOfAMessageBeyondTheBusLimitAreDropped) {
    std::uint16_t port = static_cast<std::uint16_t>(testing::claim_udp_port());
    int fd = testing::bind_udp_port_unshared(port);
    ASSERT_GE(fd, 0);
    ASSERT_EQ(guard_udpm_fragments(port), 1);
    timeval wait{0, 300'000};
    ::setsockopt(fd, SOL_SOCKET, SO_RCVTIMEO, &wait, sizeof wait);
    int out = ::socket(AF_INET, SOCK_DGRAM, 0);
    sockaddr_in to{};
    to.sin_family = AF_INET;
    to.sin_port = htons(port);
    to.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    auto delivered = [&](std::uint32_t message_size) {
        std::uint32_t words[4] = {htonl(0x4c433033), htonl(9), htonl(message_size), htonl(0)};
        std::string d(reinterpret_cast<const char *>(words), 16);
        d += std::string(4, '\0') + CHANNEL + std::string(1, '\0') + std::string(600, 'h');
        ::sendto(out, d.data(), d.size(), 0, reinterpret_cast<sockaddr *>(&to), sizeof to);
        char buffer[2048];
        return ::recv(fd, buffer, sizeof buffer, 0) > 0;
    };
    EXPECT_FALSE(delivered(250u << 20));
    EXPECT_FALSE(delivered(BUS_MAX_MESSAGE + 1));
    EXPECT_TRUE(delivered(BUS_MAX_MESSAGE));
    EXPECT_TRUE(delivered(1000));
    ::close(out);
    ::close(fd);
}

} // namespace
} // namespace envdesign::bus
