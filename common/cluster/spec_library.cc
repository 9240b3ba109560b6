#include "cluster/spec_library.h"

#include "cluster/spec_chunks.h"

#include <algorithm>

namespace envdesign::cluster {

std::vector<envdesign::spec_chunk_t>
SpecLibrary::add(const std::string &hash, const std::string &bytes, std::int64_t request_id) {
    std::lock_guard lock(mutex_);
    Entry &entry = specs_[hash];
    ++entry.users;
    entry.bytes = bytes;
    auto chunks = split_spec(bytes, hash, request_id, sender_);
    entry.sent.assign(chunks.size(), Clock::now());
    return chunks;
}

void SpecLibrary::release(const std::string &hash) {
    std::lock_guard lock(mutex_);
    auto it = specs_.find(hash);
    if (it != specs_.end() && --it->second.users <= 0)
        specs_.erase(it);
}

bool SpecLibrary::has(const std::string &hash) const {
    std::lock_guard lock(mutex_);
    return specs_.count(hash) > 0;
}

std::vector<envdesign::spec_chunk_t> SpecLibrary::need(const std::string &hash,
                                                       const std::vector<int> &missing,
                                                       std::int64_t request_id,
                                                       Clock::time_point now) {
    std::lock_guard lock(mutex_);
    auto it = specs_.find(hash);
    if (it == specs_.end())
        return {};
    Entry &entry = it->second;
    auto recent = now - std::chrono::duration_cast<Clock::duration>(
                            std::chrono::duration<double>(min_interval_s_));
    std::vector<int> wanted;
    for (std::size_t i = 0; i < entry.sent.size(); ++i) {
        bool asked = missing.empty() || std::find(missing.begin(), missing.end(),
                                                  static_cast<int>(i)) != missing.end();
        if (asked && entry.sent[i] <= recent) {
            wanted.push_back(static_cast<int>(i));
            entry.sent[i] = now;
        }
    }
    if (wanted.empty())
        return {};
    return split_spec(entry.bytes, hash, request_id, sender_, wanted);
}

} // namespace envdesign::cluster
