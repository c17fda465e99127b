// The steps World's body setters share (world_bodies.cpp, world_characters.cpp): an
// argument checked under its property's rule, and a kept setting set.
#pragma once

#include "body_properties.hpp"
#include "physical/sleep.hpp"
#include "world_access.hpp"

#include <string>

namespace jostle {

/// A setter's argument under a property's rule: "setBounce: bounce must be in [0, 1]".
inline void require(const char* function, const char* what, properties::Rule rule, float value) {
    if (const char* problem = properties::problemOf(rule, value))
        fail(function, std::string(what) + " " + problem);
}

/// A setter of a setting a body keeps as given: the argument checked by its property's
/// rule, stored, and the body disturbed (docs/sleeping.md).
template <class T>
inline void setKept(WorldState& w, BodyId id, const char* function, const char* what,
                    const properties::Property& property, T Body::*member, T value) {
    Body& b = lookUpToChange(w, id, function);
    require(function, what, property.rule, value);
    b.*member = value;
    disturb(w, id.index);
}

} // namespace jostle
