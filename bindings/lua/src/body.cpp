// world:newBody and the Body methods. newBody's fields and getDef follow the descriptions
// of src/body_properties.hpp (definitions.hpp); the settings World gets and sets whole are a
// table (Setting).
#include "binding.hpp"

#include "body_properties.hpp"
#include "definitions.hpp"

#include <array>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <optional>
#include <type_traits>
#include <variant>

namespace jostle::lua {

namespace {

/// The body that is self, live: its world is alive and the body not destroyed.
BodyHandle& checkBody(lua_State* L, int index, const char* where) {
    auto* body = static_cast<BodyHandle*>(luaL_testudata(L, index, kBodyType));
    if (!body)
        raise(L, where, "expected a Body as self (call it with a colon: body:method()), got %s",
              typeName(L, index));
    if (!body->world->data)
        raise(L, where, "the body's world was destroyed");
    if (!body->world->data->world.isValid(body->id))
        raise(L, where, "the body was destroyed");
    return *body;
}

World& worldOf(const BodyHandle& body) {
    return body.world->data->world;
}

/// The value a getter reads from the world, or a Lua error.
template <class T, class Read> T read(lua_State* L, const char* where, Read read) {
    const BodyHandle& body = checkBody(L, 1, where);
    T value{};
    guard(L, where, [&] { value = read(worldOf(body), body.id); });
    return value;
}

/// Runs a setter on the body that is self, or raises.
template <class Change>
void change(lua_State* L, const char* where, const BodyHandle& body, Change change) {
    requireChangeable(L, *body.world->data, where);
    guard(L, where, [&] { change(worldOf(body), body.id); });
}

int pushVec2(lua_State* L, Vec2 v) {
    lua_pushnumber(L, static_cast<lua_Number>(v.x));
    lua_pushnumber(L, static_cast<lua_Number>(v.y));
    return 2;
}

int pushFloat(lua_State* L, float value) {
    lua_pushnumber(L, static_cast<lua_Number>(value));
    return 1;
}

// --- newBody ---------------------------------------------------------------------------

/// The fields newBody takes: every property's, userData (any Lua value) included.
constexpr auto kBodyFieldNames =
    Names<std::size(properties::kBodyFields)>().addAll(properties::kBodyFields, true);

/// The BodyDef of the table at `index`, with the rules of scene files: hw and hh
/// required, mass (> 0) or density but not both, every value checked.
BodyDef readBodyDef(lua_State* L, int index, const char* where) {
    checkTable(L, index, where, "def");
    const Fields fields(L, index, where);
    fields.allowOnly(kBodyFieldNames.data());
    BodyDef def;
    bool hasMass = false;
    readFields(fields, def, properties::kBodyFields, [&](const auto& field, bool given) {
        const char* name = field.property->name;
        if (!given && field.property->required)
            raise(L, where, "missing field \"%s\"", name);
        if (given && field.property == &properties::kMass) {
            hasMass = true;
            if (!(def.mass > 0.0f))
                fields.fail(name, "must be > 0");
        }
        if (given && hasMass && field.property == &properties::kDensity)
            raise(L, where, "give \"mass\" or \"density\", not both");
    });

    char message[kMessageSize];
    bool bad = false;
    const bool ran = attempt(message, [&] {
        if (auto problem = checkBodyDef(def)) {
            bad = true;
            describe(message, *problem);
        }
    });
    if (!ran || bad)
        raise(L, where, "%s", message);
    if (def.type == BodyType::Static && (def.vx != 0.0f || def.vy != 0.0f))
        raise(L, where, "vx, vy: a static body cannot move (make it kinematic)");
    return def;
}

/// Stores `value` (at `valueIndex`) as the user data of `id`, in the world's user value
/// table at `env`. Nil clears it.
void storeUserData(lua_State* L, int env, BodyId id, int valueIndex) {
    env = absIndex(L, env);
    valueIndex = absIndex(L, valueIndex);
    lua_rawgeti(L, env, kSlotUserData);
    lua_pushvalue(L, valueIndex);
    rawSetInteger(L, -2, id.index);
    lua_rawgeti(L, env, kSlotUserDataGen);
    if (lua_isnil(L, valueIndex))
        lua_pushnil(L);
    else
        pushWhole(L, id.generation);
    rawSetInteger(L, -2, id.index);
    lua_pop(L, 2);
}

int worldNewBody(lua_State* L) {
    const char* where = "World:newBody";
    WorldHandle& handle = checkWorldHandle(L, 1, where);
    requireChangeable(L, *handle.data, where);
    const BodyDef def = readBodyDef(L, 2, where);
    BodyId id;
    guard(L, where, [&] { id = handle.data->world.createBody(def); });
    pushUserValue(L, 1);
    const int env = lua_gettop(L);
    lua_pushstring(L, "userData");
    lua_rawget(L, 2);
    storeUserData(L, env, id, -1);
    lua_pop(L, 1);
    pushBody(L, env, &handle, id);
    return 1;
}

// --- Methods ---------------------------------------------------------------------------

int bodyDestroy(lua_State* L) {
    const char* where = "Body:destroy";
    const BodyHandle& body = checkBody(L, 1, where);
    requireChangeable(L, *body.world->data, where); // before its user data goes
    pushUserValue(L, 1);
    lua_pushnil(L);
    storeUserData(L, -2, body.id, -1);
    change(L, where, body, [](World& world, BodyId id) { world.destroyBody(id); });
    return 0;
}

/// True once the body is destroyed, or its world is.
int bodyIsDestroyed(lua_State* L) {
    const auto* body = static_cast<BodyHandle*>(luaL_testudata(L, 1, kBodyType));
    if (!body)
        raise(L, "Body:isDestroyed", "expected a Body as self (call it with a colon), got %s",
              typeName(L, 1));
    lua_pushboolean(L, !body->world->data || !body->world->data->world.isValid(body->id));
    return 1;
}

int bodyGetWorld(lua_State* L) {
    const auto* body = static_cast<BodyHandle*>(luaL_testudata(L, 1, kBodyType));
    if (!body)
        raise(L, "Body:getWorld", "expected a Body as self (call it with a colon), got %s",
              typeName(L, 1));
    pushUserValue(L, 1);
    lua_rawgeti(L, -1, kSlotWorld);
    return 1;
}

/// The storage slot, generation and world serial number: for debugging and logs, not
/// needed to identify a body (the userdata itself does).
int bodyGetId(lua_State* L) {
    const auto* body = static_cast<BodyHandle*>(luaL_testudata(L, 1, kBodyType));
    if (!body)
        raise(L, "Body:getId", "expected a Body as self (call it with a colon), got %s",
              typeName(L, 1));
    pushWhole(L, body->id.index);
    pushWhole(L, body->id.generation);
    pushWhole(L, body->id.world);
    return 3;
}

int bodyGetType(lua_State* L) {
    pushField(
        L, read<BodyType>(L, "Body:getType", [](const World& w, BodyId id) { return w.type(id); }));
    return 1;
}

int bodySetType(lua_State* L) {
    const char* where = "Body:setType";
    const BodyHandle& body = checkBody(L, 1, where);
    const BodyType type = valueAt<BodyType>(checkOption(L, 2, where, "type", kTypeNames));
    change(L, where, body, [&](World& w, BodyId id) { w.setType(id, type); });
    return 0;
}

int bodyGetHalfExtents(lua_State* L) {
    return pushVec2(L, read<Vec2>(L, "Body:getHalfExtents",
                                  [](const World& w, BodyId id) { return w.halfExtents(id); }));
}

int bodySetHalfExtents(lua_State* L) {
    const char* where = "Body:setHalfExtents";
    const BodyHandle& body = checkBody(L, 1, where);
    const Vec2 half = checkVec2(L, 2, where, "hw", "hh");
    if (!(half.x > 0.0f))
        raise(L, where, "hw: must be > 0");
    if (!(half.y > 0.0f))
        raise(L, where, "hh: must be > 0");
    change(L, where, body, [&](World& w, BodyId id) { w.setHalfExtents(id, half); });
    return 0;
}

/// left, top, width, height: what love.graphics.rectangle takes.
int bodyGetRect(lua_State* L) {
    const char* where = "Body:getRect";
    const BodyHandle& body = checkBody(L, 1, where);
    Vec2 p, half;
    guard(L, where, [&] {
        p = worldOf(body).position(body.id);
        half = worldOf(body).halfExtents(body.id);
    });
    pushVec2(L, p - half);
    return 2 + pushVec2(L, half * 2.0f);
}

int bodyGetDensity(lua_State* L) {
    return pushFloat(L, read<float>(L, "Body:getDensity", [](const World& w, BodyId id) {
                         return w.bodyDef(id).density;
                     }));
}

int bodySetDensity(lua_State* L) {
    const char* where = "Body:setDensity";
    const BodyHandle& body = checkBody(L, 1, where);
    const float density = checkNumber(L, 2, where, "density");
    change(L, where, body, [&](World& w, BodyId id) { w.setDensity(id, density); });
    return 0;
}

int bodyIsAwake(lua_State* L) {
    lua_pushboolean(
        L, read<bool>(L, "Body:isAwake", [](const World& w, BodyId id) { return w.isAwake(id); }));
    return 1;
}

int bodyWake(lua_State* L) {
    const char* where = "Body:wake";
    change(L, where, checkBody(L, 1, where), [](World& w, BodyId id) { w.wake(id); });
    return 0;
}

int bodyGetUserData(lua_State* L) {
    const BodyHandle& body = checkBody(L, 1, "Body:getUserData");
    pushUserValue(L, 1);
    lua_rawgeti(L, -1, kSlotUserDataGen);
    rawGetInteger(L, -1, body.id.index);
    const bool mine = lua_type(L, -1) == LUA_TNUMBER &&
                      lua_tonumber(L, -1) == static_cast<lua_Number>(body.id.generation);
    if (!mine) {
        lua_pushnil(L);
        return 1;
    }
    lua_rawgeti(L, -3, kSlotUserData);
    rawGetInteger(L, -1, body.id.index);
    return 1;
}

int bodySetUserData(lua_State* L) {
    const BodyHandle& body = checkBody(L, 1, "Body:setUserData");
    lua_settop(L, 2);
    pushUserValue(L, 1);
    storeUserData(L, -1, body.id, 2);
    return 0;
}

int bodyDropThrough(lua_State* L) {
    const char* where = "Body:dropThrough";
    const BodyHandle& body = checkBody(L, 1, where);
    const float seconds = checkNumber(L, 2, where, "seconds");
    change(L, where, body, [&](World& w, BodyId id) { w.dropThrough(id, seconds); });
    return 0;
}

int bodyGetSeparation(lua_State* L) {
    return pushVec2(L, read<Vec2>(L, "Body:getSeparation",
                                  [](const World& w, BodyId id) { return w.separation(id); }));
}

/// {floor = , ceiling = , wallLeft = , wallRight = }: what the body touched in the last
/// step, relative to gravity.
int bodyGetTouching(lua_State* L) {
    const Touching touching = read<Touching>(
        L, "Body:getTouching", [](const World& w, BodyId id) { return w.touching(id); });
    lua_createtable(L, 0, 4);
    lua_pushboolean(L, touching.floor);
    lua_setfield(L, -2, "floor");
    lua_pushboolean(L, touching.ceiling);
    lua_setfield(L, -2, "ceiling");
    lua_pushboolean(L, touching.wallLeft);
    lua_setfield(L, -2, "wallLeft");
    lua_pushboolean(L, touching.wallRight);
    lua_setfield(L, -2, "wallRight");
    return 1;
}

/// ground, nx, ny, vx, vy: what the body stood on at the end of the last step, the
/// ground's push (its normal) and its velocity; nil in the air.
int bodyGetGround(lua_State* L) {
    const char* where = "Body:getGround";
    const BodyHandle& body = checkBody(L, 1, where);
    std::optional<Ground> ground;
    guard(L, where, [&] { ground = worldOf(body).ground(body.id); });
    if (!ground) {
        lua_pushnil(L);
        return 1;
    }
    pushUserValue(L, 1);
    pushBody(L, -1, body.world, ground->body);
    lua_remove(L, -2);
    pushVec2(L, ground->normal);
    return 1 + 2 + pushVec2(L, ground->velocity);
}

/// An array of {other = , nx = , ny = , x = , y = , impulse = }: the bodies it touched at
/// the end of the last step.
int bodyGetContacts(lua_State* L) {
    const char* where = "Body:getContacts";
    const BodyHandle& body = checkBody(L, 1, where);
    WorldHandle* handle = body.world;
    guard(L, where, [&] { worldOf(body).contacts(body.id, handle->data->contacts); });
    pushUserValue(L, 1);
    const int env = lua_gettop(L);
    pushArray(
        L, *handle, [](const WorldData& w) -> const auto& { return w.contacts; },
        [&](const ContactInfo& contact) {
            pushBodyRecord(L, env, handle, "other", contact.other,
                           {{"nx", contact.normal.x},
                            {"ny", contact.normal.y},
                            {"x", contact.point.x},
                            {"y", contact.point.y},
                            {"impulse", contact.impulse}});
        });
    return 1;
}

/// True if the two touched at the end of the last step.
int bodyIsTouching(lua_State* L) {
    const char* where = "Body:isTouching";
    const BodyHandle& body = checkBody(L, 1, where);
    const BodyId other = checkBodyArgument(L, 2, *body.world->data, where, "other");
    bool touching = false;
    guard(L, where, [&] { touching = worldOf(body).isTouching(body.id, other); });
    lua_pushboolean(L, touching);
    return 1;
}

/// body:applyForce(fx, fy) and applyImpulse(ix, iy): a vector given to the body, at its
/// centre.
int applyVector(lua_State* L, const char* where, const char* xName, const char* yName,
                void (World::*apply)(BodyId, Vec2)) {
    const BodyHandle& body = checkBody(L, 1, where);
    const Vec2 vector = checkVec2(L, 2, where, xName, yName);
    change(L, where, body, [&](World& w, BodyId id) { (w.*apply)(id, vector); });
    return 0;
}

int bodyApplyForce(lua_State* L) {
    return applyVector(L, "Body:applyForce", "fx", "fy", &World::applyForce);
}

int bodyApplyImpulse(lua_State* L) {
    return applyVector(L, "Body:applyImpulse", "ix", "iy", &World::applyImpulse);
}

/// The body as a definition table that world:newBody accepts: the same fields, userData
/// (the value itself, not a copy) included.
int bodyGetDef(lua_State* L) {
    const BodyDef def =
        read<BodyDef>(L, "Body:getDef", [](const World& w, BodyId id) { return w.bodyDef(id); });
    // mass or density, never both, as newBody wants it.
    const properties::Property* leftOut =
        def.mass > 0.0f ? &properties::kDensity : &properties::kMass;
    lua_createtable(L, 0, 20);
    setFields(L, def, properties::kBodyFields);
    lua_pushnil(L);
    lua_setfield(L, -2, leftOut->name);
    // userData lives in the world's user value table, not in the BodyDef.
    const int table = lua_gettop(L);
    bodyGetUserData(L);
    lua_setfield(L, table, "userData");
    lua_settop(L, table);
    return 1;
}

/// The tile map the body is part of, or nil.
int bodyGetTileMap(lua_State* L) {
    const char* where = "Body:getTileMap";
    const BodyHandle& body = checkBody(L, 1, where);
    TileMapId map;
    guard(L, where, [&] { map = tileMapOf(worldOf(body), body.id); });
    pushUserValue(L, 1);
    pushTileMap(L, -1, body.world, map);
    return 1;
}

int bodyToString(lua_State* L) {
    const auto* body = static_cast<const BodyHandle*>(lua_touserdata(L, 1));
    const bool live = body->world->data && body->world->data->world.isValid(body->id);
    char text[64];
    std::snprintf(text, sizeof text, "jostle.Body %u#%u%s", body->id.index, body->id.generation,
                  live ? "" : " (destroyed)");
    lua_pushstring(L, text);
    return 1;
}

// --- Settings World gets and sets whole ------------------------------------------------

/// A setting of a body that World gets and sets as one value, and Lua's methods for it.
template <class T> struct Setting {
    const char* getter; ///< Lua's method names
    const char* setter;
    std::array<const char*, 2> arguments; ///< the setter's argument in messages (a vector's two)
    T (World::*get)(BodyId) const;
    void (World::*set)(BodyId, T);
};

// clang-format off
constexpr Setting<Vec2> kVectorSettings[] = {
    {"getPosition", "setPosition", {"x", "y"}, &World::position, &World::setPosition},
    {"getVelocity", "setVelocity", {"vx", "vy"}, &World::velocity, &World::setVelocity},
    {"getOneWay", "setOneWay", {"nx", "ny"}, &World::oneWay, &World::setOneWay},
    {"getSurfaceVelocity", "setSurfaceVelocity", {"vx", "vy"}, &World::surfaceVelocity,
     &World::setSurfaceVelocity},
};
constexpr Setting<float> kNumberSettings[] = {
    {"getBounce", "setBounce", {"bounce"}, &World::bounce, &World::setBounce},
    {"getFriction", "setFriction", {"friction"}, &World::friction, &World::setFriction},
    {"getMass", "setMass", {"mass"}, &World::mass, &World::setMass},
    {"getGravityScale", "setGravityScale", {"scale"}, &World::gravityScale,
        &World::setGravityScale},
    {"getDamping", "setDamping", {"damping"}, &World::damping, &World::setDamping},
    {"getWallFriction", "setWallFriction", {"friction"}, &World::wallFriction,
        &World::setWallFriction},
    {"getWalkSpeed", "setWalkSpeed", {"speed"}, &World::walkSpeed, &World::setWalkSpeed},
    {"getFloorAngle", "setFloorAngle", {"degrees"}, &World::floorAngle,
        &World::setFloorAngle},
    {"getSnapDown", "setSnapDown", {"distance"}, &World::snapDown, &World::setSnapDown},
    {"getCornerCorrection", "setCornerCorrection", {"distance"}, &World::cornerCorrection,
     &World::setCornerCorrection},
    {"getStepUp", "setStepUp", {"height"}, &World::stepUp, &World::setStepUp},
};
constexpr Setting<bool> kFlagSettings[] = {
    {"isBullet", "setBullet", {"bullet"}, &World::isBullet, &World::setBullet},
    {"isSensor", "setSensor", {"sensor"}, &World::isSensor, &World::setSensor},
    {"isCharacter", "setCharacter", {"character"}, &World::isCharacter, &World::setCharacter},
};
constexpr Setting<std::uint32_t> kBitsSettings[] = {
    {"getCategory", "setCategory", {"category"}, &World::category, &World::setCategory},
    {"getMask", "setMask", {"mask"}, &World::mask, &World::setMask},
};
// clang-format on

/// Reads a setter's argument (at 2, and 3 for a vector's y) of each type a setting has.
void checkArgument(lua_State* L, const char* where, const char* const* names, Vec2& out) {
    out = checkVec2(L, 2, where, names[0], names[1]);
}
void checkArgument(lua_State* L, const char* where, const char* const* names, float& out) {
    out = checkNumber(L, 2, where, names[0]);
}
void checkArgument(lua_State* L, const char* where, const char* const* names, bool& out) {
    out = checkBoolean(L, 2, where, names[0]);
}
void checkArgument(lua_State* L, const char* where, const char* const* names, std::uint32_t& out) {
    out = static_cast<std::uint32_t>(checkWhole(L, 2, where, names[0], 0, 0xFFFFFFFF));
}

/// The Setting<T> a getter's or setter's closure was made for (its upvalue).
template <class T> const Setting<T>& settingOf(lua_State* L) {
    return *static_cast<const Setting<T>*>(lua_touserdata(L, lua_upvalueindex(1)));
}

template <class T> int getSetting(lua_State* L) {
    const Setting<T>& setting = settingOf<T>(L);
    char where[64];
    std::snprintf(where, sizeof where, "Body:%s", setting.getter);
    const T value =
        read<T>(L, where, [&](const World& w, BodyId id) { return (w.*setting.get)(id); });
    if constexpr (std::is_same_v<T, Vec2>) {
        return pushVec2(L, value); // two results: x, y
    } else {
        pushField(L, value);
        return 1;
    }
}

template <class T> int setSetting(lua_State* L) {
    const Setting<T>& setting = settingOf<T>(L);
    char where[64];
    std::snprintf(where, sizeof where, "Body:%s", setting.setter);
    const BodyHandle& body = checkBody(L, 1, where);
    T value{};
    checkArgument(L, where, setting.arguments.data(), value);
    change(L, where, body, [&](World& w, BodyId id) { (w.*setting.set)(id, value); });
    return 0;
}

/// Adds each setting's getter and setter to the methods table on top of the stack.
template <class T, std::size_t N> void addSettings(lua_State* L, const Setting<T> (&settings)[N]) {
    for (const Setting<T>& setting : settings) {
        void* entry = const_cast<Setting<T>*>(&setting);
        lua_pushlightuserdata(L, entry);
        lua_pushcclosure(L, getSetting<T>, 1);
        lua_setfield(L, -2, setting.getter);
        lua_pushlightuserdata(L, entry);
        lua_pushcclosure(L, setSetting<T>, 1);
        lua_setfield(L, -2, setting.setter);
    }
}

constexpr luaL_Reg kBodyMethods[] = {
    {"destroy", bodyDestroy},
    {"isDestroyed", bodyIsDestroyed},
    {"getWorld", bodyGetWorld},
    {"getId", bodyGetId},
    {"getType", bodyGetType},
    {"setType", bodySetType},
    {"getHalfExtents", bodyGetHalfExtents},
    {"setHalfExtents", bodySetHalfExtents},
    {"getRect", bodyGetRect},
    {"getDensity", bodyGetDensity},
    {"setDensity", bodySetDensity},
    {"isAwake", bodyIsAwake},
    {"wake", bodyWake},
    {"getUserData", bodyGetUserData},
    {"setUserData", bodySetUserData},
    {"dropThrough", bodyDropThrough},
    {"getSeparation", bodyGetSeparation},
    {"getTouching", bodyGetTouching},
    {"getGround", bodyGetGround},
    {"getContacts", bodyGetContacts},
    {"isTouching", bodyIsTouching},
    {"applyForce", bodyApplyForce},
    {"applyImpulse", bodyApplyImpulse},
    {"getDef", bodyGetDef},
    {"getTileMap", bodyGetTileMap},
    {nullptr, nullptr},
};

constexpr luaL_Reg kWorldBodyMethods[] = {
    {"newBody", worldNewBody},
    {nullptr, nullptr},
};

} // namespace

void pushBody(lua_State* L, int env, WorldHandle* world, BodyId id) {
    pushHandle<BodyHandle>(L, env, kSlotBodies, 'b', kBodyType, world, id,
                           world->data->world.isValid(id));
}

void pushBodyRecord(lua_State* L, int env, WorldHandle* world, const char* bodyField, BodyId id,
                    std::initializer_list<NamedNumber> numbers) {
    lua_createtable(L, 0, static_cast<int>(numbers.size()) + 1);
    pushBody(L, env, world, id);
    lua_setfield(L, -2, bodyField);
    setNumbers(L, numbers);
}

BodyId checkBodyArgument(lua_State* L, int index, const WorldData& world, const char* where,
                         const char* name) {
    const auto* body = static_cast<BodyHandle*>(luaL_testudata(L, index, kBodyType));
    if (!body)
        raise(L, where, "%s: expected a Body, got %s", name, typeName(L, index));
    if (!body->world->data)
        raise(L, where, "%s: the body's world was destroyed", name);
    if (body->world->data != &world)
        raise(L, where, "%s: the body belongs to another world", name);
    if (!world.world.isValid(body->id))
        raise(L, where, "%s: the body was destroyed", name);
    return body->id;
}

void registerBodyMethods(lua_State* L, int worldMethods) {
    lua_pushvalue(L, worldMethods);
    luaL_setfuncs(L, kWorldBodyMethods, 0);
    lua_pop(L, 1);
}

void openBody(lua_State* L) {
    luaL_newmetatable(L, kBodyType);
    lua_createtable(L, 0, 64);
    luaL_setfuncs(L, kBodyMethods, 0);
    addSettings(L, kVectorSettings);
    addSettings(L, kNumberSettings);
    addSettings(L, kFlagSettings);
    addSettings(L, kBitsSettings);
    lua_setfield(L, -2, "__index");
    lua_pushcfunction(L, bodyToString);
    lua_setfield(L, -2, "__tostring");
    lua_pushliteral(L, "jostle.Body");
    lua_setfield(L, -2, "__name");
    lua_pop(L, 1);
}

} // namespace jostle::lua
