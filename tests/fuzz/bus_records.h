#pragma once
// The input format of the bus fuzz targets: records of
//   [1 byte: channel, modulo the target's channel list][2 bytes: length, little endian][bytes]
// each published raw on a memq:// bus, so that the service core's own subscriptions decode
// and handle them as they would datagrams from the network. A simple format, so that
// make_seeds.cc can write valid messages for the corpus and libFuzzer can splice them.

#include "bus/bus.h"

#include <spdlog/sinks/null_sink.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace envdesign::fuzz {

struct BusRecord {
    int channel = 0;
    std::string bytes;
};

inline std::vector<BusRecord> read_records(const std::uint8_t *data, std::size_t size,
                                           int channels) {
    std::vector<BusRecord> records;
    std::size_t at = 0;
    while (at + 3 <= size) {
        BusRecord r;
        r.channel = data[at] % channels;
        std::size_t length = data[at + 1] | (static_cast<std::size_t>(data[at + 2]) << 8);
        at += 3;
        length = std::min(length, size - at);
        r.bytes.assign(reinterpret_cast<const char *>(data + at), length);
        at += length;
        records.push_back(std::move(r));
    }
    return records;
}

inline std::string write_record(int channel, const std::string &bytes) {
    std::string out;
    out += static_cast<char>(channel);
    out += static_cast<char>(bytes.size() & 0xff);
    out += static_cast<char>((bytes.size() >> 8) & 0xff);
    return out + bytes;
}

inline std::shared_ptr<spdlog::logger> quiet_logger() {
    return std::make_shared<spdlog::logger>("fuzz",
                                            std::make_shared<spdlog::sinks::null_sink_mt>());
}

} // namespace envdesign::fuzz
