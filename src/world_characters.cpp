// World's characters: the character switch and its settings, walking, and the ground a
// body stands on (docs/characters.md); each setter checks its argument.
#include "body_setters.hpp"

#include <cstdint>
#include <optional>

namespace jostle {

// --- Characters ---------------------------------------------------------------------------

bool World::isCharacter(BodyId id) const {
    return lookUp(*state_, id, "isCharacter").character;
}

void World::setCharacter(BodyId id, bool character) {
    Body& b = lookUpToChange(*state_, id, "setCharacter");
    const bool was = b.maySnap();
    b.character = character;
    state_->snappingBodies += std::uint32_t(b.maySnap()) - std::uint32_t(was);
    disturb(*state_, id.index);
}

float World::wallFriction(BodyId id) const {
    return lookUp(*state_, id, "wallFriction").wallFriction;
}

void World::setWallFriction(BodyId id, float friction) {
    setKept(*state_, id, "setWallFriction", "friction", properties::kWallFriction,
            &Body::wallFriction, friction);
}

float World::floorAngle(BodyId id) const {
    lookUp(*state_, id, "floorAngle");
    return state_->asGiven[id.index].floorAngle;
}

void World::setFloorAngle(BodyId id, float degrees) {
    Body& b = lookUpToChange(*state_, id, "setFloorAngle");
    require("setFloorAngle", "degrees", properties::kFloorAngle.rule, degrees);
    state_->asGiven[id.index].floorAngle = degrees;
    b.floorCos = floorCosOf(degrees);
    disturb(*state_, id.index);
}

float World::snapDown(BodyId id) const {
    return lookUp(*state_, id, "snapDown").snapDown;
}

void World::setSnapDown(BodyId id, float distance) {
    const bool was = lookUpToChange(*state_, id, "setSnapDown").maySnap();
    setKept(*state_, id, "setSnapDown", "distance", properties::kSnapDown, &Body::snapDown,
            distance);
    state_->snappingBodies += std::uint32_t(state_->slots[id.index].maySnap()) - std::uint32_t(was);
}

namespace {

/// Sets a setting the corner stage reads (KeptAsGiven), keeping count of the bodies that
/// slip round corners.
void setCornerSetting(WorldState& w, BodyId id, const char* function, const char* what,
                      const properties::Property& property, float KeptAsGiven::*member,
                      float value) {
    lookUpToChange(w, id, function);
    require(function, what, property.rule, value);
    KeptAsGiven& kept = w.asGiven[id.index];
    const bool was = kept.slipsRoundCorners();
    kept.*member = value;
    w.cornerBodies += std::uint32_t(kept.slipsRoundCorners()) - std::uint32_t(was);
    disturb(w, id.index);
}

} // namespace

float World::cornerCorrection(BodyId id) const {
    lookUp(*state_, id, "cornerCorrection");
    return state_->asGiven[id.index].cornerCorrection;
}

void World::setCornerCorrection(BodyId id, float distance) {
    setCornerSetting(*state_, id, "setCornerCorrection", "distance", properties::kCornerCorrection,
                     &KeptAsGiven::cornerCorrection, distance);
}

float World::stepUp(BodyId id) const {
    lookUp(*state_, id, "stepUp");
    return state_->asGiven[id.index].stepUp;
}

void World::setStepUp(BodyId id, float height) {
    setCornerSetting(*state_, id, "setStepUp", "height", properties::kStepUp, &KeptAsGiven::stepUp,
                     height);
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
