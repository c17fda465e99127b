// JSON as scene files read it (json.hpp).
#include "json.hpp"

#include "jostle/scene.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <system_error>

namespace jostle::json {

namespace {

// Error messages quote what they cite, at most this many bytes of it.
constexpr std::size_t kMaxQuoted = 200;

} // namespace

[[noreturn]] void fail(const std::string& place, const std::string& rule) {
    throw SceneError(place.empty() ? rule : place + ": " + rule);
}

std::string field(const std::string& place, const std::string& name) {
    return place.empty() ? name : place + "." + name;
}

std::string element(const std::string& place, std::size_t index) {
    return place + "[" + std::to_string(index) + "]";
}

namespace {

/// The length of the valid UTF-8 sequence at the start of `text`, or 0 if there is none.
std::size_t utf8Length(std::string_view text) {
    const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(text[i]); };
    const unsigned char lead = byte(0);
    const std::size_t length = lead < 0x80                    ? 1
                               : lead >= 0xC2 && lead <= 0xDF ? 2
                               : lead >= 0xE0 && lead <= 0xEF ? 3
                               : lead >= 0xF0 && lead <= 0xF4 ? 4
                                                              : 0;
    if (length == 0 || length > text.size())
        return 0;
    for (std::size_t i = 1; i < length; ++i)
        if ((byte(i) & 0xC0u) != 0x80u)
            return 0;
    return length;
}

/// The code point of the valid UTF-8 sequence of `length` bytes at the start of `text`.
char32_t codePoint(std::string_view text, std::size_t length) {
    const auto byte = [&](std::size_t i) {
        return static_cast<char32_t>(static_cast<unsigned char>(text[i]));
    };
    if (length == 1)
        return byte(0);
    char32_t c = byte(0) & (0x7Fu >> length);
    for (std::size_t i = 1; i < length; ++i)
        c = (c << 6) | (byte(i) & 0x3Fu);
    return c;
}

/// The control characters: C0 (U+0000 to U+001F), DEL and C1 (U+007F to U+009F).
bool isControl(char32_t c) {
    return c < 0x20 || (c >= 0x7F && c <= 0x9F);
}

/// Characters that show as nothing, or move what follows: controls, the default-ignorable
/// ones (soft hyphen, zero-width space and joiners, the byte-order mark, variation
/// selectors, tags), the line and paragraph separators and the bidirectional controls.
bool isInvisible(char32_t c) {
    const auto in = [c](char32_t first, char32_t last) { return c >= first && c <= last; };
    return isControl(c) || c == 0x00AD || c == 0x034F || c == 0x061C || in(0x115F, 0x1160) ||
           in(0x17B4, 0x17B5) || in(0x180B, 0x180F) || in(0x200B, 0x200F) || in(0x2028, 0x202E) ||
           in(0x2060, 0x206F) || c == 0x3164 || in(0xFE00, 0xFE0F) || c == 0xFEFF || c == 0xFFA0 ||
           in(0xFFF0, 0xFFFB) || in(0xE0000, 0xE0FFF);
}

/// Cuts `text` to at most kMaxQuoted bytes, never inside a UTF-8 sequence.
std::string clip(std::string text) {
    if (text.size() <= kMaxQuoted)
        return text;
    std::size_t end = kMaxQuoted;
    while (end > 0 && (static_cast<unsigned char>(text[end]) & 0xC0u) == 0x80u)
        --end;
    text.resize(end);
    return text + "...";
}

} // namespace

/// A name as JSON spells it, quotes and escapes included, so that odd names stay
/// readable in a one-line message: every invisible character escaped (JSON escapes the
/// controls below U+0020 itself, not DEL, C1, U+FEFF, ...).
std::string quoteName(const std::string& name) {
    const std::string json = Json(name).dump(-1, ' ', false, Json::error_handler_t::replace);
    std::string quoted;
    for (std::string_view rest = json; !rest.empty();) {
        const std::size_t valid = utf8Length(rest);
        const std::size_t length = std::max<std::size_t>(valid, 1);
        if (const char32_t c = codePoint(rest, length); valid > 0 && c >= 0x7F && isInvisible(c)) {
            // Beyond U+FFFF, JSON escapes a character as its UTF-16 surrogate pair.
            const auto escape = [&quoted](char32_t unit) {
                char escaped[16];
                std::snprintf(escaped, sizeof escaped, "\\u%04x", static_cast<unsigned>(unit));
                quoted += escaped;
            };
            if (c > 0xFFFF) {
                escape(0xD800 + ((c - 0x10000) >> 10));
                escape(0xDC00 + ((c - 0x10000) & 0x3FF));
            } else {
                escape(c);
            }
        } else {
            quoted.append(rest.substr(0, length));
        }
        rest.remove_prefix(length);
    }
    return clip(quoted);
}

