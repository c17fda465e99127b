// World's characters: the character switch and its settings, walking, and the ground a
// body stands on (docs/characters.md); each setter checks its argument.
#include "body_setters.hpp"

#include <cstdint>
#include <optional>

namespace jostle {

// --- Characters ---------------------------------------------------------------------------

bool World::isCharacter(BodyId id) const {
    return getKept<bool>(*state_, id, "isCharacter", properties::kCharacter);
}

void World::setCharacter(BodyId id, bool character) {
    setKept(*state_, id, "setCharacter", "character", properties::kCharacter, character);
}

float World::wallFriction(BodyId id) const {
    return getKept<float>(*state_, id, "wallFriction", properties::kWallFriction);
}

void World::setWallFriction(BodyId id, float friction) {
    setKept(*state_, id, "setWallFriction", "friction", properties::kWallFriction, friction);
}

float World::floorAngle(BodyId id) const {
    return getKept<float>(*state_, id, "floorAngle", properties::kFloorAngle);
}

void World::setFloorAngle(BodyId id, float degrees) {
    setKept(*state_, id, "setFloorAngle", "degrees", properties::kFloorAngle, degrees);
}

float World::snapDown(BodyId id) const {
    return getKept<float>(*state_, id, "snapDown", properties::kSnapDown);
}

void World::setSnapDown(BodyId id, float distance) {
    setKept(*state_, id, "setSnapDown", "distance", properties::kSnapDown, distance);
}

float World::cornerCorrection(BodyId id) const {
    return getKept<float>(*state_, id, "cornerCorrection", properties::kCornerCorrection);
}

void World::setCornerCorrection(BodyId id, float distance) {
    setKept(*state_, id, "setCornerCorrection", "distance", properties::kCornerCorrection,
            distance);
}

float World::stepUp(BodyId id) const {
    return getKept<float>(*state_, id, "stepUp", properties::kStepUp);
}

void World::setStepUp(BodyId id, float height) {
    setKept(*state_, id, "setStepUp", "height", properties::kStepUp, height);
}

float World::walkSpeed(BodyId id) const {
    return lookUp(*state_, id, "walkSpeed").walkSpeed;
}

void World::setWalkSpeed(BodyId id, float speed) {
    Body& b = lookUpToChange(*state_, id, "setWalkSpeed");
    requireFinite("setWalkSpeed", "speed", speed);
    if (!b.isCharacter())
        fail("setWalkSpeed", "the body is not a character (a dynamic body with "
                             "BodyDef::character = true)");
    // A standing character, told to stand every frame, may sleep.
    const bool changed = b.walkSpeed != speed;
    b.walkSpeed = speed;
    if (changed)
        disturb(*state_, id.index);
}

std::optional<Ground> World::ground(BodyId id) const {
    lookUp(*state_, id, "ground");
    const GroundRecord g = groundOf(*state_, id);
    if (g.body.isNull())
        return std::nullopt;
    return Ground{g.body, g.normal, state_->slots[g.body.index].surfaceMotion(g.normal)};
}

} // namespace jostle
