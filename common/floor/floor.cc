#include "floor.h"

namespace envdesign::floor {

namespace {

// The length of the UTF-8 sequence that starts at text[i], with its code point in `code`;
// 0 if none does (a stray or missing continuation byte, an overlong form, a surrogate, a
// code point beyond U+10FFFF).
std::size_t utf8_at(const std::string &text, std::size_t i, char32_t &code) {
    auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
    unsigned char lead = byte(i);
    std::size_t length = lead < 0x80           ? 1
                         : (lead >> 5) == 0x06 ? 2
                         : (lead >> 4) == 0x0E ? 3
                         : (lead >> 3) == 0x1E ? 4
                                               : 0;
    if (length == 0 || i + length > text.size())
        return 0;
    code = length == 1 ? lead : lead & (0x7F >> length);
    for (std::size_t k = 1; k < length; ++k) {
        if ((byte(i + k) & 0xC0) != 0x80)
            return 0;
        code = (code << 6) | (byte(i + k) & 0x3F);
    }
    static constexpr char32_t least[] = {0, 0, 0x80, 0x800, 0x10000};
    if (code < least[length] || code > 0x10FFFF || (code >= 0xD800 && code <= 0xDFFF))
        return 0;
    return length;
}

bool control(char32_t code) { return code < 0x20 || code == 0x7F || (code >= 0x80 && code < 0xA0); }

} // namespace

std::string name_problem(const std::string &name) {
    if (name.size() > MAX_NAME_BYTES)
        return "is longer than " + std::to_string(MAX_NAME_BYTES) + " bytes";
    for (std::size_t i = 0; i < name.size();) {
        char32_t code = 0;
        std::size_t length = utf8_at(name, i, code);
        if (length == 0)
            return "is not UTF-8 text (byte " + std::to_string(i) + ")";
        if (control(code))
            return "holds a control character (byte " + std::to_string(i) + ")";
        i += length;
    }
    return "";
}

} // namespace envdesign::floor