bool hasControlCharacter(std::string_view text) {
    while (!text.empty()) {
        const std::size_t valid = utf8Length(text);
        const std::size_t length = std::max<std::size_t>(valid, 1);
        if (valid > 0 && isControl(codePoint(text, length)))
            return true;
        text.remove_prefix(length);
    }
    return false;
}

std::string got(const Json& value) {
    return std::string(", got ") + value.type_name();
}

namespace {

// --- Syntax --------------------------------------------------------------------------

/// `text` with every byte that is not part of valid UTF-8 spelt as <0xNN>, and every
/// invisible character as <U+FEFF>: the parser quotes what it last read, and a message
/// must stay visible, printable text even when the file is binary garbage.
std::string printable(std::string_view text) {
    std::string result;
    while (!text.empty()) {
        std::size_t length = utf8Length(text);
        char escaped[16];
        if (length == 0) {
            std::snprintf(escaped, sizeof escaped, "<0x%02X>",
                          static_cast<unsigned>(static_cast<unsigned char>(text[0])));
            result += escaped;
            length = 1;
        } else if (const char32_t c = codePoint(text, length); isInvisible(c)) {
            std::snprintf(escaped, sizeof escaped, "<U+%04X>", static_cast<unsigned>(c));
            result += escaped;
        } else {
            result.append(text.substr(0, length));
        }
        text.remove_prefix(length);
    }
    return result;
}

/// "[json.exception.parse_error.101] parse error at line 2, column 7: syntax error ..."
/// becomes "invalid JSON at line 2, column 7: syntax error ...".
std::string describe(const nlohmann::json::exception& error) {
    std::string message = error.what();
    const std::string marker = "parse error ";
    if (const std::size_t at = message.find(marker); at != std::string::npos)
        message = message.substr(at + marker.size());
    else if (const std::size_t bracket = message.find("] "); bracket != std::string::npos)
        message = ": " + message.substr(bracket + 2);
    // The parser quotes the last token it read, which may be a whole megabyte string.
    return "invalid JSON " + printable(clip(message));
}

} // namespace

namespace {

/// Bytes read from a file at a time.
constexpr std::size_t kChunkBytes = std::size_t{1} << 16;

} // namespace

Input::Input(std::FILE* file) : file_(file), chunk_(new char[kChunkBytes]) {}

bool Input::refill() {
    if (!file_ || fileEnded_)
        return false;
    errno = 0;
    const std::size_t count = std::fread(chunk_.get(), 1, kChunkBytes, file_);
    if (count == 0) {
        // Opening a directory succeeds; reading it is where EISDIR shows.
        if (std::ferror(file_))
            throw SceneError("cannot read: " +
                             std::error_code(errno, std::generic_category()).message());
        fileEnded_ = true;
        return false;
    }
    if (read_ == 0)
        head_.assign(chunk_.get(), std::min(count, kHeadBytes));
    read_ += count;
    if (read_ > kMaxSceneBytes)
        throw SceneError(tooLarge());
    buffer_ = std::string_view(chunk_.get(), count);
    next_ = 0;
    return true;
}

bool Input::startsWithTwoByteOrderMarks() const {
    return head_ == "\xEF\xBB\xBF\xEF\xBB\xBF";
}

std::string tooLarge() {
    return "too large: a scene file holds at most " + std::to_string(kMaxSceneBytes) +
           " bytes (1 GiB)";
}

namespace {

/// JSON text never holds a NUL byte (in a string it is written \u0000): one is an error
/// wherever it is, after the value too.
[[noreturn]] void failNul(const Input& input, bool afterTheValue) {
    throw SceneError("invalid JSON at line " + std::to_string(input.line()) + ", column " +
                     std::to_string(input.column()) + ": unexpected NUL byte (0x00)" +
                     (afterTheValue ? "; expected end of input" : ""));
}

} // namespace

void parse(Input& input, nlohmann::json_sax<Json>& handler) {
    // No comments: a scene file is plain JSON, readable by every other tool. Strict: nothing
    // but whitespace after the value.
    Json::sax_parse(input.begin(), input.end(), &handler, nlohmann::json::input_format_t::json,
                    /*strict=*/true, /*ignore_comments=*/false);
    // The parser stops at a NUL byte as at the end of the text.
    if (input.endedAtNul())
        failNul(input, true);
}

