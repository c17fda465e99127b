// Names of body types and the rules a BodyDef must follow.
#include "jostle/body.hpp"

#include "range_check.hpp"

#include <cmath>

namespace jostle {

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

std::optional<FieldError> checkBodyDef(const BodyDef& def) {
    if (def.type != BodyType::Static && def.type != BodyType::Kinematic &&
        def.type != BodyType::Dynamic)
        return FieldError{"type", "must be static, kinematic or dynamic"};

    // In the range first, so that the rules below never see a NaN (every comparison with
    // NaN is false, which would let it slip through).
    const std::pair<const char*, float> numbers[] = {
        {"x", def.x},
        {"y", def.y},
        {"hw", def.hw},
        {"hh", def.hh},
        {"vx", def.vx},
        {"vy", def.vy},
        {"bounce", def.bounce},
        {"friction", def.friction},
        {"mass", def.mass},
        {"density", def.density},
        {"gravityScale", def.gravityScale},
        {"damping", def.damping},
        {"oneWay", def.oneWay.x},
        {"oneWay", def.oneWay.y},
    };
    for (const auto& [field, value] : numbers)
        if (const char* problem = rangeProblem(value))
            return FieldError{field, problem};

    if (def.hw <= 0.0f)
        return FieldError{"hw", "must be > 0"};
    if (def.hh <= 0.0f)
        return FieldError{"hh", "must be > 0"};
    if (def.hw < kMinMagnitude)
        return FieldError{"hw", "must be >= 1e-9"};
    if (def.hh < kMinMagnitude)
        return FieldError{"hh", "must be >= 1e-9"};
    if (def.bounce < 0.0f || def.bounce > 1.0f)
        return FieldError{"bounce", "must be in [0, 1]"};
    if (def.friction < 0.0f || def.friction > 1.0f)
        return FieldError{"friction", "must be in [0, 1]"};
    if (def.mass < 0.0f)
        return FieldError{"mass", "must be >= 0 (0: from density)"};
    if (def.mass > 0.0f && def.mass < kMinMagnitude)
        return FieldError{"mass", "must be 0 (from density) or >= 1e-9"};
    if (def.density <= 0.0f)
        return FieldError{"density", "must be > 0"};
    if (def.density < kMinMagnitude)
        return FieldError{"density", "must be >= 1e-9"};
    if (def.damping < 0.0f)
        return FieldError{"damping", "must be >= 0"};
    if (!isValidOneWay(def.oneWay))
        return FieldError{"oneWay", "must be [0, 0] or one of [1, 0], [-1, 0], [0, 1], [0, -1]"};
    if (def.type == BodyType::Static && (def.vx != 0.0f || def.vy != 0.0f))
        return FieldError{def.vx != 0.0f ? "vx" : "vy",
                          "a static body cannot move (make it kinematic)"};
    // Within the range, a density mass is at most 1e9 × 4 × 1e9 × 1e9 = 4e27 and at least
    // 4e-27: finite, and so is its inverse.
    return std::nullopt;
}

} // namespace jostle
