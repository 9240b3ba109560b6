#pragma once
// A guard in front of LCM 1.3.1's udpm reassembly (Debian's liblcm1, issue 10). LCM checks a
// fragment with `fragment_offset + size > message size` in 32-bit arithmetic: an offset
// near 2^32 wraps the sum below the size, and the fragment is copied ~4 GB past the message's
// buffer. One forged datagram, before any MAC of ours is checked, so writes into (or crashes)
// every process on the bus (valgrind: "Invalid write ... liblcm.so" on the receive thread).
// The guard attaches a socket filter (classic BPF) to LCM's receive socket that drops
// fragments whose offset lies beyond any message LCM takes (LCM_MAX_MESSAGE_SIZE, 2^28):
// no genuine fragment has one, and below it the sum cannot wrap, so LCM's own check holds.
// It also drops the fragments of a message larger than BUS_MAX_MESSAGE (issue 21: one
// unsigned 250 MB message took a coordinator to 506 MB and stalled it for a second while
// LCM reassembled it, before any check of ours could refuse it).
//
//   lcm::LCM lcm(url);
//   lcm.getFileno();                   // LCM opens its receive socket lazily
//   guard_udpm_fragments(*udpm_port(url));

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace envdesign::bus {

// The largest message LCM 1.3.1 reassembles (lcm.h's LCM_MAX_MESSAGE_SIZE).
inline constexpr std::uint32_t LCM_MAX_MESSAGE = 1u << 28;
// The largest message our services take: a request's spec is at most 48 MiB
// (MAX_SPEC_BYTES_LIMIT, cluster/spec_chunks.h), and everything else is far smaller.
inline constexpr std::uint32_t BUS_MAX_MESSAGE = 64u << 20;

// The multicast port of a udpm:// URL (LCM's default 7667 when it names none); nothing for
// other providers.
std::optional<std::uint16_t> udpm_port(const std::string &url);

// Attaches the filter to every UDP socket of this process bound to the wildcard address on
// `port` (LCM's receive sockets; its send socket is bound elsewhere). Returns how many.
int guard_udpm_fragments(std::uint16_t port);

// The number of filter instructions on socket `fd` (0: none), for tests.
int socket_filter_length(int fd);

// This process's UDP sockets bound to the wildcard address on `port`.
std::vector<int> udpm_receive_sockets(std::uint16_t port);

} // namespace envdesign::bus
