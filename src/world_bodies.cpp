// World's bodies: creating and destroying them, their handles, and their getters and
// setters, each setter checking its argument (body_properties.hpp has the rules); the
// settings of characters are world_characters.cpp's.
#include "body_setters.hpp"
#include "integrate.hpp"
#include "room.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace jostle {

// --- Handles ---------------------------------------------------------------------------

bool World::isValid(BodyId id) const {
    return state_->isCurrent(id);
}

BodyId World::adopt(BodyId id) const {
    const WorldState& w = *state_;
    return !id.isNull() && w.isCurrent(SlotRef{id.index, id.generation}) ? w.idOf(id.index)
                                                                         : BodyId{};
}

BodyId World::createBody(const BodyDef& def) {
    requireChangeable(*state_, "createBody");
    if (auto problem = checkBodyDef(def))
        fail("createBody", "BodyDef." + problem->field + ": " + problem->problem);

    WorldState& w = *state_;
    Body made;
    KeptAsGiven kept;
    Shape shape;
    properties::keep(def, {made, kept, shape});
    if (shape.kind() != ShapeKind::Box && w.def.solver == Solver::Classic)
        fail("createBody", std::string("BodyDef.") + (def.slope != Vec2{} ? "slope" : "radius") +
                               ": the classic model has sharp boxes only");
    if (w.freeSlots.empty() && w.slots.size() == w.slots.capacity())
        w.reserveSlots(slotRoomAfter(w.slots.size()));
    const std::optional<std::uint32_t> taken = takeSlot(w.slots, w.freeSlots);
    if (!taken)
        fail("createBody", "too many bodies");
    const std::uint32_t slot = *taken;
    w.created.resize(w.slots.size());
    w.created[slot] = w.bodiesCreated++;
    w.shapes.resize(w.slots.size());
    w.shapes[slot] = shape;
    w.asGiven.resize(w.slots.size());
    w.asGiven[slot] = kept;
    // A body created by a callback may be touched later in the same step.
    w.events.touching.resize(w.slots.size(), 0);
    w.events.touching[slot] = 0;
    made.generation = w.slots[slot].generation;
    made.alive = true;
    made.lastStepVelocity = made.velocity;
    made.shape = shape.kind();
    deriveFrom(kept, made);
    w.slots[slot] = made;
    w.count(slot, true);

    const BodyId id = w.idOf(slot);
    w.order.append(id);
    disturb(w, slot);
    return id;
}

void World::destroyBody(BodyId id) {
    WorldState& w = *state_;
    Body& body = lookUpToChange(w, id, "destroyBody");
    disturb(w, id.index);
    w.events.destroyedSincePublish = true;
    if (body.type == BodyType::Static)
        w.restingDirty = true;
    w.count(id.index, false);
    body.alive = false;
    if (moveGenerationOn(body))
        (w.stepping ? w.pendingFree : w.freeSlots).push_back(id.index);
    w.order.remove(id.index);
}

std::span<const BodyId> World::bodies() const {
    return state_->order.live();
}

std::size_t World::bodyCount() const {
    return state_->order.size();
}

// --- Body getters and setters ----------------------------------------------------------

BodyDef World::bodyDef(BodyId id) const {
    const WorldState& w = *state_;
    lookUp(w, id, "bodyDef");
    return properties::definitionOf(placesOf(w, id.index));
}

BodyType World::type(BodyId id) const {
    return lookUp(*state_, id, "type").type;
}

void World::setType(BodyId id, BodyType type) {
    Body& b = lookUpToChange(*state_, id, "setType");
    if (const char* problem = properties::formProblem(type))
        fail("setType", std::string("type ") + problem);
    if (type == BodyType::Dynamic && (b.shape == ShapeKind::Ramp || b.shape == ShapeKind::Segment))
        fail("setType", "a ramp or segment must be static or kinematic");
    if (type == BodyType::Dynamic && b.surfaceVelocity != Vec2{})
        fail("setType", "a conveyor must be static or kinematic (set its surfaceVelocity to "
                        "{0, 0} first)");
    disturb(*state_, id.index); // what rested on it, where it was
    state_->restingDirty = true;
    b.type = type;
    ++state_->typeChanges;
    if (type == BodyType::Static) {
        b.velocity = {};
        b.separation = {}; // the step resets only what moves
    }
    b.lastStepVelocity = b.velocity;
    b.updateMass(state_->asGiven[id.index].density);
    disturb(*state_, id.index);
}

