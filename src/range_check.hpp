// The range of numbers jostle works in (math.hpp), as the words its errors use: one rule,
// worded once, for the definitions (checkBodyDef, checkTileMapDef, checkWorldDef) and for
// the arguments of every API function (world_access.hpp).
#pragma once

#include "jostle/math.hpp"

#include <cmath>

namespace jostle {

/// What is wrong with a number given to jostle ("must be ..."), or nullptr if nothing is.
/// Finite is asked first, so that the magnitude rule never sees a NaN.
inline const char* rangeProblem(float value) {
    if (!std::isfinite(value))
        return "must be a finite number";
    if (!inRange(value))
        return "must be of magnitude <= 1e9";
    return nullptr;
}

/// The same for both numbers of a vector ("must be finite numbers", ...).
inline const char* rangeProblem(Vec2 value) {
    if (!isFinite(value))
        return "must be finite numbers";
    if (!inRange(value))
        return "must be of magnitude <= 1e9";
    return nullptr;
}

} // namespace jostle
