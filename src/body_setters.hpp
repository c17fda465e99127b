// The steps World's body getters and setters share (world_bodies.cpp,
// world_characters.cpp): an argument checked under its property's rule, and a property
// read or written where its row of body_properties.hpp says the world keeps it.
#pragma once

#include "body_properties.hpp"
#include "physical/sleep.hpp"
#include "world_access.hpp"

#include <string>
#include <type_traits>

namespace jostle {

/// A setter's argument under a rule: "setMass: mass must be > 0".
template <class T>
inline void require(const char* function, const char* what, properties::Rule rule, T value) {
    if (const char* problem = properties::problemOf(rule, value))
        fail(function, std::string(what) + " " + problem);
}

/// A setter's argument under its property's rule: "setBounce: bounce must be in [0, 1]".
template <class T>
inline void require(const char* function, const char* what, const properties::Property& property,
                    T value) {
    if (const char* problem = properties::problemOf(property, value))
        fail(function, std::string(what) + " " + problem);
}

/// The places where the world keeps the properties of the body in `slot`.
inline properties::Places placesOf(WorldState& w, std::uint32_t slot) {
    return {w.slots[slot], w.asGiven[slot], w.shapes[slot]};
}
inline properties::ConstPlaces placesOf(const WorldState& w, std::uint32_t slot) {
    return {w.slots[slot], w.asGiven[slot], w.shapes[slot]};
}

/// Calls f(value) with the value of `property` where the world keeps it for `places`.
template <class P, class F> void visitKept(P places, const properties::Property& property, F&& f) {
    properties::find(properties::kBodyFields, property)->visitStore([&](auto, auto store) {
        f(properties::at(places, store));
    });
}

/// A getter of a property as the body keeps it.
template <class T>
T getKept(const WorldState& w, BodyId id, const char* function,
          const properties::Property& property) {
    lookUp(w, id, function);
    T value{};
    visitKept(placesOf(w, id.index), property, [&](const auto& kept) {
        if constexpr (std::is_same_v<std::remove_cvref_t<decltype(kept)>, T>)
            value = kept;
    });
    return value;
}

/// Whether a setter wakes the body (docs/sleeping.md): all do but setBullet and
/// setUserData, which change nothing a step has done.
enum class Disturbs : bool { No, Yes };

/// A setter of a property whose rule is its Property's alone: the argument checked, kept
/// where the body keeps it, what the steps read of it derived again (deriveFrom), the
/// world's counts of bodies kept (WorldState::count), and the body disturbed.
template <class T>
void setKept(WorldState& w, BodyId id, const char* function, const char* what,
             const properties::Property& property, T value, Disturbs disturbs = Disturbs::Yes) {
    lookUpToChange(w, id, function);
    require(function, what, property, value);
    w.count(id.index, false);
    const properties::Places places = placesOf(w, id.index);
    visitKept(places, property, [&](auto& kept) {
        if constexpr (std::is_same_v<std::remove_cvref_t<decltype(kept)>, T>)
            kept = value;
    });
    deriveFrom(places.kept, places.body);
    w.count(id.index, true);
    if (disturbs == Disturbs::Yes)
        disturb(w, id.index);
}

} // namespace jostle
