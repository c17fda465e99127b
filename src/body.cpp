// Names of body types and the rules a BodyDef must follow (the rules of each property are
// body_properties.hpp's).
#include "jostle/body.hpp"

#include "body_properties.hpp"

#include <algorithm>
#include <cmath>

namespace jostle {

namespace {

/// The rules between the shape's fields, and between the shape and the body's type.
std::optional<FieldError> shapeProblem(const BodyDef& def) {
    if (def.radius > std::min(def.hw, def.hh))
        return FieldError{"radius", "must be <= hw and hh"};
    const bool sloped = def.slope != Vec2{};
    if (def.segment && !sloped)
        return FieldError{"segment", "needs a slope: a segment is a ramp's sloped face"};
    if (sloped && def.type == BodyType::Dynamic)
        return FieldError{"slope", "a ramp or segment must be static or kinematic"};
    if (sloped && def.radius > 0.0f)
        return FieldError{"radius", "must be 0 for a ramp or segment"};
    if ((sloped || def.radius > 0.0f) && def.oneWay != Vec2{})
        return FieldError{"oneWay", "must be {0, 0} for a rounded body, ramp or segment"};
    if (def.surfaceVelocity != Vec2{} && def.type == BodyType::Dynamic)
        return FieldError{"surfaceVelocity", "a conveyor must be static or kinematic"};
    return std::nullopt;
}

} // namespace

const char* toString(BodyType type) {
    switch (type) {
    case BodyType::Static:
        return "static";
    case BodyType::Kinematic:
        return "kinematic";
    case BodyType::Dynamic:
        return "dynamic";
    }
    return "unknown";
}

std::optional<BodyType> bodyTypeFromString(const std::string& name) {
    for (BodyType type : {BodyType::Static, BodyType::Kinematic, BodyType::Dynamic})
        if (name == toString(type))
            return type;
    return std::nullopt;
}

bool isValidOneWay(Vec2 normal) {
    const float ax = std::abs(normal.x), ay = std::abs(normal.y);
    return (ax == 0.0f && ay == 0.0f) || (ax == 1.0f && ay == 0.0f) || (ax == 0.0f && ay == 1.0f);
}

bool isValidSlope(Vec2 corner) {
    const float ax = std::abs(corner.x), ay = std::abs(corner.y);
    return (ax == 0.0f && ay == 0.0f) || (ax == 1.0f && ay == 1.0f);
}

std::optional<FieldError> checkBodyDef(const BodyDef& def) {
    using namespace properties;
    if (!allPass<kBodyFields>(def)) {
        if (auto problem = formProblem(def, kBodyFields))
            return problem;
        if (auto problem = ruleProblem(def, kBodyFields))
            return problem;
    }
    if (def.type == BodyType::Static && (def.vx != 0.0f || def.vy != 0.0f))
        return FieldError{def.vx != 0.0f ? "vx" : "vy",
                          "a static body cannot move (make it kinematic)"};
    if (auto problem = shapeProblem(def))
        return problem;
    // Within the range, a density mass is at most 1e9 × 4 × 1e9 × 1e9 = 4e27 and at least
    // 4e-27: finite, and so is its inverse.
    return std::nullopt;
}

static_assert(properties::defaultsAgree(BodyDef{}, properties::kBodyFields),
              "body_properties.hpp's defaults are body.hpp's");

} // namespace jostle
