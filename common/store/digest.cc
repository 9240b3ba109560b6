#include "store/digest.h"

#include <openssl/evp.h>
#include <openssl/hmac.h>

#include <stdexcept>

namespace envdesign::store {

std::string Digest::hex() const {
    static constexpr char DIGITS[] = "0123456789abcdef";
    std::string out;
    out.reserve(2 * bytes.size());
    for (unsigned char b : bytes) {
        out.push_back(DIGITS[b >> 4]);
        out.push_back(DIGITS[b & 15]);
    }
    return out;
}

Digest sha256(std::string_view data) {
    Digest d;
    unsigned int size = 0;
    if (EVP_Digest(data.data(), data.size(), d.bytes.data(), &size, EVP_sha256(), nullptr) != 1 ||
        size != d.bytes.size())
        throw std::runtime_error("SHA-256 failed (OpenSSL)");
    return d;
}

Digest hmac_sha256(std::string_view secret, std::string_view data) {
    Digest d;
    std::size_t size = 0;
    if (!EVP_Q_mac(nullptr, "HMAC", nullptr, "SHA256", nullptr, secret.data(), secret.size(),
                   reinterpret_cast<const unsigned char *>(data.data()), data.size(),
                   d.bytes.data(), d.bytes.size(), &size) ||
        size != d.bytes.size())
        throw std::runtime_error("HMAC-SHA256 failed (OpenSSL)");
    return d;
}

} // namespace envdesign::store
