#include "bus/key_file.h"

#include <cctype>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <set>
#include <sstream>
#include <sys/stat.h>
#include <unistd.h>

namespace envdesign::bus {
namespace {

bool valid_id(const std::string &id) {
    if (id.empty() || id.size() > KeyRing::MAX_ID)
        return false;
    for (char c : id)
        if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '_' || c == '-'))
            return false;
    return true;
}

int hex_digit(char c) {
    if (c >= '0' && c <= '9')
        return c - '0';
    if (c >= 'a' && c <= 'f')
        return c - 'a' + 10;
    if (c >= 'A' && c <= 'F')
        return c - 'A' + 10;
    return -1;
}

std::optional<std::string> from_hex(const std::string &hex) {
    if (hex.size() % 2 != 0)
        return std::nullopt;
    std::string bytes;
    for (std::size_t i = 0; i < hex.size(); i += 2) {
        int high = hex_digit(hex[i]), low = hex_digit(hex[i + 1]);
        if (high < 0 || low < 0)
            return std::nullopt;
        bytes.push_back(static_cast<char>(high * 16 + low));
    }
    return bytes;
}

Key parse_line(const std::string &line, const std::string &where) {
    std::istringstream in(line);
    std::string id, hex, extra;
    in >> id >> hex >> extra;
    if (hex.empty() || !extra.empty())
        throw KeyFileError(where + ": expected 'KEY_ID HEX_SECRET'");
    if (!valid_id(id))
        throw KeyFileError(where + ": key id '" + id + "' is not 1-8 of [A-Za-z0-9._-]");
    auto secret = from_hex(hex);
    if (!secret)
        throw KeyFileError(where + ": the secret of key '" + id + "' is not hexadecimal");
    if (secret->size() < 32 || secret->size() > 64)
        throw KeyFileError(where + ": the secret of key '" + id + "' has " +
                           std::to_string(secret->size()) +
                           " bytes; use 32 to 64 (openssl rand -hex 32)");
    return Key{id, *secret};
}

} // namespace

const Key *KeyRing::find(const std::string &id) const {
    for (const Key &key : keys)
        if (key.id == id)
            return &key;
    return nullptr;
}

KeyRing parse_key_ring(const std::string &text, const std::string &source) {
    KeyRing ring;
    std::set<std::string> ids;
    std::istringstream in(text);
    std::string line;
    for (int number = 1; std::getline(in, line); ++number) {
        auto first = line.find_first_not_of(" \t\r");
        if (first == std::string::npos || line[first] == '#')
            continue;
        std::string where = source + ":" + std::to_string(number);
        Key key = parse_line(line, where);
        if (!ids.insert(key.id).second)
            throw KeyFileError(where + ": key id '" + key.id + "' appears twice");
        if (ring.keys.size() == KeyRing::MAX_KEYS)
            throw KeyFileError(where + ": more than " + std::to_string(KeyRing::MAX_KEYS) +
                               " keys");
        ring.keys.push_back(std::move(key));
    }
    if (ring.keys.empty())
        throw KeyFileError(source + ": no key (expected lines 'KEY_ID HEX_SECRET')");
    return ring;
}

KeyRing load_key_file(const std::string &path) {
    // Open first, then check what was opened: no window for a swap between check and read.
    int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NOFOLLOW | O_NONBLOCK);
    if (fd < 0)
        throw KeyFileError(path + ": cannot open the key file: " + std::strerror(errno));
    struct stat st {};
    std::string text;
    try {
        if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode))
            throw KeyFileError(path + ": the key file is not a regular file");
        if ((st.st_mode & 077) != 0)
            throw KeyFileError(path + ": the key file is accessible by group or others (mode " +
                               (std::ostringstream() << std::oct << (st.st_mode & 0777)).str() +
                               "); chmod 600 it");
        if (st.st_uid != ::geteuid() && st.st_uid != 0)
            throw KeyFileError(path + ": the key file belongs to another user");
        if (st.st_size > 64 * 1024)
            throw KeyFileError(path + ": the key file is larger than 64 KiB");
        char buffer[4096];
        for (ssize_t n; (n = ::read(fd, buffer, sizeof buffer)) > 0 && text.size() <= 65536;)
            text.append(buffer, static_cast<std::size_t>(n));
    } catch (...) {
        ::close(fd);
        throw;
    }
    ::close(fd);
    return parse_key_ring(text, path);
}

std::optional<std::string> key_file_path(const std::string &flag) {
    if (!flag.empty())
        return flag;
    const char *env = std::getenv("ENVDESIGN_KEY_FILE");
    if (env && *env)
        return std::string(env);
    return std::nullopt;
}

} // namespace envdesign::bus
