// JSON as scene files read it: parsed with every value's place known ("bodies[3].hw"),
// duplicate fields and deep nesting refused, and values read by type, each problem a
// SceneError that names the place. scene.cpp reads a scene from it.
#pragma once

#include "jostle/math.hpp"

#include <nlohmann/json.hpp>

#include <cstdint>
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

/// ", got <type>": the end of a message about a value of the wrong type.
std::string got(const Json& value);

/// The document, or a SceneError naming the place of the problem.
Json parse(std::string_view text);

// Values of each type; each fails with the place when the value is not of it.
float readFloat(const Json& value, const std::string& place);
Vec2 readVec2(const Json& value, const std::string& place);
/// Bit fields (category, mask): a whole number from 0 to 2^32 - 1.
std::uint32_t readBits(const Json& value, const std::string& place);
bool readBool(const Json& value, const std::string& place);
const std::string& readString(const Json& value, const std::string& place);
const Json::object_t& readObject(const Json& value, const std::string& place);
const Json::array_t& readArray(const Json& value, const std::string& place);
/// An int option: a whole number. Those beyond an int are kept as INT_MIN or INT_MAX,
/// which every int option's range (checked by checkWorldDef) refuses.
int readInt(const Json& value, const std::string& place);

} // namespace jostle::json
