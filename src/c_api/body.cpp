// The C API's bodies: creation, destruction, every getter and setter World offers, forces,
// contacts now, and move().
#include "c_api.hpp"

using namespace jostle;
using namespace jostle::c_api;

namespace {

/// A getter: the world's answer, or `Result{}` (zero) on misuse.
template <class Result, class Get>
Result get(const char* function, const jostle_world* world, Get&& read) noexcept {
    return guard(function, Result{}, [&] { return read(worldOf(world).world); });
}

/// A setter: true once `write` has run, false on misuse.
template <class Set> bool set(const char* function, jostle_world* world, Set&& write) noexcept {
    return guard(function, false, [&] {
        write(worldOf(world).world);
        return true;
    });
}

/// The C filter as move()'s, its answers checked (C may return any int); none for NULL.
MoveFilter moveFilter(jostle_move_filter_fn filter, void* context) {
    if (filter == nullptr)
        return {};
    return [filter, context](BodyId other) { return toCpp(filter(toC(other), context)); };
}

// The contacts of a body, kept from one call to the next; one set per thread, as getters
// may run on several threads at once.
thread_local std::vector<ContactInfo> foundContacts;

} // namespace

extern "C" {

jostle_body_def jostle_default_body_def(void) {
    return toC(BodyDef{});
}

jostle_body_id jostle_body_create(jostle_world* world, const jostle_body_def* def) {
    return guard(__func__, jostle_body_id{}, [&] {
        World& w = worldOf(world).world;
        return toC(w.createBody(toCpp(required(def, "def"))));
    });
}

bool jostle_body_destroy(jostle_world* world, jostle_body_id body) {
    return set(__func__, world, [&](World& w) { w.destroyBody(toCpp(body)); });
}

bool jostle_body_is_valid(const jostle_world* world, jostle_body_id body) {
    return get<bool>(__func__, world, [&](const World& w) { return w.isValid(toCpp(body)); });
}

jostle_body_id jostle_world_adopt_body(const jostle_world* world, jostle_body_id body) {
    return get<jostle_body_id>(__func__, world,
                               [&](const World& w) { return toC(w.adopt(toCpp(body))); });
}

jostle_body_def jostle_body_get_def(const jostle_world* world, jostle_body_id body) {
    return get<jostle_body_def>(__func__, world,
                                [&](const World& w) { return toC(w.bodyDef(toCpp(body))); });
}

jostle_body_type jostle_body_get_type(const jostle_world* world, jostle_body_id body) {
    return get<jostle_body_type>(__func__, world,
                                 [&](const World& w) { return toC(w.type(toCpp(body))); });
}

bool jostle_body_set_type(jostle_world* world, jostle_body_id body, jostle_body_type type) {
    return set(__func__, world, [&](World& w) { w.setType(toCpp(body), toCpp(type)); });
}

jostle_vec2 jostle_body_get_position(const jostle_world* world, jostle_body_id body) {
    return get<jostle_vec2>(__func__, world,
                            [&](const World& w) { return toC(w.position(toCpp(body))); });
}

bool jostle_body_set_position(jostle_world* world, jostle_body_id body, jostle_vec2 centre) {
    return set(__func__, world, [&](World& w) { w.setPosition(toCpp(body), toCpp(centre)); });
}

jostle_vec2 jostle_body_get_velocity(const jostle_world* world, jostle_body_id body) {
    return get<jostle_vec2>(__func__, world,
                            [&](const World& w) { return toC(w.velocity(toCpp(body))); });
}

bool jostle_body_set_velocity(jostle_world* world, jostle_body_id body, jostle_vec2 velocity) {
    return set(__func__, world, [&](World& w) { w.setVelocity(toCpp(body), toCpp(velocity)); });
}

jostle_vec2 jostle_body_get_half_extents(const jostle_world* world, jostle_body_id body) {
    return get<jostle_vec2>(__func__, world,
                            [&](const World& w) { return toC(w.halfExtents(toCpp(body))); });
}

bool jostle_body_set_half_extents(jostle_world* world, jostle_body_id body, jostle_vec2 half) {
    return set(__func__, world, [&](World& w) { w.setHalfExtents(toCpp(body), toCpp(half)); });
}

float jostle_body_get_bounce(const jostle_world* world, jostle_body_id body) {
    return get<float>(__func__, world, [&](const World& w) { return w.bounce(toCpp(body)); });
}

bool jostle_body_set_bounce(jostle_world* world, jostle_body_id body, float bounce) {
    return set(__func__, world, [&](World& w) { w.setBounce(toCpp(body), bounce); });
}

float jostle_body_get_friction(const jostle_world* world, jostle_body_id body) {
    return get<float>(__func__, world, [&](const World& w) { return w.friction(toCpp(body)); });
}

bool jostle_body_set_friction(jostle_world* world, jostle_body_id body, float friction) {
    return set(__func__, world, [&](World& w) { w.setFriction(toCpp(body), friction); });
}

float jostle_body_get_mass(const jostle_world* world, jostle_body_id body) {
    return get<float>(__func__, world, [&](const World& w) { return w.mass(toCpp(body)); });
}

bool jostle_body_set_mass(jostle_world* world, jostle_body_id body, float mass) {
    return set(__func__, world, [&](World& w) { w.setMass(toCpp(body), mass); });
}

bool jostle_body_set_density(jostle_world* world, jostle_body_id body, float density) {
    return set(__func__, world, [&](World& w) { w.setDensity(toCpp(body), density); });
}

float jostle_body_get_gravity_scale(const jostle_world* world, jostle_body_id body) {
    return get<float>(__func__, world, [&](const World& w) { return w.gravityScale(toCpp(body)); });
}

bool jostle_body_set_gravity_scale(jostle_world* world, jostle_body_id body, float scale) {
    return set(__func__, world, [&](World& w) { w.setGravityScale(toCpp(body), scale); });
}

float jostle_body_get_damping(const jostle_world* world, jostle_body_id body) {
    return get<float>(__func__, world, [&](const World& w) { return w.damping(toCpp(body)); });
}

bool jostle_body_set_damping(jostle_world* world, jostle_body_id body, float damping) {
    return set(__func__, world, [&](World& w) { w.setDamping(toCpp(body), damping); });
}

bool jostle_body_is_bullet(const jostle_world* world, jostle_body_id body) {
    return get<bool>(__func__, world, [&](const World& w) { return w.isBullet(toCpp(body)); });
}

bool jostle_body_set_bullet(jostle_world* world, jostle_body_id body, bool bullet) {
    return set(__func__, world, [&](World& w) { w.setBullet(toCpp(body), bullet); });
}

bool jostle_body_is_awake(const jostle_world* world, jostle_body_id body) {
    return get<bool>(__func__, world, [&](const World& w) { return w.isAwake(toCpp(body)); });
}

bool jostle_body_wake(jostle_world* world, jostle_body_id body) {
    return set(__func__, world, [&](World& w) { w.wake(toCpp(body)); });
}

void* jostle_body_get_user_data(const jostle_world* world, jostle_body_id body) {
    return get<void*>(__func__, world, [&](const World& w) { return w.userData(toCpp(body)); });
}

bool jostle_body_set_user_data(jostle_world* world, jostle_body_id body, void* data) {
    return set(__func__, world, [&](World& w) { w.setUserData(toCpp(body), data); });
}

jostle_vec2 jostle_body_get_one_way(const jostle_world* world, jostle_body_id body) {
    return get<jostle_vec2>(__func__, world,
                            [&](const World& w) { return toC(w.oneWay(toCpp(body))); });
}

bool jostle_body_set_one_way(jostle_world* world, jostle_body_id body, jostle_vec2 normal) {
    return set(__func__, world, [&](World& w) { w.setOneWay(toCpp(body), toCpp(normal)); });
}

bool jostle_body_drop_through(jostle_world* world, jostle_body_id body, float seconds) {
    return set(__func__, world, [&](World& w) { w.dropThrough(toCpp(body), seconds); });
}

uint32_t jostle_body_get_category(const jostle_world* world, jostle_body_id body) {
    return get<uint32_t>(__func__, world, [&](const World& w) { return w.category(toCpp(body)); });
}

bool jostle_body_set_category(jostle_world* world, jostle_body_id body, uint32_t bits) {
    return set(__func__, world, [&](World& w) { w.setCategory(toCpp(body), bits); });
}

uint32_t jostle_body_get_mask(const jostle_world* world, jostle_body_id body) {
    return get<uint32_t>(__func__, world, [&](const World& w) { return w.mask(toCpp(body)); });
}

bool jostle_body_set_mask(jostle_world* world, jostle_body_id body, uint32_t bits) {
    return set(__func__, world, [&](World& w) { w.setMask(toCpp(body), bits); });
}

bool jostle_body_is_sensor(const jostle_world* world, jostle_body_id body) {
    return get<bool>(__func__, world, [&](const World& w) { return w.isSensor(toCpp(body)); });
}

bool jostle_body_set_sensor(jostle_world* world, jostle_body_id body, bool sensor) {
    return set(__func__, world, [&](World& w) { w.setSensor(toCpp(body), sensor); });
}

jostle_vec2 jostle_body_get_separation(const jostle_world* world, jostle_body_id body) {
    return get<jostle_vec2>(__func__, world,
                            [&](const World& w) { return toC(w.separation(toCpp(body))); });
}

jostle_touching jostle_body_get_touching(const jostle_world* world, jostle_body_id body) {
    return get<jostle_touching>(__func__, world,
                                [&](const World& w) { return toC(w.touching(toCpp(body))); });
}

bool jostle_body_is_character(const jostle_world* world, jostle_body_id body) {
    return get<bool>(__func__, world, [&](const World& w) { return w.isCharacter(toCpp(body)); });
}

bool jostle_body_set_character(jostle_world* world, jostle_body_id body, bool character) {
    return set(__func__, world, [&](World& w) { w.setCharacter(toCpp(body), character); });
}

float jostle_body_get_wall_friction(const jostle_world* world, jostle_body_id body) {
    return get<float>(__func__, world, [&](const World& w) { return w.wallFriction(toCpp(body)); });
}

bool jostle_body_set_wall_friction(jostle_world* world, jostle_body_id body, float friction) {
    return set(__func__, world, [&](World& w) { w.setWallFriction(toCpp(body), friction); });
}

float jostle_body_get_floor_angle(const jostle_world* world, jostle_body_id body) {
    return get<float>(__func__, world, [&](const World& w) { return w.floorAngle(toCpp(body)); });
}

bool jostle_body_set_floor_angle(jostle_world* world, jostle_body_id body, float degrees) {
    return set(__func__, world, [&](World& w) { w.setFloorAngle(toCpp(body), degrees); });
}

float jostle_body_get_corner_correction(const jostle_world* world, jostle_body_id body) {
    return get<float>(__func__, world,
                      [&](const World& w) { return w.cornerCorrection(toCpp(body)); });
}

bool jostle_body_set_corner_correction(jostle_world* world, jostle_body_id body, float distance) {
    return set(__func__, world, [&](World& w) { w.setCornerCorrection(toCpp(body), distance); });
}

float jostle_body_get_step_up(const jostle_world* world, jostle_body_id body) {
    return get<float>(__func__, world, [&](const World& w) { return w.stepUp(toCpp(body)); });
}

bool jostle_body_set_step_up(jostle_world* world, jostle_body_id body, float height) {
    return set(__func__, world, [&](World& w) { w.setStepUp(toCpp(body), height); });
}

jostle_vec2 jostle_body_get_surface_velocity(const jostle_world* world, jostle_body_id body) {
    return get<jostle_vec2>(__func__, world,
                            [&](const World& w) { return toC(w.surfaceVelocity(toCpp(body))); });
}

bool jostle_body_set_surface_velocity(jostle_world* world, jostle_body_id body,
                                      jostle_vec2 velocity) {
    return set(__func__, world,
               [&](World& w) { w.setSurfaceVelocity(toCpp(body), toCpp(velocity)); });
}

float jostle_body_get_snap_down(const jostle_world* world, jostle_body_id body) {
    return get<float>(__func__, world, [&](const World& w) { return w.snapDown(toCpp(body)); });
}

bool jostle_body_set_snap_down(jostle_world* world, jostle_body_id body, float distance) {
    return set(__func__, world, [&](World& w) { w.setSnapDown(toCpp(body), distance); });
}

float jostle_body_get_walk_speed(const jostle_world* world, jostle_body_id body) {
    return get<float>(__func__, world, [&](const World& w) { return w.walkSpeed(toCpp(body)); });
}

bool jostle_body_set_walk_speed(jostle_world* world, jostle_body_id body, float speed) {
    return set(__func__, world, [&](World& w) { w.setWalkSpeed(toCpp(body), speed); });
}

bool jostle_body_get_ground(const jostle_world* world, jostle_body_id body, jostle_ground* ground) {
    return get<bool>(__func__, world, [&](const World& w) {
        jostle_ground& result = required(ground, "ground");
        return answer(w.ground(toCpp(body)), result);
    });
}

bool jostle_body_apply_force(jostle_world* world, jostle_body_id body, jostle_vec2 force) {
    return set(__func__, world, [&](World& w) { w.applyForce(toCpp(body), toCpp(force)); });
}

bool jostle_body_apply_impulse(jostle_world* world, jostle_body_id body, jostle_vec2 impulse) {
    return set(__func__, world, [&](World& w) { w.applyImpulse(toCpp(body), toCpp(impulse)); });
}

int jostle_body_contacts(const jostle_world* world, jostle_body_id body, jostle_contact_info* out,
                         int capacity) {
    return get<int>(__func__, world, [&](const World& w) {
        checkBuffer(out, capacity);
        w.contacts(toCpp(body), foundContacts);
        return copyOut(std::span<const ContactInfo>(foundContacts), out, capacity);
    });
}

bool jostle_body_is_touching(const jostle_world* world, jostle_body_id a, jostle_body_id b) {
    return get<bool>(__func__, world,
                     [&](const World& w) { return w.isTouching(toCpp(a), toCpp(b)); });
}

bool jostle_body_move(jostle_world* world, jostle_body_id body, jostle_vec2 delta,
                      jostle_move_filter_fn filter, void* context, jostle_move_result* result) {
    // On misuse nothing moved and nothing was met.
    if (result != nullptr)
        *result = {};
    return guard(__func__, false, [&] {
        jostle_world& w = worldOf(world);
        const BodyId id = toCpp(body);
        if (result != nullptr && w.world.isValid(id))
            result->centre = toC(w.world.position(id));
        MoveOutcome moved;
        {
            const FlagScope scope(w.moving);
            moved = move(w.world, id, toCpp(delta), moveFilter(filter, context));
        }
        // Where it went stands even if what it met cannot be kept (out of memory).
        if (result != nullptr)
            result->centre = toC(moved.centre);
        convert(std::span<const MoveCollision>(moved.collisions), w.moveCollisions);
        if (result != nullptr && !w.moveCollisions.empty()) {
            result->collisions = w.moveCollisions.data();
            result->count = countOf(w.moveCollisions.size());
        }
        return true;
    });
}

} // extern "C"
