// JSON as scene files read it: the text handed to nlohmann-json's SAX parser, what the
// parser refuses turned into a SceneError that says where, and values read by type, each
// problem a SceneError that names the place ("bodies[3].hw"). scene.cpp reads a scene from
// the parser's events.
#pragma once

#include "jostle/math.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <iterator>
#include <memory>
#include <string>
#include <string_view>

namespace jostle::json {

// ordered_json keeps fields in file order, so that "the first problem" is the first
// one a reader meets in the file, not the first in alphabetical order.
using Json = nlohmann::ordered_json;

/// Throws SceneError("place: rule").
[[noreturn]] void fail(const std::string& place, const std::string& rule);

/// The place of a field of the value at `place`, and of an element.
std::string field(const std::string& place, const std::string& name);
std::string element(const std::string& place, std::size_t index);

/// A name as JSON spells it, quotes and escapes included, cut to a readable length.
std::string quoteName(const std::string& name);

/// True if `text` (UTF-8) holds a control character: U+0000 to U+001F, U+007F to U+009F.
bool hasControlCharacter(std::string_view text);

/// ", got <type>": the end of a message about a value of the wrong type.
std::string got(const Json& value);

// --- The text ------------------------------------------------------------------------

/// The bytes of a scene, in memory or read from a file as the parser asks for them, handed
/// to the parser one at a time. It knows where the last byte handed out was: the parser
/// takes a NUL byte for the end of the text, and only the input can tell that it was not.
class Input {
public:
    class Iterator;

    /// Text in memory, which must outlive the Input.
    explicit Input(std::string_view text)
        : buffer_(text), head_(text.substr(0, std::min(text.size(), kHeadBytes))) {}
    /// A file, read in chunks from where it stands (not closed). Reading throws
    /// SceneError("cannot read: ..."), and so does a file longer than kMaxSceneBytes.
    explicit Input(std::FILE* file);

    Input(const Input&) = delete;
    Input& operator=(const Input&) = delete;

    Iterator begin();
    Iterator end();

    /// True if the text starts with two byte-order marks (EF BB BF EF BB BF).
    bool startsWithTwoByteOrderMarks() const;
    /// True if the last byte handed out was a NUL.
    bool endedAtNul() const { return handedOut_ > 0 && last_ == '\0'; }
    /// The line and column (from 1, in bytes) of the last byte handed out.
    std::size_t line() const { return line_; }
    std::size_t column() const { return handedOut_ - lineStart_; }

private:
    /// True when every byte has been handed out (after reading more of the file).
    bool atEnd() { return next_ == buffer_.size() && !refill(); }
    char peek() const { return buffer_[next_]; }
    void advance() {
        last_ = buffer_[next_++];
        ++handedOut_;
        if (last_ == '\n') {
            ++line_;
            lineStart_ = handedOut_;
        }
    }
    /// Reads the next chunk of the file; false at its end.
    bool refill();

    std::string_view buffer_; ///< the bytes at hand: the text, or the chunk read last
    std::size_t next_ = 0;    ///< the next byte of buffer_ to hand out
    std::FILE* file_ = nullptr;
    std::unique_ptr<char[]> chunk_;
    bool fileEnded_ = false;
    std::size_t read_ = 0; ///< bytes read from the file so far

    static constexpr std::size_t kHeadBytes = 6;
    std::string head_; ///< the first kHeadBytes bytes of the text (fewer if it is shorter)

    std::size_t handedOut_ = 0;
    char last_ = '\0';
    std::size_t line_ = 1;
    std::size_t lineStart_ = 0; ///< handedOut_ at the start of the line
};

/// The rule a file longer than kMaxSceneBytes breaks: "too large: ...".
std::string tooLarge();

/// An input iterator over the bytes of an Input, for nlohmann-json's iterator input.
class Input::Iterator {
public:
    using iterator_category = std::input_iterator_tag;
    using value_type = char;
    using difference_type = std::ptrdiff_t;
    using pointer = const char*;
    using reference = char;

    Iterator() = default; ///< the end
    explicit Iterator(Input* input) : input_(input) {}

    char operator*() const { return input_->peek(); }
    Iterator& operator++() {
        input_->advance();
        return *this;
    }
    Iterator operator++(int) {
        Iterator before = *this;
        ++*this;
        return before;
    }
    /// Iterators are equal when both are at the end or neither is.
    friend bool operator==(const Iterator& a, const Iterator& b) { return a.done() == b.done(); }

private:
    bool done() const { return !input_ || input_->atEnd(); }

    Input* input_ = nullptr;
};

inline Input::Iterator Input::begin() {
    return Iterator(this);
}
inline Input::Iterator Input::end() {
    return Iterator();
}

/// Parses `input` as one JSON value (RFC 8259, nothing after it but whitespace), telling
/// `handler` what it reads. The handler's parse_error must call failSyntax.
void parse(Input& input, nlohmann::json_sax<Json>& handler);

/// Throws the SceneError for text the parser refused: "invalid JSON at line 2, column 3:
/// ...", with what was read last in printable form; a NUL byte and a second byte-order
/// mark named as such; for a number beyond a double, "<place>: must be a finite number".
[[noreturn]] void failSyntax(const Input& input, const nlohmann::json::exception& error,
                             const std::string& place);

// --- Values --------------------------------------------------------------------------

// Values of each type; each fails with the place when the value is not of it.
float readFloat(const Json& value, const std::string& place);
Vec2 readVec2(const Json& value, const std::string& place);
/// Fails with the message for an array of `size` elements where two numbers belong.
[[noreturn]] void failVec2Size(const std::string& place, std::size_t size);
/// A whole number: a number whose value is an integer, written with or without a fraction
/// or an exponent (4, 4.0, 4e0), from `lowest` to `highest`. "expected a whole number, got
/// 1.5", "must be in [0, 4294967295], got -1".
std::int64_t readWhole(const Json& value, const std::string& place, std::int64_t lowest,
                       std::int64_t highest);
/// Bit fields (category, mask): a whole number from 0 to 2^32 - 1.
std::uint32_t readBits(const Json& value, const std::string& place);
bool readBool(const Json& value, const std::string& place);
const std::string& readString(const Json& value, const std::string& place);
/// Fails with "expected <what>, got <type of value>".
[[noreturn]] void failType(const Json& value, const std::string& place, const char* what);
/// An int option: a whole number, as readWhole takes it. Those beyond an int are kept as
/// INT_MIN or INT_MAX, which every int option's range (checked by checkWorldDef) refuses.
int readInt(const Json& value, const std::string& place);
/// A number as messages show it: "-1", "2.5", "18446744073709551616", "1e+300".
std::string numberText(const Json& value);

} // namespace jostle::json
