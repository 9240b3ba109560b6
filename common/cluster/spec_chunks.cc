#include "cluster/spec_chunks.h"

#include "bus/log.h"

#include <glib.h>

#include <memory>

namespace envdesign::cluster {

std::string content_hash(const std::string &bytes) {
    std::unique_ptr<gchar, decltype(&g_free)> hex(
        g_compute_checksum_for_data(G_CHECKSUM_SHA256,
                                    reinterpret_cast<const guchar *>(bytes.data()), bytes.size()),
        &g_free);
    return hex ? std::string(hex.get()) : std::string();
}

std::vector<envdesign::spec_chunk_t> split_spec(const std::string &bytes, const std::string &hash,
                                                std::int64_t request_id, const std::string &sender,
                                                const std::vector<int> &indices) {
    int count = static_cast<int>((bytes.size() + CHUNK_BYTES - 1) / CHUNK_BYTES);
    std::vector<int> wanted = indices;
    if (wanted.empty())
        for (int i = 0; i < count; ++i)
            wanted.push_back(i);
    std::vector<envdesign::spec_chunk_t> chunks;
    for (int i : wanted) {
        if (i < 0 || i >= count)
            continue;
        envdesign::spec_chunk_t c;
        c.utime = bus::now_utime();
        c.request_id = request_id;
        c.sender = sender;
        c.spec_hash = hash;
        c.total_bytes = static_cast<std::int32_t>(bytes.size());
        c.chunk_index = static_cast<std::int16_t>(i);
        c.num_chunks = static_cast<std::int16_t>(count);
        std::size_t begin = static_cast<std::size_t>(i) * CHUNK_BYTES;
        std::size_t size = std::min<std::size_t>(CHUNK_BYTES, bytes.size() - begin);
        c.data.assign(bytes.begin() + begin, bytes.begin() + begin + size);
        c.num_bytes = static_cast<std::int16_t>(size);
        chunks.push_back(std::move(c));
    }
    return chunks;
}

std::optional<std::string> chunk_problem(const envdesign::spec_chunk_t &c,
                                         std::size_t max_spec_bytes) {
    if (c.spec_hash.size() != 64)
        return "the spec hash is not 64 hex digits";
    if (c.total_bytes > 0 && static_cast<std::size_t>(c.total_bytes) > max_spec_bytes)
        return "the spec claims " + std::to_string(c.total_bytes) + " bytes, more than the " +
               std::to_string(max_spec_bytes) + " taken";
    if (c.total_bytes <= 0 || c.num_chunks <= 0 ||
        c.num_chunks != (c.total_bytes + CHUNK_BYTES - 1) / CHUNK_BYTES)
        return "the chunk count does not match the size";
    if (c.chunk_index < 0 || c.chunk_index >= c.num_chunks)
        return "the chunk index is out of range";
    long long begin = static_cast<long long>(c.chunk_index) * CHUNK_BYTES;
    if (c.num_bytes != std::min<long long>(CHUNK_BYTES, c.total_bytes - begin))
        return "the chunk has the wrong length";
    return std::nullopt;
}

SpecAssembler::SpecAssembler(const envdesign::spec_chunk_t &first)
    : total_bytes_(first.total_bytes), chunks_(static_cast<std::size_t>(first.num_chunks)),
      missing_count_(first.num_chunks) {}

bool SpecAssembler::add(const envdesign::spec_chunk_t &c) {
    if (chunk_problem(c, static_cast<std::size_t>(total_bytes_)) || c.total_bytes != total_bytes_ ||
        c.num_chunks != static_cast<std::int16_t>(chunks_.size()))
        return false;
    std::string &slot = chunks_[static_cast<std::size_t>(c.chunk_index)];
    if (slot.empty()) {
        slot.assign(c.data.begin(), c.data.end());
        received_bytes_ += slot.size();
        --missing_count_;
    }
    return true;
}

std::string SpecAssembler::bytes() const {
    std::string out;
    out.reserve(received_bytes_);
    for (const auto &chunk : chunks_)
        out += chunk;
    return out;
}

std::vector<int> SpecAssembler::missing() const {
    std::vector<int> out;
    for (std::size_t i = 0; i < chunks_.size(); ++i)
        if (chunks_[i].empty())
            out.push_back(static_cast<int>(i));
    return out;
}

} // namespace envdesign::cluster
