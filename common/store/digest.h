#pragma once
// SHA-256 content digests (OpenSSL libcrypto): the names of durable records
// (record_db.h). A digest is computed over a canonical text that starts with a format
// version, so that a change of what a record means changes every name.

#include <array>
#include <compare>
#include <string>
#include <string_view>

namespace envdesign::store {

struct Digest {
    std::array<unsigned char, 32> bytes{};

    auto operator<=>(const Digest &) const = default;
    std::string hex() const; // 64 lower-case hex digits
};

Digest sha256(std::string_view data);
Digest hmac_sha256(std::string_view secret, std::string_view data); // the store's record tags

} // namespace envdesign::store
