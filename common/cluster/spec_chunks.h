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

// SHA-256 of `bytes`, lower-case hex.
std::string content_hash(const std::string &bytes);

// All chunks of `bytes`, or only those in `indices` (out-of-range ones are skipped).
std::vector<envdesign::spec_chunk_t> split_spec(const std::string &bytes, const std::string &hash,
                                                std::int64_t request_id, const std::string &sender,
                                                const std::vector<int> &indices = {});

// Why `chunk` cannot be part of a spec (sizes inconsistent), or nullopt when it is fine.
std::optional<std::string> chunk_problem(const envdesign::spec_chunk_t &chunk);

// Collects the chunks of one spec.
class SpecAssembler {
public:
    // `first` must have passed chunk_problem.
    explicit SpecAssembler(const envdesign::spec_chunk_t &first);

    // False if `chunk` does not match the spec's sizes.
    bool add(const envdesign::spec_chunk_t &chunk);
    bool complete() const { return missing_count_ == 0; }
    std::vector<int> missing() const;
    // The whole encoding once complete; its hash still needs checking.
    const std::string &bytes() const { return bytes_; }

private:
    std::string bytes_;
    std::vector<bool> have_;
    int missing_count_;
};

} // namespace envdesign::cluster
