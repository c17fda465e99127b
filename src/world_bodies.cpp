// World's bodies: creating and destroying them, their handles, and their getters and
// setters, each setter checking its argument (body_properties.hpp has the rules); the
// settings of characters are world_characters.cpp's.
#include "body_setters.hpp"
#include "integrate.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace jostle {

// --- Handles ---------------------------------------------------------------------------

bool World::isValid(BodyId id) const {
    return state_->isCurrent(id);
}

namespace {

/// Calls f(BodyDef member, Body member) for each setting a Body keeps as its BodyDef gives
/// it; position, velocity and size become vectors.
template <class F> void forEachKeptSetting(F&& f) {
    f(&BodyDef::type, &Body::type);
    f(&BodyDef::bounce, &Body::bounce);
    f(&BodyDef::friction, &Body::friction);
    f(&BodyDef::mass, &Body::mass);
    f(&BodyDef::gravityScale, &Body::gravityScale);
    f(&BodyDef::damping, &Body::damping);
    f(&BodyDef::bullet, &Body::bullet);
    f(&BodyDef::oneWay, &Body::oneWay);
    f(&BodyDef::category, &Body::category);
    f(&BodyDef::mask, &Body::mask);
    f(&BodyDef::sensor, &Body::sensor);
    f(&BodyDef::character, &Body::character);
    f(&BodyDef::wallFriction, &Body::wallFriction);
    f(&BodyDef::snapDown, &Body::snapDown);
    f(&BodyDef::surfaceVelocity, &Body::surfaceVelocity);
}

} // namespace

BodyId World::createBody(const BodyDef& def) {
    requireChangeable(*state_, "createBody");
    if (auto problem = checkBodyDef(def))
        fail("createBody", "BodyDef." + problem->field + ": " + problem->problem);

    WorldState& w = *state_;
    const Shape shape{def.radius, def.slope, def.segment};
    if (shape.kind() != ShapeKind::Box && w.def.solver == Solver::Classic)
        fail("createBody", std::string("BodyDef.") + (def.slope != Vec2{} ? "slope" : "radius") +
                               ": the classic model has sharp boxes only");
    const std::optional<std::uint32_t> taken = takeSlot(w.slots, w.freeSlots);
    if (!taken)
        fail("createBody", "too many bodies");
    const std::uint32_t slot = *taken;
    w.created.resize(w.slots.size());
    w.created[slot] = w.bodiesCreated++;
    w.shapes.resize(w.slots.size());
    w.shapes[slot] = shape;
    w.asGiven.resize(w.slots.size());
    w.asGiven[slot] = {def.userData, def.floorAngle, def.density, def.cornerCorrection, def.stepUp};
    if (w.asGiven[slot].slipsRoundCorners())
        ++w.cornerBodies;
    // A body created by a callback may be touched later in the same step.
    w.events.touching.resize(w.slots.size(), 0);
    w.events.touching[slot] = 0;
    Body& body = w.slots[slot];
    const std::uint32_t generation = body.generation;
    body = Body{};
    body.generation = generation;
    body.alive = true;
    body.position = {def.x, def.y};
    body.velocity = {def.vx, def.vy};
    body.half = {def.hw, def.hh};
    forEachKeptSetting([&](auto given, auto kept) { body.*kept = def.*given; });
    body.lastStepVelocity = body.velocity;
    body.shape = shape.kind();
    body.floorCos = floorCosOf(def.floorAngle);
    if (!body.isBox())
        ++w.shapedBodies;
    if (body.maySnap())
        ++w.snappingBodies;
    body.updateMass(def.density);
    if (body.surfaceVelocity != Vec2{})
        ++w.conveyors;

    if (slot < w.events.touching.size())
        w.events.touching[slot] = 0; // the slot's last body's flags
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
    body.alive = false;
    if (!body.isBox())
        --w.shapedBodies;
    if (body.maySnap())
        --w.snappingBodies;
    if (body.surfaceVelocity != Vec2{})
        --w.conveyors;
    if (w.asGiven[id.index].slipsRoundCorners())
        --w.cornerBodies;
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
    const Body& b = lookUp(*state_, id, "bodyDef");
    BodyDef def{.x = b.position.x,
                .y = b.position.y,
                .hw = b.half.x,
                .hh = b.half.y,
                .vx = b.velocity.x,
                .vy = b.velocity.y};
    forEachKeptSetting([&](auto given, auto kept) { def.*given = b.*kept; });
    const Shape& shape = state_->shapes[id.index];
    def.radius = shape.radius;
    def.slope = shape.slope;
    def.segment = shape.segment;
    def.userData = state_->asGiven[id.index].userData;
    def.floorAngle = state_->asGiven[id.index].floorAngle;
    def.density = state_->asGiven[id.index].density;
    def.cornerCorrection = state_->asGiven[id.index].cornerCorrection;
    def.stepUp = state_->asGiven[id.index].stepUp;
    return def;
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
    if (type == BodyType::Static)
        b.velocity = {};
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
    return lookUp(*state_, id, "bounce").bounce;
}

