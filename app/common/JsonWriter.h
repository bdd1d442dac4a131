// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <concepts>
#include <iosfwd>
#include <string>
#include <string_view>
#include <vector>

namespace vv::app {

/// `text` as a JSON string literal: quotes, backslashes and control
/// characters escaped; bytes that are not valid UTF-8 become U+FFFD so the
/// output stays valid UTF-8.
[[nodiscard]] std::string jsonString(std::string_view text);

/// The one JSON writer of both front ends (the command line's info --json,
/// render --timings, vss --stats; the measurement files the command line and
/// the GUI write): objects, arrays, strings, numbers, booleans, null. Numbers
/// are written in one machine format: the shortest text that reads back as
/// exactly the value (vv::shortestText, always the C locale); a float as a
/// float (0.1F is 0.1), not as the double it widens to. Non-finite numbers
/// have no JSON form and are written as null.
class JsonWriter {
  public:
    enum class Layout {
        Indented,  ///< one member per line, two spaces per level
        OneLine,   ///< {"a": 1, "b": [2, 3]} and a newline at the end
    };

    explicit JsonWriter(std::ostream& out, Layout layout = Layout::Indented);

    void beginObject() { open('{'); }
    void endObject() { close('}'); }
    void beginArray() { open('['); }
    void endArray() { close(']'); }

    void key(std::string_view name);
    void string(std::string_view text);
    void number(double v);
    void number(float v);
    template <std::integral T>
    void integer(T v) {
        raw(std::to_string(v));
    }
    void boolean(bool v);
    void null();
    /// Ends the document with a newline.
    void finish();

    /// A member of the open object: key(name), then the value as its type
    /// says (text, a number, an integer, a boolean).
    template <typename T>
    void member(std::string_view name, const T& value) {
        key(name);
        write(value);
    }

  private:
    void write(std::string_view text) { string(text); }
    void write(const char* text) { string(text); }
    void write(const std::string& text) { string(text); }
    void write(double v) { number(v); }
    void write(float v) { number(v); }
    void write(bool v) { boolean(v); }
    template <std::integral T>
    void write(T v) {
        integer(v);
    }
    void raw(const std::string& text);
    void open(char bracket);
    void close(char bracket);
    void separate();
    void newline();

    std::ostream& out_;
    Layout layout_;
    std::vector<bool> first_;  // per open container: nothing written yet
    bool afterKey_ = false;
};

}  // namespace vv::app
