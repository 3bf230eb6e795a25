#include "io/printable_text.hpp"

#include <cstdint>
#include <cstdio>

namespace shadowlab {
namespace {

// The length of the well-formed UTF-8 sequence starting at `at` (RFC 3629: no overlong form, no
// surrogate, nothing above U+10FFFF), or 0 when the byte there starts none.
std::size_t sequence_length(std::string_view bytes, std::size_t at) {
    const auto byte = [&](std::size_t i) { return static_cast<std::uint8_t>(bytes[i]); };
    const std::uint8_t lead = byte(at);
    if (lead < 0x80) return 1;
    std::size_t length = 0;
    if (lead >= 0xC2 && lead <= 0xDF)
        length = 2;  // 0xC0 and 0xC1 start only overlong forms
    else if (lead >= 0xE0 && lead <= 0xEF)
        length = 3;
    else if (lead >= 0xF0 && lead <= 0xF4)
        length = 4;
    else
        return 0;
    std::uint8_t first_min = 0x80, first_max = 0xBF;  // the range of the byte after the lead
    if (lead == 0xE0) first_min = 0xA0;               // overlong
    if (lead == 0xED) first_max = 0x9F;               // surrogates
    if (lead == 0xF0) first_min = 0x90;               // overlong
    if (lead == 0xF4) first_max = 0x8F;               // beyond U+10FFFF
    if (bytes.size() - at < length) return 0;
    for (std::size_t i = 1; i < length; ++i) {
        const std::uint8_t next = byte(at + i);
        const std::uint8_t min = i == 1 ? first_min : 0x80, max = i == 1 ? first_max : 0xBF;
        if (next < min || next > max) return 0;
    }
    return length;
}

bool control(unsigned char c) { return c < 0x20 || c == 0x7F; }

}  // namespace

std::string printable_text(std::string_view bytes) {
    std::string out;
    out.reserve(bytes.size());
    for (std::size_t at = 0; at < bytes.size();) {
        const std::size_t length = sequence_length(bytes, at);
        if (length == 0 || (length == 1 && control(static_cast<unsigned char>(bytes[at])))) {
            char escaped[5];
            std::snprintf(escaped, sizeof escaped, "\\x%02X", static_cast<unsigned char>(bytes[at]));
            out += escaped;
            ++at;
        } else {
            out.append(bytes.substr(at, length));
            at += length;
        }
    }
    return out;
}

}  // namespace shadowlab
