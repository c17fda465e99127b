// The characters of a tile map's rows: '#', '.' and the ramps (jostle/tilemap.hpp), and
// how a message shows a character.
#pragma once

#include "jostle/math.hpp"

#include <string>

namespace jostle {

/// What a ramp character stands for. Rows read top first in a y-down world: "down" below
/// is the next row. A 2:1 ramp takes two tiles, its low half and its high half.
struct RampTile {
    char tile;
    Vec2 slope;   ///< BodyDef::slope of its triangle
    int height;   ///< 0: a 45° tile; 1: the low half of a 2:1 ramp; 2: its high half
    char partner; ///< the 2:1 half that merges with it on its right, or 0
};

constexpr RampTile kRampTiles[] = {
    {'/', {-1, -1}, 0, 0},   {'\\', {1, -1}, 0, 0}, {'7', {-1, 1}, 0, 0},   {'F', {1, 1}, 0, 0},
    {'r', {-1, -1}, 1, 'R'}, {'R', {-1, -1}, 2, 0}, {'L', {1, -1}, 2, 'l'}, {'l', {1, -1}, 1, 0},
    {'c', {-1, 1}, 1, 'C'},  {'C', {-1, 1}, 2, 0},  {'D', {1, 1}, 2, 'd'},  {'d', {1, 1}, 1, 0},
};

inline const RampTile* rampTile(char tile) {
    for (const RampTile& r : kRampTiles)
        if (r.tile == tile)
            return &r;
    return nullptr;
}

inline bool isTileChar(char tile) {
    return tile == '#' || tile == '.' || rampTile(tile) != nullptr;
}

/// A character as a message shows it: 'x' if printable ASCII, else its byte in hex (a
/// tab, or the first byte of a UTF-8 sequence).
inline std::string describeChar(char c) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte >= 0x20 && byte < 0x7F)
        return std::string("'") + c + "'";
    const char* digits = "0123456789ABCDEF";
    return std::string("byte 0x") + digits[byte >> 4] + digits[byte & 0xF];
}

} // namespace jostle