Vec2 World::position(BodyId id) const {
    return lookUp(*state_, id, "position").position;
}

void World::setPosition(BodyId id, Vec2 centre) {
    Body& b = lookUpToChange(*state_, id, "setPosition");
    requireFinite("setPosition", "centre", centre);
    disturb(*state_, id.index); // what rested on it, where it was
    b.position = centre;
    disturb(*state_, id.index);
}

Vec2 World::velocity(BodyId id) const {
    return lookUp(*state_, id, "velocity").velocity;
}

void World::setVelocity(BodyId id, Vec2 velocity) {
    Body& b = lookUpToChange(*state_, id, "setVelocity");
    requireFinite("setVelocity", "velocity", velocity);
    if (b.type == BodyType::Static && (velocity.x != 0.0f || velocity.y != 0.0f))
        fail("setVelocity", "a static body cannot move (make it kinematic)");
    b.velocity = velocity;
    disturb(*state_, id.index);
}

Vec2 World::halfExtents(BodyId id) const {
    return lookUp(*state_, id, "halfExtents").half;
}

void World::setHalfExtents(BodyId id, Vec2 halfExtents) {
    Body& b = lookUpToChange(*state_, id, "setHalfExtents");
    require("setHalfExtents", "halfExtents.x", properties::kHw.rule, halfExtents.x);
    require("setHalfExtents", "halfExtents.y", properties::kHh.rule, halfExtents.y);
    if (std::min(halfExtents.x, halfExtents.y) < state_->shapes[id.index].radius)
        fail("setHalfExtents", "halfExtents must be >= the body's radius");
    disturb(*state_, id.index); // what rested on it, as it was
    b.half = halfExtents;
    b.updateMass(state_->asGiven[id.index].density);
    disturb(*state_, id.index);
}

float World::bounce(BodyId id) const {
    return getKept<float>(*state_, id, "bounce", properties::kBounce);
}

void World::setBounce(BodyId id, float bounce) {
    setKept(*state_, id, "setBounce", "bounce", properties::kBounce, bounce);
}

float World::friction(BodyId id) const {
    return getKept<float>(*state_, id, "friction", properties::kFriction);
}

void World::setFriction(BodyId id, float friction) {
    setKept(*state_, id, "setFriction", "friction", properties::kFriction, friction);
}

float World::mass(BodyId id) const {
    const Body& b = lookUp(*state_, id, "mass");
    return b.isDynamic() ? b.dynamicMass(state_->asGiven[id.index].density)
                         : std::numeric_limits<float>::infinity();
}

void World::setMass(BodyId id, float mass) {
    Body& b = lookUpToChange(*state_, id, "setMass");
    // An explicit mass: a size (BodyDef::mass's 0, "from density", is setDensity's to ask).
    require("setMass", "mass", properties::Rule::Size, mass);
    b.mass = mass;
    b.updateMass(state_->asGiven[id.index].density);
    disturb(*state_, id.index);
}

void World::setDensity(BodyId id, float density) {
    Body& b = lookUpToChange(*state_, id, "setDensity");
    require("setDensity", "density", properties::kDensity.rule, density);
    b.mass = 0.0f;
    state_->asGiven[id.index].density = density;
    b.updateMass(density);
    disturb(*state_, id.index);
}

float World::gravityScale(BodyId id) const {
    return getKept<float>(*state_, id, "gravityScale", properties::kGravityScale);
}

void World::setGravityScale(BodyId id, float scale) {
    setKept(*state_, id, "setGravityScale", "scale", properties::kGravityScale, scale);
}

float World::damping(BodyId id) const {
    return getKept<float>(*state_, id, "damping", properties::kDamping);
}

void World::setDamping(BodyId id, float damping) {
    setKept(*state_, id, "setDamping", "damping", properties::kDamping, damping);
}

bool World::isBullet(BodyId id) const {
    return getKept<bool>(*state_, id, "isBullet", properties::kBullet);
}

void World::setBullet(BodyId id, bool bullet) {
    setKept(*state_, id, "setBullet", "bullet", properties::kBullet, bullet, Disturbs::No);
}

bool World::isAwake(BodyId id) const {
    return !lookUp(*state_, id, "isAwake").asleep;
}

void World::wake(BodyId id) {
    lookUpToChange(*state_, id, "wake");
    disturb(*state_, id.index); // its island, and the time it has been still, start over
}