void failSyntax(const Input& input, const nlohmann::json::exception& error,
                const std::string& place) {
    // The parser stops at a NUL byte as at the end of the text, and says so.
    if (input.endedAtNul())
        failNul(input, false);
    // It skips one byte-order mark, and would quote the first (invisible) with the second.
    if (input.startsWithTwoByteOrderMarks())
        throw SceneError("invalid JSON at line 1, column 4: a second byte-order mark (EF BB BF)");
    // The parser refuses numbers beyond a double (1e400) itself, while reading the value at
    // `place`.
    if (error.id == 406)
        fail(place, "must be a finite number");
    throw SceneError(describe(error));
}

// --- Values --------------------------------------------------------------------------

float readFloat(const Json& value, const std::string& place) {
    // is_number() is false for booleans: true is not 1 in a scene file.
    if (!value.is_number())
        fail(place, "expected a number" + got(value));
    const double number = value.get<double>();
    // 2^128 - 2^103 is FLT_MAX plus half its ulp: doubles below it round to a finite
    // float, doubles from it up (1e39) to infinity. (The parser refuses 1e400 itself.)
    constexpr double kFloatLimit = 0x1.ffffffp127;
    if (!(std::fabs(number) < kFloatLimit))
        fail(place, "must be a finite number");
    return static_cast<float>(number);
}

Vec2 readVec2(const Json& value, const std::string& place) {
    if (!value.is_array())
        fail(place, "expected an array of 2 numbers" + got(value));
    if (value.size() != 2)
        failVec2Size(place, value.size());
    return {readFloat(value[0], element(place, 0)), readFloat(value[1], element(place, 1))};
}

void failVec2Size(const std::string& place, std::size_t size) {
    fail(place, "expected an array of 2 numbers, got " + std::to_string(size) +
                    (size == 1 ? " number" : " numbers"));
}

std::string numberText(const Json& value) {
    if (value.is_number_unsigned())
        return std::to_string(value.get<std::uint64_t>());
    if (value.is_number_integer())
        return std::to_string(value.get<std::int64_t>());
    // A whole double in digits while that stays short (18446744073709551616), else as JSON
    // writes it (1.5, 1e+300).
    const double number = value.get<double>();
    if (number == std::floor(number) && std::fabs(number) < 1e21) {
        char digits[32];
        std::snprintf(digits, sizeof digits, "%.0f", number);
        return digits;
    }
    return value.dump();
}

namespace {

/// The whole number `value` holds, checked for type and fraction; nullopt for a whole
/// number beyond an int64.
std::optional<std::int64_t> wholeNumber(const Json& value, const std::string& place) {
    if (!value.is_number())
        fail(place, "expected a whole number" + got(value));
    if (value.is_number_unsigned()) {
        const std::uint64_t number = value.get<std::uint64_t>();
        if (number > static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max()))
            return std::nullopt;
        return static_cast<std::int64_t>(number);
    }
    if (value.is_number_integer())
        return value.get<std::int64_t>();
    const double number = value.get<double>();
    if (number != std::floor(number))
        fail(place, "expected a whole number, got " + numberText(value));
    // 2^63: the first double beyond an int64.
    if (!(std::fabs(number) < 0x1p63))
        return std::nullopt;
    return static_cast<std::int64_t>(number);
}

} // namespace

std::int64_t readWhole(const Json& value, const std::string& place, std::int64_t lowest,
                       std::int64_t highest) {
    const std::optional<std::int64_t> number = wholeNumber(value, place);
    if (!number || *number < lowest || *number > highest)
        fail(place, "must be in [" + std::to_string(lowest) + ", " + std::to_string(highest) +
                        "], got " + numberText(value));
    return *number;
}

std::uint32_t readBits(const Json& value, const std::string& place) {
    return static_cast<std::uint32_t>(readWhole(value, place, 0, 0xFFFFFFFF));
}

bool readBool(const Json& value, const std::string& place) {
    if (!value.is_boolean())
        fail(place, "expected true or false" + got(value));
    return value.get<bool>();
}

const std::string& readString(const Json& value, const std::string& place) {
    if (!value.is_string())
        fail(place, "expected a string" + got(value));
    return value.get_ref<const std::string&>();
}

void failType(const Json& value, const std::string& place, const char* what) {
    fail(place, std::string("expected ") + what + got(value));
}

int readInt(const Json& value, const std::string& place) {
    const std::optional<std::int64_t> number = wholeNumber(value, place);
    const bool negative = number ? *number < 0 : value.get<double>() < 0;
    const std::int64_t lowest = std::numeric_limits<int>::min();
    const std::int64_t highest = std::numeric_limits<int>::max();
    return static_cast<int>(number ? std::clamp(*number, lowest, highest)
                                   : (negative ? lowest : highest));
}

} // namespace jostle::json
