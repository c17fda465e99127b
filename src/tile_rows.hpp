// The rules of a tile map's rows (jostle/tilemap.hpp), worded once for checkTileMapDef and
// createTileMap (and so C, scene files and JavaScript) and for the Lua module, each place
// counted as its language counts (notation.hpp): the second row is rows[1] in C++ and
// rows[2] in Lua.
#pragma once

#include "jostle/body.hpp"
#include "notation.hpp"
#include "tile_chars.hpp"

#include <climits>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace jostle {

/// Why a world of the classic model refuses a ramp tile: its bodies are sharp boxes only.
inline constexpr const char* kNoRampsInClassic = "the classic model has sharp boxes only: no ramps";

/// "rows[1]": row `row` (counted from 0) as `notation` counts it.
inline std::string rowPlace(std::size_t row, Notation notation) {
    return "rows[" + std::to_string(row + firstIndex(notation)) + "]";
}

/// "rows[1][4]": the character of tile (column, row) as `notation` counts it.
inline std::string tilePlace(std::size_t column, std::size_t row, Notation notation) {
    return rowPlace(row, notation) + "[" + std::to_string(column + firstIndex(notation)) + "]";
}

/// What a message about a tile adds where the counting of its place is not that of the
/// tile's coordinates (from 0 in every language): " (tile column 4, row 1)"; else "".
inline std::string tileCoordinates(std::size_t column, std::size_t row, Notation notation) {
    if (firstIndex(notation) == 0)
        return "";
    return " (tile column " + std::to_string(column) + ", row " + std::to_string(row) + ")";
}

/// The first problem with `rows`: none at all, too many, a first row empty or too long,
/// a character that is no tile's, a row not as long as the first (row by row, each row's
/// characters before its length).
inline std::optional<FieldError> rowsProblem(const std::vector<std::string>& rows,
                                             Notation notation) {
    constexpr std::size_t kMost = static_cast<std::size_t>(INT_MAX);
    if (rows.empty())
        return FieldError{"rows", "must have at least one row"};
    if (rows.size() > kMost)
        return FieldError{"rows", "too many rows"};
    const std::size_t columns = rows[0].size();
    if (columns == 0)
        return FieldError{rowPlace(0, notation), "must have at least one column"};
    if (columns > kMost)
        return FieldError{rowPlace(0, notation), "too many columns"};
    for (std::size_t row = 0; row < rows.size(); ++row) {
        const std::string& text = rows[row];
        for (std::size_t column = 0; column < text.size(); ++column)
            if (!isTileChar(text[column]))
                return FieldError{tilePlace(column, row, notation),
                                  "expected '#', '.' or a ramp, got " + describeChar(text[column]) +
                                      tileCoordinates(column, row, notation)};
        if (text.size() != columns)
            return FieldError{rowPlace(row, notation), "has " + std::to_string(text.size()) +
                                                           " columns, " + rowPlace(0, notation) +
                                                           " has " + std::to_string(columns)};
    }
    return std::nullopt;
}

/// Why a one-way map refuses a ramp tile: BodyDef::oneWay is for boxes, and a ramp blocks
/// from every side.
inline constexpr const char* kNoRampsOneWay =
    "a one-way map has boxes only: no ramps (a ramp blocks from every side)";

/// Why a map refuses 2:1 ramps: their halves, half a tile high, would be smaller than a body
/// may be where the map lies (said of its `tile`).
inline constexpr const char* kHalfTilesTooSmall =
    "is too small for the map's position: the halves of its 2:1 ramps would be narrower "
    "than 2e-9 (math.hpp)";

/// The first ramp tile of `rows` as a problem saying `why`; else nothing.
inline std::optional<FieldError> firstRampProblem(const std::vector<std::string>& rows,
                                                  Notation notation, const char* why) {
    for (std::size_t row = 0; row < rows.size(); ++row)
        for (std::size_t column = 0; column < rows[row].size(); ++column)
            if (rampTile(rows[row][column]))
                return FieldError{tilePlace(column, row, notation),
                                  why + tileCoordinates(column, row, notation)};
    return std::nullopt;
}

/// The first ramp tile of `rows`, which a world of the classic model refuses; else nothing.
inline std::optional<FieldError> rampProblem(const std::vector<std::string>& rows,
                                             Notation notation) {
    return firstRampProblem(rows, notation, kNoRampsInClassic);
}

/// The first ramp tile of the rows of a one-way map (`oneWay` not {0, 0}); else nothing.
inline std::optional<FieldError> oneWayRampProblem(const std::vector<std::string>& rows,
                                                   Vec2 oneWay, Notation notation) {
    if (oneWay == Vec2{})
        return std::nullopt;
    return firstRampProblem(rows, notation, kNoRampsOneWay);
}

/// Whether `rows` hold a half of a 2:1 ramp, a body half a tile high.
inline bool hasHalfTiles(const std::vector<std::string>& rows) {
    for (const std::string& row : rows)
        for (char tile : row)
            if (const RampTile* ramp = rampTile(tile); ramp && ramp->height != 0)
                return true;
    return false;
}

} // namespace jostle
