#pragma once
// LCM encoding of one message to bytes and back, outside a Bus (content hashes, chunks).

#include <stdexcept>
#include <string>

namespace envdesign::bus {

template <typename Message> std::string encode_message(const Message &message) {
    std::string bytes(static_cast<std::size_t>(message.getEncodedSize()), '\0');
    if (message.encode(bytes.data(), 0, static_cast<int>(bytes.size())) < 0)
        throw std::runtime_error("cannot encode a " + std::string(Message::getTypeName()));
    return bytes;
}

// False when the `size` bytes at `data` are not exactly one encoded Message. Never throws:
// lcm-gen's code throws (length_error, bad_alloc) on a negative or huge array length.
template <typename Message> bool decode_message(const void *data, int size, Message &message) {
    try {
        return message.decode(data, 0, size) == size;
    } catch (const std::exception &) {
        return false;
    }
}

template <typename Message> bool decode_message(const std::string &bytes, Message &message) {
    return decode_message(bytes.data(), static_cast<int>(bytes.size()), message);
}

} // namespace envdesign::bus