Vec2 World::surfaceVelocity(BodyId id) const {
    return getKept<Vec2>(*state_, id, "surfaceVelocity", properties::kSurfaceVelocity);
}

void World::setSurfaceVelocity(BodyId id, Vec2 velocity) {
    const Body& body = lookUpToChange(*state_, id, "setSurfaceVelocity");
    requireFinite("setSurfaceVelocity", "velocity", velocity);
    if (velocity != Vec2{} && body.isDynamic())
        fail("setSurfaceVelocity", "a conveyor must be static or kinematic");
    setKept(*state_, id, "setSurfaceVelocity", "velocity", properties::kSurfaceVelocity, velocity);
}

Vec2 World::oneWay(BodyId id) const {
    return getKept<Vec2>(*state_, id, "oneWay", properties::kOneWay);
}

void World::setOneWay(BodyId id, Vec2 normal) {
    Body& body = lookUpToChange(*state_, id, "setOneWay");
    if (const char* problem = properties::problemOf(properties::kOneWay.rule, normal))
        fail("setOneWay", std::string("normal ") + problem);
    if (normal != Vec2{} && !body.isBox())
        fail("setOneWay", "a rounded body, ramp or segment cannot be one-way");
    body.oneWay = normal;
    disturb(*state_, id.index);
}

void World::dropThrough(BodyId id, float seconds) {
    Body& body = lookUpToChange(*state_, id, "dropThrough");
    if (body.type != BodyType::Dynamic)
        fail("dropThrough", "only a dynamic body drops through one-way platforms");
    if (!(seconds >= 0.0f) || !std::isfinite(seconds))
        fail("dropThrough", "seconds must be a finite number >= 0");
    body.dropThroughTime = seconds;
    disturb(*state_, id.index);
}

namespace {

/// Copies `member` of each body, in creation order, into `out`, as many as fit.
std::size_t readEach(const WorldState& w, std::span<Vec2> out, Vec2 Body::*member) {
    const std::span<const BodyId> order = w.order.live();
    const std::size_t count = std::min(out.size(), order.size());
    for (std::size_t i = 0; i < count; ++i)
        out[i] = w.slots[order[i].index].*member;
    return count;
}

} // namespace

std::size_t World::readPositions(std::span<Vec2> out) const {
    return readEach(*state_, out, &Body::position);
}

std::size_t World::readVelocities(std::span<Vec2> out) const {
    return readEach(*state_, out, &Body::velocity);
}

std::size_t World::readHalfExtents(std::span<Vec2> out) const {
    return readEach(*state_, out, &Body::half);
}

// --- Forces -------------------------------------------------------------------------------

void World::applyForce(BodyId id, Vec2 force) {
    const Body& b = lookUpToChange(*state_, id, "applyForce");
    requireFinite("applyForce", "force", force);
    if (!b.isDynamic())
        return;
    state_->forces.push_back({id, force});
    disturb(*state_, id.index);
}

void World::applyImpulse(BodyId id, Vec2 impulse) {
    Body& b = lookUpToChange(*state_, id, "applyImpulse");
    requireFinite("applyImpulse", "impulse", impulse);
    if (!b.isDynamic())
        return;
    b.velocity = withinRange(b.velocity + impulse * b.invMass);
    disturb(*state_, id.index);
}

std::uint32_t World::category(BodyId id) const {
    return getKept<std::uint32_t>(*state_, id, "category", properties::kCategory);
}

void World::setCategory(BodyId id, std::uint32_t bits) {
    setKept(*state_, id, "setCategory", "bits", properties::kCategory, bits);
}

std::uint32_t World::mask(BodyId id) const {
    return getKept<std::uint32_t>(*state_, id, "mask", properties::kMask);
}

void World::setMask(BodyId id, std::uint32_t bits) {
    setKept(*state_, id, "setMask", "bits", properties::kMask, bits);
}

bool World::isSensor(BodyId id) const {
    return getKept<bool>(*state_, id, "isSensor", properties::kSensor);
}

void World::setSensor(BodyId id, bool sensor) {
    setKept(*state_, id, "setSensor", "sensor", properties::kSensor, sensor);
}

void* World::userData(BodyId id) const {
    return getKept<void*>(*state_, id, "userData", properties::kUserData);
}

void World::setUserData(BodyId id, void* data) {
    setKept(*state_, id, "setUserData", "data", properties::kUserData, data, Disturbs::No);
}

Vec2 World::separation(BodyId id) const {
    return lookUp(*state_, id, "separation").separation;
}

} // namespace jostle
