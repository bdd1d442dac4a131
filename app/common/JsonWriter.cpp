// SPDX-License-Identifier: GPL-3.0-or-later
#include "common/JsonWriter.h"

#include <cmath>
#include <cstdint>
#include <ostream>

#include "vv/core/NumberText.h"

namespace vv::app {

std::string jsonString(std::string_view text) {
    std::string out = "\"";
    const auto* s = reinterpret_cast<const unsigned char*>(text.data());
    const std::size_t n = text.size();
    for (std::size_t i = 0; i < n;) {
        const unsigned char c = s[i];
        if (c < 0x80) {
            switch (c) {
                case '"':
                    out += "\\\"";
                    break;
                case '\\':
                    out += "\\\\";
                    break;
                case '\b':
                    out += "\\b";
                    break;
                case '\f':
                    out += "\\f";
                    break;
                case '\n':
                    out += "\\n";
                    break;
                case '\r':
                    out += "\\r";
                    break;
                case '\t':
                    out += "\\t";
                    break;
                default:
                    if (c < 0x20 || c == 0x7F) {
                        constexpr std::string_view kHex = "0123456789abcdef";
                        out += "\\u00";
                        out += kHex[c / 16];
                        out += kHex[c % 16];
                    } else {
                        out += static_cast<char>(c);
                    }
            }
            ++i;
            continue;
        }
        // Multi-byte UTF-8: validate length, continuation bytes, overlongs,
        // surrogates and the U+10FFFF limit.
        std::size_t length = 0;
        std::uint32_t code = 0;
        if (c >= 0xC2 && c <= 0xDF) {
            length = 2;
            code = c & 0x1FU;
        } else if (c >= 0xE0 && c <= 0xEF) {
            length = 3;
            code = c & 0x0FU;
        } else if (c >= 0xF0 && c <= 0xF4) {
            length = 4;
            code = c & 0x07U;
        }
        bool valid = length > 0 && i + length <= n;
        for (std::size_t k = 1; valid && k < length; ++k) {
            valid = (s[i + k] & 0xC0U) == 0x80U;
            code = (code << 6U) | (s[i + k] & 0x3FU);
        }
        if (valid) {
            valid = !(length == 3 && code < 0x800) && !(length == 4 && code < 0x10000) &&
                    !(code >= 0xD800 && code <= 0xDFFF) && code <= 0x10FFFF;
        }
        if (valid) {
            out.append(text.substr(i, length));
            i += length;
        } else {
            out += "\\ufffd";
            ++i;
        }
    }
    out += '"';
    return out;
}

JsonWriter::JsonWriter(std::ostream& out, Layout layout) : out_(out), layout_(layout) {}

void JsonWriter::key(std::string_view name) {
    separate();
    out_ << jsonString(name) << ": ";
    afterKey_ = true;
}

void JsonWriter::string(std::string_view text) {
    raw(jsonString(text));
}

void JsonWriter::number(double v) {
    raw(std::isfinite(v) ? vv::shortestText(v) : "null");
}

void JsonWriter::number(float v) {
    raw(std::isfinite(v) ? vv::shortestText(v) : "null");
}

void JsonWriter::boolean(bool v) {
    raw(v ? "true" : "false");
}

void JsonWriter::null() {
    raw("null");
}

void JsonWriter::finish() {
    out_ << '\n';
}

void JsonWriter::raw(const std::string& text) {
    separate();
    out_ << text;
}

void JsonWriter::open(char bracket) {
    separate();
    out_ << bracket;
    first_.push_back(true);
}

void JsonWriter::close(char bracket) {
    const bool empty = first_.back();
    first_.pop_back();
    if (!empty && layout_ == Layout::Indented) {
        newline();
    }
    out_ << bracket;
}

void JsonWriter::separate() {
    if (afterKey_) {
        afterKey_ = false;
        return;
    }
    if (first_.empty()) {
        return;
    }
    if (!first_.back()) {
        out_ << (layout_ == Layout::Indented ? "," : ", ");
    }
    first_.back() = false;
    if (layout_ == Layout::Indented) {
        newline();
    }
}

void JsonWriter::newline() {
    out_ << '\n' << std::string(first_.size() * 2, ' ');
}

}  // namespace vv::app
