// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/io/json_duplicate_keys.h"

#include <set>
#include <vector>

namespace xyt {

namespace {

/// A single pass over the text with an explicit stack (no recursion, any depth).
class Scanner {
public:
    explicit Scanner(std::string_view text) : s_(text) {}

    std::optional<std::string> run() {
        while (i_ < s_.size()) {
            const char c = s_[i_];
            if (c == '{') {
                ++i_;
                frames_.push_back({true, {}, {}, 0, true});
            } else if (c == '[') {
                ++i_;
                frames_.push_back({false, {}, {}, 0, true});
            } else if (c == '}' || c == ']') {
                ++i_;
                if (!frames_.empty())
                    frames_.pop_back();
            } else if (c == '"') {
                std::string text = string();
                if (!frames_.empty() && frames_.back().isObject && frames_.back().expectKey) {
                    Frame& f = frames_.back();
                    if (!f.keys.insert(text).second)
                        return pathTo(text);
                    f.currentKey = std::move(text);
                    f.expectKey = false;
                }
            } else if (c == ',') {
                ++i_;
                if (!frames_.empty()) {
                    if (frames_.back().isObject)
                        frames_.back().expectKey = true;
                    else
                        ++frames_.back().index;
                }
            } else if (c == ':' || c == ' ' || c == '\t' || c == '\n' || c == '\r') {
                ++i_;
            } else { // a number, true, false or null
                do
                    ++i_;
                while (i_ < s_.size() && !isDelimiter(s_[i_]));
            }
        }
        return std::nullopt;
    }

private:
    struct Frame {
        bool isObject;
        std::set<std::string> keys;
        std::string currentKey;
        long long index;
        bool expectKey;
    };

    static bool isDelimiter(char c) {
        return c == ',' || c == '}' || c == ']' || c == ':' || c == ' ' || c == '\t' || c == '\n' ||
               c == '\r' || c == '"' || c == '{' || c == '[';
    }

    static int hex(char c) {
        if (c >= '0' && c <= '9')
            return c - '0';
        if (c >= 'a' && c <= 'f')
            return c - 'a' + 10;
        if (c >= 'A' && c <= 'F')
            return c - 'A' + 10;
        return 0;
    }

    unsigned readHex4() {
        unsigned v = 0;
        for (int k = 0; k < 4 && i_ < s_.size(); ++k, ++i_)
            v = v * 16 + static_cast<unsigned>(hex(s_[i_]));
        return v;
    }

    static void appendUtf8(std::string& out, unsigned cp) {
        if (cp < 0x80) {
            out += static_cast<char>(cp);
        } else if (cp < 0x800) {
            out += static_cast<char>(0xC0 | (cp >> 6));
            out += static_cast<char>(0x80 | (cp & 0x3F));
        } else if (cp < 0x10000) {
            out += static_cast<char>(0xE0 | (cp >> 12));
            out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
            out += static_cast<char>(0x80 | (cp & 0x3F));
        } else {
            out += static_cast<char>(0xF0 | (cp >> 18));
            out += static_cast<char>(0x80 | ((cp >> 12) & 0x3F));
            out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
            out += static_cast<char>(0x80 | (cp & 0x3F));
        }
    }

    /// The decoded string starting at the opening quote; leaves i_ after the closing quote.
    std::string string() {
        std::string out;
        ++i_;
        while (i_ < s_.size() && s_[i_] != '"') {
            if (s_[i_] != '\\') {
                out += s_[i_++];
                continue;
            }
            if (++i_ >= s_.size())
                break;
            const char e = s_[i_++];
            switch (e) {
            case 'b':
                out += '\b';
                break;
            case 'f':
                out += '\f';
                break;
            case 'n':
                out += '\n';
                break;
            case 'r':
                out += '\r';
                break;
            case 't':
                out += '\t';
                break;
            case 'u': {
                unsigned cp = readHex4();
                if (cp >= 0xD800 && cp < 0xDC00 && i_ + 1 < s_.size() && s_[i_] == '\\' &&
                    s_[i_ + 1] == 'u') {
                    i_ += 2;
                    const unsigned low = readHex4();
                    cp = 0x10000 + ((cp - 0xD800) << 10) + (low - 0xDC00);
                }
                appendUtf8(out, cp);
                break;
            }
            default:
                out += e; // \" \\ \/
            }
        }
        ++i_; // the closing quote
        return out;
    }

    /// "a.b[2].key" for the key about to be added to the innermost object.
    std::string pathTo(const std::string& key) const {
        std::string path;
        for (std::size_t k = 0; k + 1 < frames_.size(); ++k) {
            const Frame& f = frames_[k];
            if (f.isObject)
                path += (path.empty() ? "" : ".") + f.currentKey;
            else
                path += "[" + std::to_string(f.index) + "]";
        }
        return path.empty() ? key : path + "." + key;
    }

    std::string_view s_;
    std::size_t i_ = 0;
    std::vector<Frame> frames_;
};

} // namespace

std::optional<std::string> findDuplicateJsonKey(std::string_view json) {
    return Scanner(json).run();
}

} // namespace xyt
