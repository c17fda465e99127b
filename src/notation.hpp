// Each language's own notation in messages. A rule is worded once, in the C++ library's
// notation (body_properties.hpp, checkBodyDef, checkTileMapDef, World's setters); each
// binding shows the same words in its own:
//
// | notation           | a vector | a definition's field set to a value | counting |
// |--------------------|----------|-------------------------------------|----------|
// | C++ (and C)        | {0, -1}  | BodyDef::character = true           | from 0   |
// | Lua                | {0, -1}  | character = true                    | from 1   |
// | JSON (scene files) | [0, -1]  | "character": true                   | from 0   |
// | JavaScript         | [0, -1]  | character: true                     | from 0   |
//
// Counting is that of places in a definition: the rows of a tile map and the characters of
// a row ("rows[2][5]"). A tile's own coordinates (column, row) count from 0 in every
// language.
//
// Only a rule's words are rewritten, never what it quotes: a character ('{') or a name
// ("a{b}") is the caller's, as it was written.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace jostle {

enum class Notation : std::uint8_t { Cpp, Lua, Json, JavaScript };

/// The index of the first row, or of a row's first character, in `notation`.
constexpr std::size_t firstIndex(Notation notation) {
    return notation == Notation::Lua ? 1 : 0;
}

namespace notation_detail {

constexpr bool isWordChar(char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
}

/// The C++ names of the definitions whose fields a rule may name as "Def::field = value".
inline constexpr std::string_view kDefinitions[] = {"BodyDef::", "TileMapDef::", "WorldDef::"};

} // namespace notation_detail

/// Writes `rule`, worded in C++'s notation, in `notation`: put(std::string_view) for each
/// piece, in order. Allocates nothing, for the Lua module's fixed buffers.
template <class Put> void writeInNotation(std::string_view rule, Notation notation, Put&& put) {
    using namespace notation_detail;
    const bool json = notation == Notation::Json || notation == Notation::JavaScript;
    std::size_t i = 0;
    while (i < rule.size()) {
        const char c = rule[i];
        // Quoted, it is a caller's or a literal: a character, 'x', or a name, "x" (JSON
        // escapes within).
        std::size_t quote = 0;
        if (c == '\'' && i + 2 < rule.size() && rule[i + 2] == '\'')
            quote = 3;
        else if (c == '"') {
            std::size_t end = i + 1;
            while (end < rule.size() && rule[end] != '"')
                end += rule[end] == '\\' ? 2 : 1;
            quote = (end < rule.size() ? end + 1 : rule.size()) - i;
        }
        if (quote > 0) {
            put(rule.substr(i, quote));
            i += quote;
            continue;
        }
        if (json && (c == '{' || c == '}')) {
            put(c == '{' ? std::string_view("[") : std::string_view("]"));
            ++i;
            continue;
        }
        // "BodyDef::character = true", at the start of a word.
        std::string_view definition;
        if (notation != Notation::Cpp && (i == 0 || !isWordChar(rule[i - 1])))
            for (std::string_view d : kDefinitions)
                if (rule.substr(i).starts_with(d))
                    definition = d;
        std::size_t end = i + definition.size();
        while (!definition.empty() && end < rule.size() && isWordChar(rule[end]))
            ++end;
        if (definition.empty() || end == i + definition.size() ||
            !rule.substr(end).starts_with(" = ")) {
            put(rule.substr(i, 1));
            ++i;
            continue;
        }
        const std::string_view field =
            rule.substr(i + definition.size(), end - i - definition.size());
        const bool jsonName = notation == Notation::Json;
        put(jsonName ? std::string_view("\"") : std::string_view());
        put(field);
        // Lua: a field of the definition's table, as newBody takes it.
        put(notation == Notation::Lua ? std::string_view(" = ")
            : jsonName                ? std::string_view("\": ")
                                      : std::string_view(": "));
        i = end + 3;
    }
}

/// `rule`, worded in C++'s notation, in `notation`.
inline std::string inNotation(std::string_view rule, Notation notation) {
    std::string out;
    out.reserve(rule.size());
    writeInNotation(rule, notation, [&](std::string_view piece) { out += piece; });
    return out;
}

/// The same into `out`, cut to `size` bytes and ended by a NUL (size > 0).
inline void copyInNotation(std::string_view rule, Notation notation, char* out,
                           std::size_t size) noexcept {
    std::size_t length = 0;
    writeInNotation(rule, notation, [&](std::string_view piece) {
        for (char c : piece)
            if (length + 1 < size)
                out[length++] = c;
    });
    out[length] = '\0';
}

} // namespace jostle
