#pragma once
// The bus keys of a deployment: a small text file, one key a line, "KEY_ID HEX_SECRET".
//
//   # envdesign bus keys: the first signs, every one verifies (rotation: deploy/LAN.md)
//   2026-11 4f0c...   (64 hex digits: `openssl rand -hex 32`)
//   2026-05 9a1e...
//
// Blank lines and lines starting with '#' are skipped. A key id is 1-8 characters of
// [A-Za-z0-9._-]; a secret is 32-64 bytes in hex. The file must be owned by the user that
// reads it (or root) and must not be readable or writable by group or others (mode 0600 or
// 0400): a key others can read authenticates nothing.

#include <cstddef>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace envdesign::bus {

class KeyFileError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

struct Key {
    std::string id;     // 1-8 characters, sent with every message
    std::string secret; // raw bytes
};

struct KeyRing {
    static constexpr std::size_t MAX_KEYS = 8;
    static constexpr std::size_t MAX_ID = 8;
    std::vector<Key> keys; // keys[0] signs; all verify. Never empty once loaded.

    const Key *find(const std::string &id) const;
};

// Parses the text of a key file; `source` names it in errors ("FILE:LINE: ..."). Throws
// KeyFileError for a malformed line, a repeated id, no key or too many keys.
KeyRing parse_key_ring(const std::string &text, const std::string &source);

// Reads and parses `path` after checking its permissions (see above). Throws KeyFileError.
KeyRing load_key_file(const std::string &path);

// The key file to use: `flag` if given, else $ENVDESIGN_KEY_FILE if set and not empty.
std::optional<std::string> key_file_path(const std::string &flag);

} // namespace envdesign::bus
