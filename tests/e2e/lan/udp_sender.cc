// The sending side of udp_shim_test.cc, run with the shim preloaded: COUNT datagrams, each
// its 4-byte sequence number (0, 1, ...), sent with one of the calls the shim wraps.
//
//   udp_sender udp PORT COUNT sendto|sendmsg|sendmmsg|send [LINGER_MS]   (to 127.0.0.1:PORT)
//   udp_sender unix PATH COUNT                               (a unix datagram socket)
//
// It pauses 1 ms every 50 datagrams so that the receiver's buffer never overflows: any
// datagram missing at the receiver is the shim's doing. LINGER_MS: it stays that long after
// the last send before it exits.

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <sys/un.h>
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>

namespace {

int usage() {
    std::fprintf(stderr, "usage: udp_sender udp PORT COUNT sendto|sendmsg|sendmmsg|send "
                         "[LINGER_MS]\n"
                         "       udp_sender unix PATH COUNT\n");
    return 2;
}

void pace(std::uint32_t sequence) {
    if (sequence % 50 == 49)
        usleep(1000);
}

int send_udp(int port, std::uint32_t count, const std::string &call) {
    int fd = socket(AF_INET, SOCK_DGRAM, 0);
    sockaddr_in to{};
    to.sin_family = AF_INET;
    to.sin_port = htons(static_cast<std::uint16_t>(port));
    to.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    auto *address = reinterpret_cast<sockaddr *>(&to);
    if (call == "send" && connect(fd, address, sizeof to) != 0) {
        std::perror("udp_sender: connect");
        return 1;
    }
    for (std::uint32_t i = 0; i < count; ++i) {
        std::uint32_t sequence = i;
        iovec iov{&sequence, sizeof sequence};
        msghdr m{};
        m.msg_name = &to;
        m.msg_namelen = sizeof to;
        m.msg_iov = &iov;
        m.msg_iovlen = 1;
        ssize_t n = -1;
        if (call == "sendto") {
            n = sendto(fd, &sequence, sizeof sequence, 0, address, sizeof to);
        } else if (call == "sendmsg") {
            n = sendmsg(fd, &m, 0);
        } else if (call == "sendmmsg") {
            mmsghdr one{m, 0};
            n = sendmmsg(fd, &one, 1, 0) == 1 ? one.msg_len : -1;
        } else if (call == "send") {
            n = send(fd, &sequence, sizeof sequence, 0);
        } else {
            return usage();
        }
        if (n != sizeof sequence) {
            std::perror("udp_sender: send");
            return 1;
        }
        pace(i);
    }
    close(fd);
    return 0;
}

int send_unix(const std::string &path, std::uint32_t count) {
    int fd = socket(AF_UNIX, SOCK_DGRAM, 0);
    sockaddr_un to{};
    to.sun_family = AF_UNIX;
    std::strncpy(to.sun_path, path.c_str(), sizeof to.sun_path - 1);
    for (std::uint32_t i = 0; i < count; ++i) {
        if (sendto(fd, &i, sizeof i, 0, reinterpret_cast<sockaddr *>(&to), sizeof to) != sizeof i) {
            std::perror("udp_sender: sendto");
            return 1;
        }
        pace(i);
    }
    close(fd);
    return 0;
}

} // namespace

int main(int argc, char **argv) {
    if ((argc == 5 || argc == 6) && std::string(argv[1]) == "udp") {
        int code =
            send_udp(std::stoi(argv[2]), static_cast<std::uint32_t>(std::stoul(argv[3])), argv[4]);
        if (argc == 6)
            usleep(static_cast<useconds_t>(std::stoi(argv[5])) * 1000);
        return code;
    }
    if (argc == 4 && std::string(argv[1]) == "unix")
        return send_unix(argv[2], static_cast<std::uint32_t>(std::stoul(argv[3])));
    return usage();
}
