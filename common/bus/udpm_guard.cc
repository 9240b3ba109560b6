#include "bus/udpm_guard.h"

#include <arpa/inet.h>
#include <filesystem>
#include <linux/filter.h>
#include <netinet/in.h>
#include <sys/socket.h>

namespace envdesign::bus {
namespace {

constexpr std::uint32_t LCM_FRAGMENT_MAGIC = 0x4c433033; // "LC03"
// The filter sees the datagram from its UDP header (8 bytes) on.
constexpr std::uint32_t LCM_HEADER = 8;
constexpr std::uint32_t MESSAGE_SIZE = LCM_HEADER + 8; // magic, seqno, size, offset
constexpr std::uint32_t FRAGMENT_OFFSET = LCM_HEADER + 12;

// Accept everything but a fragment whose offset is beyond LCM_MAX_MESSAGE, or of a message
// beyond BUS_MAX_MESSAGE.
sock_filter FILTER[] = {
    BPF_STMT(BPF_LD | BPF_W | BPF_ABS, LCM_HEADER),
    BPF_JUMP(BPF_JMP | BPF_JEQ | BPF_K, LCM_FRAGMENT_MAGIC, 0, 5), // not a fragment: accept
    BPF_STMT(BPF_LD | BPF_W | BPF_ABS, FRAGMENT_OFFSET),
    BPF_JUMP(BPF_JMP | BPF_JGT | BPF_K, LCM_MAX_MESSAGE, 2, 0),
    BPF_STMT(BPF_LD | BPF_W | BPF_ABS, MESSAGE_SIZE),
    BPF_JUMP(BPF_JMP | BPF_JGT | BPF_K, BUS_MAX_MESSAGE, 0, 1),
    BPF_STMT(BPF_RET | BPF_K, 0), // drop
    BPF_STMT(BPF_RET | BPF_K, 0xFFFFFFFF),
};

bool bound_to(int fd, std::uint16_t port) {
    int type = 0;
    socklen_t length = sizeof type;
    if (getsockopt(fd, SOL_SOCKET, SO_TYPE, &type, &length) != 0 || type != SOCK_DGRAM)
        return false;
    sockaddr_in address{};
    length = sizeof address;
    if (getsockname(fd, reinterpret_cast<sockaddr *>(&address), &length) != 0 ||
        address.sin_family != AF_INET)
        return false;
    return ntohs(address.sin_port) == port && address.sin_addr.s_addr == htonl(INADDR_ANY);
}

} // namespace

std::optional<std::uint16_t> udpm_port(const std::string &url) {
    if (url.rfind("udpm://", 0) != 0)
        return std::nullopt;
    std::string rest = url.substr(7, url.find('?') - 7);
    auto colon = rest.find(':');
    if (colon == std::string::npos)
        return 7667;
    try {
        int port = std::stoi(rest.substr(colon + 1));
        if (port > 0 && port < 65536)
            return static_cast<std::uint16_t>(port);
    } catch (const std::exception &) {
    }
    return std::nullopt;
}

std::vector<int> udpm_receive_sockets(std::uint16_t port) {
    std::vector<int> sockets;
    std::error_code error;
    for (const auto &entry : std::filesystem::directory_iterator("/proc/self/fd", error)) {
        int fd = -1;
        try {
            fd = std::stoi(entry.path().filename().string());
        } catch (const std::exception &) {
            continue;
        }
        if (bound_to(fd, port))
            sockets.push_back(fd);
    }
    return sockets;
}

int guard_udpm_fragments(std::uint16_t port) {
    sock_fprog program{static_cast<unsigned short>(std::size(FILTER)), FILTER};
    int guarded = 0;
    for (int fd : udpm_receive_sockets(port))
        if (setsockopt(fd, SOL_SOCKET, SO_ATTACH_FILTER, &program, sizeof program) == 0)
            ++guarded;
    return guarded;
}

int socket_filter_length(int fd) {
    // SO_GET_FILTER with no buffer answers the number of instructions.
    socklen_t length = 0;
    if (getsockopt(fd, SOL_SOCKET, SO_GET_FILTER, nullptr, &length) != 0)
        return 0;
    return static_cast<int>(length);
}

} // namespace envdesign::bus
