#pragma once
// Specs on the planner channels: a spec_t travels once per request as its LCM encoding, cut
// into spec_chunk_t pieces that each fit one UDP datagram (LCM 1.3.1 loses a fragmented
// message whole when one fragment is lost), and is named by the SHA-256 of that encoding.
// Jobs carry only the hash; a planner that lacks the spec asks for it (spec_need_t).
//
//   std::string bytes = bus::encode_message(spec);
//   std::string hash = content_hash(bytes);
//   for (auto &chunk : split_spec(bytes, hash, request_id, me)) bus.publish(bus::SPEC, chunk);
//   ...
//   SpecAssembler a(first_chunk);          // on a planner
//   a.add(chunk); if (a.complete()) use(a.bytes());

#include "envdesign/spec_chunk_t.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace envdesign::cluster {

inline constexpr int CHUNK_BYTES = 32000;
// The largest spec encoding (spec text and inlined PDDL files) a service takes by default:
// far above real design problems (the paper's are under 100 KB), far below what hurts.
inline constexpr std::size_t DEFAULT_MAX_SPEC_BYTES = 16u << 20;
// The most --max-spec-bytes may raise it to: a request carrying it (one LCM message) must stay
// below the bus's own cap (bus/udpm_guard.h, BUS_MAX_MESSAGE).
inline constexpr std::size_t MAX_SPEC_BYTES_LIMIT = 48u << 20;

// SHA-256 of `bytes`, lower-case hex.
std::string content_hash(const std::string &bytes);

// All chunks of `bytes`, or only those in `indices` (out-of-range ones are skipped).
std::vector<envdesign::spec_chunk_t> split_spec(const std::string &bytes, const std::string &hash,
                                                std::int64_t request_id, const std::string &sender,
                                                const std::vector<int> &indices = {});

// Why `chunk` cannot be part of a spec (sizes inconsistent, or the spec it claims to be part
// of larger than `max_spec_bytes`), or nullopt when it is fine.
std::optional<std::string> chunk_problem(const envdesign::spec_chunk_t &chunk,
                                         std::size_t max_spec_bytes = DEFAULT_MAX_SPEC_BYTES);

// Collects the chunks of one spec. Holds only what has arrived: the size a chunk claims is
// not allocated up front (two forged chunks claiming 1 GB each once took a planner to 2 GB).
class SpecAssembler {
public:
    // `first` must have passed chunk_problem.
    explicit SpecAssembler(const envdesign::spec_chunk_t &first);

    // False if `chunk` does not match the spec's sizes.
    bool add(const envdesign::spec_chunk_t &chunk);
    bool complete() const { return missing_count_ == 0; }
    std::vector<int> missing() const;
    // Bytes held so far.
    std::size_t received_bytes() const { return received_bytes_; }
    // The whole encoding once complete; its hash still needs checking.
    std::string bytes() const;

private:
    std::int32_t total_bytes_;
    std::vector<std::string> chunks_; // empty: not arrived (every chunk has at least 1 byte)
    int missing_count_;
    std::size_t received_bytes_ = 0;
};

} // namespace envdesign::cluster
