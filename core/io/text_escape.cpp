// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/io/text_escape.h"

#include <cstdio>

namespace xyt {

namespace {

/// One decoded character: its code point, or -1 for a malformed byte (then length 1).
struct Decoded {
    long codePoint;
    std::size_t length;
};

Decoded decode(std::string_view s, std::size_t i) {
    const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(s[k]); };
    const unsigned char b = byte(i);
    if (b < 0x80)
        return {b, 1};
    std::size_t n = 0;
    long cp = 0;
    if ((b & 0xE0) == 0xC0) {
        n = 2;
        cp = b & 0x1F;
    } else if ((b & 0xF0) == 0xE0) {
        n = 3;
        cp = b & 0x0F;
    } else if ((b & 0xF8) == 0xF0) {
        n = 4;
        cp = b & 0x07;
    } else {
        return {-1, 1};
    }
    if (i + n > s.size())
        return {-1, 1};
    for (std::size_t k = 1; k < n; ++k) {
        if ((byte(i + k) & 0xC0) != 0x80)
            return {-1, 1};
        cp = (cp << 6) | (byte(i + k) & 0x3F);
    }
    static constexpr long kMinimum[] = {0, 0, 0x80, 0x800, 0x10000};
    if (cp < kMinimum[n] || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF))
        return {-1, 1}; // overlong, beyond Unicode, or a surrogate
    return {cp, n};
}

bool printable(long cp) {
    if (cp < 0x20 || cp == 0x7F || (cp >= 0x80 && cp <= 0x9F))
        return false; // C0, DEL, C1 (NEL U+0085 among them)
    if (cp == 0x2028 || cp == 0x2029 || cp == 0xFEFF)
        return false; // line and paragraph separators, byte-order mark
    if (cp == 0x200E || cp == 0x200F || (cp >= 0x202A && cp <= 0x202E) ||
        (cp >= 0x2066 && cp <= 0x2069) || cp == 0x061C)
        return false; // bidirectional marks, overrides and isolates
    return cp >= 0;
}

} // namespace

std::string commentText(std::string_view text, CommentSyntax syntax, std::size_t maxChars) {
    std::string out;
    std::size_t chars = 0;
    for (std::size_t i = 0; i < text.size();) {
        if (chars == maxChars) {
            out += "...";
            break;
        }
        const Decoded d = decode(text, i);
        if (!printable(d.codePoint)) {
            out += '_';
        } else {
            const char c = text[i];
            if (syntax == CommentSyntax::C && !out.empty() && d.length == 1) {
                const char last = out.back();
                if ((last == '*' && c == '/') || (last == '/' && c == '*') ||
                    (last == '?' && c == '?'))
                    out += ' ';
            }
            out.append(text.substr(i, d.length));
        }
        i += d.length;
        ++chars;
    }
    return out;
}

std::string terminalText(std::string_view text) {
    std::string out;
    char buf[16];
    for (std::size_t i = 0; i < text.size();) {
        const Decoded d = decode(text, i);
        if (d.codePoint < 0) {
            std::snprintf(buf, sizeof buf, "\\x%02x", static_cast<unsigned char>(text[i]));
            out += buf;
        } else if (!printable(d.codePoint)) {
            std::snprintf(buf, sizeof buf, d.codePoint < 0x100 ? "\\x%02lx" : "\\u%04lx",
                          d.codePoint);
            out += buf;
        } else if (text[i] == '\\') {
            out += "\\\\";
        } else {
            out.append(text.substr(i, d.length));
        }
        i += d.length;
    }
    return out;
}

} // namespace xyt