void World::setBounce(BodyId id, float bounce) {
    setKept(*state_, id, "setBounce", "bounce", properties::kBounce, &Body::bounce, bounce);
}

float World::friction(BodyId id) const {
    return lookUp(*state_, id, "friction").friction;
}

void World::setFriction(BodyId id, float friction) {
    setKept(*state_, id, "setFriction", "friction", properties::kFriction, &Body::friction,
            friction);
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
    return lookUp(*state_, id, "gravityScale").gravityScale;
}

void World::setGravityScale(BodyId id, float scale) {
    setKept(*state_, id, "setGravityScale", "scale", properties::kGravityScale, &Body::gravityScale,
            scale);
}

float World::damping(BodyId id) const {
    return lookUp(*state_, id, "damping").damping;
}

void World::setDamping(BodyId id, float damping) {
    setKept(*state_, id, "setDamping", "damping", properties::kDamping, &Body::damping, damping);
}

bool World::isBullet(BodyId id) const {
    return lookUp(*state_, id, "isBullet").bullet;
}

void World::setBullet(BodyId id, bool bullet) {
    lookUpToChange(*state_, id, "setBullet").bullet = bullet;
}

bool World::isAwake(BodyId id) const {
    return !lookUp(*state_, id, "isAwake").asleep;
}

void World::wake(BodyId id) {
    lookUpToChange(*state_, id, "wake");
    disturb(*state_, id.index); // its island, and the time it has been still, start over
}

Vec2 World::surfaceVelocity(BodyId id) const {
    return lookUp(*state_, id, "surfaceVelocity").surfaceVelocity;
}

void World::setSurfaceVelocity(BodyId id, Vec2 velocity) {
    Body& body = lookUpToChange(*state_, id, "setSurfaceVelocity");
    requireFinite("setSurfaceVelocity", "velocity", velocity);
    if (velocity != Vec2{} && body.isDynamic())
        fail("setSurfaceVelocity", "a conveyor must be static or kinematic");
    state_->conveyors +=
        std::uint32_t(velocity != Vec2{}) - std::uint32_t(body.surfaceVelocity != Vec2{});
    body.surfaceVelocity = velocity;
    disturb(*state_, id.index);
}

Vec2 World::oneWay(BodyId id) const {
    return lookUp(*state_, id, "oneWay").oneWay;
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
    return lookUp(*state_, id, "category").category;
}

void World::setCategory(BodyId id, std::uint32_t bits) {
    lookUpToChange(*state_, id, "setCategory").category = bits;
    disturb(*state_, id.index);
}

std::uint32_t World::mask(BodyId id) const {
    return lookUp(*state_, id, "mask").mask;
}

void World::setMask(BodyId id, std::uint32_t bits) {
    lookUpToChange(*state_, id, "setMask").mask = bits;
    disturb(*state_, id.index);
}

bool World::isSensor(BodyId id) const {
    return lookUp(*state_, id, "isSensor").sensor;
}

void World::setSensor(BodyId id, bool sensor) {
    lookUpToChange(*state_, id, "setSensor").sensor = sensor;
    disturb(*state_, id.index);
}

void* World::userData(BodyId id) const {
    lookUp(*state_, id, "userData");
    return state_->asGiven[id.index].userData;
}

void World::setUserData(BodyId id, void* data) {
    lookUpToChange(*state_, id, "setUserData");
    state_->asGiven[id.index].userData = data;
}

Vec2 World::separation(BodyId id) const {
    return lookUp(*state_, id, "separation").separation;
}

} // namespace jostle
