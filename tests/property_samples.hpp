// For tests that walk the property tables of src/body_properties.hpp: a valid value of
// each property that is not its default, what else a body needs to take it, and reading
// and writing a field by its table entry.
#pragma once

#include "body_properties.hpp"

#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

namespace jostle::test_support {

/// A value of `property` that a BodyDef or TileMapDef accepts and that is not its default.
inline properties::Value sampleOf(const properties::Property& property) {
    using properties::Rule;
    static int anchor; // something for userData to point to
    auto sample = [&](auto byDefault) -> properties::Value {
        using T = decltype(byDefault);
        if constexpr (std::is_same_v<T, float>) {
            switch (property.rule) {
            case Rule::Unit:
                return 0.25f;
            case Rule::Size:
                return 2.5f;
            case Rule::MassOrZero:
                return 3.0f;
            case Rule::NonNegative:
                return 0.75f;
            default:
                return 7.5f;
            }
        } else if constexpr (std::is_same_v<T, Vec2>) {
            return property.rule == Rule::Corner ? Vec2{1.0f, -1.0f} : Vec2{0.0f, -1.0f};
        } else if constexpr (std::is_same_v<T, bool>) {
            return !byDefault;
        } else if constexpr (std::is_same_v<T, std::uint32_t>) {
            return byDefault ^ 6u;
        } else if constexpr (std::is_same_v<T, BodyType>) {
            return BodyType::Kinematic;
        } else {
            return static_cast<void*>(&anchor);
        }
    };
    return std::visit(sample, property.byDefault);
}

/// A property and a value of it.
using Setting = std::pair<const properties::Property*, properties::Value>;

/// What a body must also hold, besides the defaults and a size of 1 × 1 half extents, for
/// checkBodyDef to accept the sample of `property`: a ramp (slope) and a conveyor
/// (surfaceVelocity) are static or kinematic, and a segment is a ramp's face, so it needs a
/// slope too. Each value is a sample itself
/// (kinematic is the type's), so that a test writes them as it writes samples. The radius
/// sample (0.75) fits in half extents of 1 with nothing else.
inline std::vector<Setting> sampleNeeds(const properties::Property& property) {
    using namespace properties;
    if (&property == &kSlope || &property == &kSurfaceVelocity)
        return {{&kType, sampleOf(kType)}};
    if (&property == &kSegment)
        return {{&kType, sampleOf(kType)}, {&kSlope, sampleOf(kSlope)}};
    return {};
}

/// The value of `field` in `def`.
template <class Def, class F> properties::Value valueOf(const Def& def, const F& field) {
    return std::visit([&](auto member) -> properties::Value { return def.*member; }, field.member);
}

/// Sets `field` of `def` to `value` (of the field's type).
template <class Def, class F>
void setValue(Def& def, const F& field, const properties::Value& value) {
    std::visit(
        [&](auto member) {
            using T = std::remove_cvref_t<decltype(def.*member)>;
            def.*member = std::get<T>(value);
        },
        field.member);
}

} // namespace jostle::test_support
