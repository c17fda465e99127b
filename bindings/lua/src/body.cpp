// world:newBody and the Body methods.
#include "binding.hpp"

#include <cmath>
#include <cstdio>

namespace jostle::lua {

namespace {

constexpr const char* kTypeNames[] = {"static", "kinematic", "dynamic", nullptr};

BodyType bodyTypeOf(int option) {
    return option == 0 ? BodyType::Static : option == 1 ? BodyType::Kinematic : BodyType::Dynamic;
}
const char* bodyTypeName(BodyType type) {
    return type == BodyType::Static      ? "static"
           : type == BodyType::Kinematic ? "kinematic"
                                         : "dynamic";
}

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

constexpr const char* kBodyFields[] = {
    "type",   "x",        "y",    "hw",      "hh",           "vx",      "vy",
    "bounce", "friction", "mass", "density", "gravityScale", "damping", "bullet",
    "oneWay", "category", "mask", "sensor",  "userData",     nullptr};

/// The BodyDef of the table at `index`, with the rules of scene files: hw and hh
/// required, mass (> 0) or density but not both, every value checked.
BodyDef readBodyDef(lua_State* L, int index, const char* where) {
    checkTable(L, index, where, "def");
    const Fields fields(L, index, where);
    fields.allowOnly(kBodyFields);
    BodyDef def;
    int type = 2;
    if (fields.option("type", type, kTypeNames))
        def.type = bodyTypeOf(type);
    fields.number("x", def.x);
    fields.number("y", def.y);
    if (!fields.number("hw", def.hw))
        raise(L, where, "missing field \"hw\"");
    if (!fields.number("hh", def.hh))
        raise(L, where, "missing field \"hh\"");
    fields.number("vx", def.vx);
    fields.number("vy", def.vy);
    fields.number("bounce", def.bounce);
    fields.number("friction", def.friction);
    const bool hasMass = fields.number("mass", def.mass);
    if (hasMass && !(def.mass > 0.0f))
        fields.fail("mass", "must be > 0");
    if (fields.number("density", def.density) && hasMass)
        raise(L, where, "give \"mass\" or \"density\", not both");
    fields.number("gravityScale", def.gravityScale);
    fields.number("damping", def.damping);
    fields.boolean("bullet", def.bullet);
    fields.vec2("oneWay", def.oneWay);
    fields.bits("category", def.category);
    fields.bits("mask", def.mask);
    fields.boolean("sensor", def.sensor);

    char message[kMessageSize];
    bool bad = false;
    const bool ran = attempt(message, [&] {
        if (auto problem = checkBodyDef(def)) {
            bad = true;
            std::snprintf(message, kMessageSize, "%s: %s", problem->field.c_str(),
                          problem->problem.c_str());
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

/// The storage slot and generation: for debugging and logs, not needed to identify a
/// body (the userdata itself does).
int bodyGetId(lua_State* L) {
    const auto* body = static_cast<BodyHandle*>(luaL_testudata(L, 1, kBodyType));
    if (!body)
        raise(L, "Body:getId", "expected a Body as self (call it with a colon), got %s",
              typeName(L, 1));
    pushWhole(L, body->id.index);
    pushWhole(L, body->id.generation);
    return 2;
}

int bodyGetType(lua_State* L) {
    lua_pushstring(L, bodyTypeName(read<BodyType>(L, "Body:getType", [](const World& w, BodyId id) {
                       return w.type(id);
                   })));
    return 1;
}

int bodySetType(lua_State* L) {
    const char* where = "Body:setType";
    const BodyHandle& body = checkBody(L, 1, where);
    const BodyType type = bodyTypeOf(checkOption(L, 2, where, "type", kTypeNames));
    change(L, where, body, [&](World& w, BodyId id) { w.setType(id, type); });
    return 0;
}

int bodyGetPosition(lua_State* L) {
    return pushVec2(L, read<Vec2>(L, "Body:getPosition",
                                  [](const World& w, BodyId id) { return w.position(id); }));
}

int bodySetPosition(lua_State* L) {
    const char* where = "Body:setPosition";
    const BodyHandle& body = checkBody(L, 1, where);
    const Vec2 p = checkVec2(L, 2, where, "x", "y");
    change(L, where, body, [&](World& w, BodyId id) { w.setPosition(id, p); });
    return 0;
}

int bodyGetVelocity(lua_State* L) {
    return pushVec2(L, read<Vec2>(L, "Body:getVelocity",
                                  [](const World& w, BodyId id) { return w.velocity(id); }));
}

int bodySetVelocity(lua_State* L) {
    const char* where = "Body:setVelocity";
    const BodyHandle& body = checkBody(L, 1, where);
    const Vec2 v = checkVec2(L, 2, where, "vx", "vy");
    change(L, where, body, [&](World& w, BodyId id) { w.setVelocity(id, v); });
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

/// A float property with a getter and a setter taking one number.
#define JOSTLE_FLOAT_PROPERTY(Name, getter, setter, argument)                                      \
    int bodyGet##Name(lua_State* L) {                                                              \
        return pushFloat(L, read<float>(L, "Body:get" #Name,                                       \
                                        [](const World& w, BodyId id) { return w.getter(id); }));  \
    }                                                                                              \
    int bodySet##Name(lua_State* L) {                                                              \
        const char* where = "Body:set" #Name;                                                      \
        const BodyHandle& body = checkBody(L, 1, where);                                           \
        const float value = checkNumber(L, 2, where, argument);                                    \
        change(L, where, body, [&](World& w, BodyId id) { w.setter(id, value); });                 \
        return 0;                                                                                  \
    }

JOSTLE_FLOAT_PROPERTY(Bounce, bounce, setBounce, "bounce")
JOSTLE_FLOAT_PROPERTY(Friction, friction, setFriction, "friction")
JOSTLE_FLOAT_PROPERTY(Mass, mass, setMass, "mass")
JOSTLE_FLOAT_PROPERTY(GravityScale, gravityScale, setGravityScale, "scale")
JOSTLE_FLOAT_PROPERTY(Damping, damping, setDamping, "damping")
#undef JOSTLE_FLOAT_PROPERTY

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

int bodyIsBullet(lua_State* L) {
    lua_pushboolean(L, read<bool>(L, "Body:isBullet",
                                  [](const World& w, BodyId id) { return w.isBullet(id); }));
    return 1;
}

int bodySetBullet(lua_State* L) {
    const char* where = "Body:setBullet";
    const BodyHandle& body = checkBody(L, 1, where);
    const bool bullet = checkBoolean(L, 2, where, "bullet");
    change(L, where, body, [&](World& w, BodyId id) { w.setBullet(id, bullet); });
    return 0;
}

int bodyIsSensor(lua_State* L) {
    lua_pushboolean(L, read<bool>(L, "Body:isSensor",
                                  [](const World& w, BodyId id) { return w.isSensor(id); }));
    return 1;
}

int bodySetSensor(lua_State* L) {
    const char* where = "Body:setSensor";
    const BodyHandle& body = checkBody(L, 1, where);
    const bool sensor = checkBoolean(L, 2, where, "sensor");
    change(L, where, body, [&](World& w, BodyId id) { w.setSensor(id, sensor); });
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

int bodyGetOneWay(lua_State* L) {
    return pushVec2(
        L, read<Vec2>(L, "Body:getOneWay", [](const World& w, BodyId id) { return w.oneWay(id); }));
}

int bodySetOneWay(lua_State* L) {
    const char* where = "Body:setOneWay";
    const BodyHandle& body = checkBody(L, 1, where);
    const Vec2 normal = checkVec2(L, 2, where, "nx", "ny");
    change(L, where, body, [&](World& w, BodyId id) { w.setOneWay(id, normal); });
    return 0;
}

int bodyDropThrough(lua_State* L) {
    const char* where = "Body:dropThrough";
    const BodyHandle& body = checkBody(L, 1, where);
    const float seconds = checkNumber(L, 2, where, "seconds");
    change(L, where, body, [&](World& w, BodyId id) { w.dropThrough(id, seconds); });
    return 0;
}

int bodyGetCategory(lua_State* L) {
    pushWhole(L, read<std::uint32_t>(L, "Body:getCategory",
                                     [](const World& w, BodyId id) { return w.category(id); }));
    return 1;
}

int bodySetCategory(lua_State* L) {
    const char* where = "Body:setCategory";
    const BodyHandle& body = checkBody(L, 1, where);
    const auto bits =
        static_cast<std::uint32_t>(checkWhole(L, 2, where, "category", 0, 0xFFFFFFFF));
    change(L, where, body, [&](World& w, BodyId id) { w.setCategory(id, bits); });
    return 0;
}

int bodyGetMask(lua_State* L) {
    pushWhole(L, read<std::uint32_t>(L, "Body:getMask",
                                     [](const World& w, BodyId id) { return w.mask(id); }));
    return 1;
}

int bodySetMask(lua_State* L) {
    const char* where = "Body:setMask";
    const BodyHandle& body = checkBody(L, 1, where);
    const auto bits = static_cast<std::uint32_t>(checkWhole(L, 2, where, "mask", 0, 0xFFFFFFFF));
    change(L, where, body, [&](World& w, BodyId id) { w.setMask(id, bits); });
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

/// The body as a definition table that world:newBody accepts: the same fields.
int bodyGetDef(lua_State* L) {
    const BodyDef def =
        read<BodyDef>(L, "Body:getDef", [](const World& w, BodyId id) { return w.bodyDef(id); });
    lua_createtable(L, 0, 18);
    lua_pushstring(L, bodyTypeName(def.type));
    lua_setfield(L, -2, "type");
    const struct {
        const char* name;
        float value;
    } numbers[] = {{"x", def.x},
                   {"y", def.y},
                   {"hw", def.hw},
                   {"hh", def.hh},
                   {"vx", def.vx},
                   {"vy", def.vy},
                   {"bounce", def.bounce},
                   {"friction", def.friction},
                   {"gravityScale", def.gravityScale},
                   {"damping", def.damping}};
    for (const auto& number : numbers) {
        lua_pushnumber(L, static_cast<lua_Number>(number.value));
        lua_setfield(L, -2, number.name);
    }
    // mass or density, never both, as newBody wants it.
    lua_pushnumber(L, static_cast<lua_Number>(def.mass > 0.0f ? def.mass : def.density));
    lua_setfield(L, -2, def.mass > 0.0f ? "mass" : "density");
    lua_pushboolean(L, def.bullet);
    lua_setfield(L, -2, "bullet");
    lua_createtable(L, 2, 0);
    lua_pushnumber(L, static_cast<lua_Number>(def.oneWay.x));
    lua_rawseti(L, -2, 1);
    lua_pushnumber(L, static_cast<lua_Number>(def.oneWay.y));
    lua_rawseti(L, -2, 2);
    lua_setfield(L, -2, "oneWay");
    pushWhole(L, def.category);
    lua_setfield(L, -2, "category");
    pushWhole(L, def.mask);
    lua_setfield(L, -2, "mask");
    lua_pushboolean(L, def.sensor);
    lua_setfield(L, -2, "sensor");
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

constexpr luaL_Reg kBodyMethods[] = {
    {"destroy", bodyDestroy},
    {"isDestroyed", bodyIsDestroyed},
    {"getWorld", bodyGetWorld},
    {"getId", bodyGetId},
    {"getType", bodyGetType},
    {"setType", bodySetType},
    {"getPosition", bodyGetPosition},
    {"setPosition", bodySetPosition},
    {"getVelocity", bodyGetVelocity},
    {"setVelocity", bodySetVelocity},
    {"getHalfExtents", bodyGetHalfExtents},
    {"setHalfExtents", bodySetHalfExtents},
    {"getRect", bodyGetRect},
    {"getBounce", bodyGetBounce},
    {"setBounce", bodySetBounce},
    {"getFriction", bodyGetFriction},
    {"setFriction", bodySetFriction},
    {"getMass", bodyGetMass},
    {"setMass", bodySetMass},
    {"getDensity", bodyGetDensity},
    {"setDensity", bodySetDensity},
    {"getGravityScale", bodyGetGravityScale},
    {"setGravityScale", bodySetGravityScale},
    {"getDamping", bodyGetDamping},
    {"setDamping", bodySetDamping},
    {"isBullet", bodyIsBullet},
    {"setBullet", bodySetBullet},
    {"isSensor", bodyIsSensor},
    {"setSensor", bodySetSensor},
    {"isAwake", bodyIsAwake},
    {"wake", bodyWake},
    {"getUserData", bodyGetUserData},
    {"setUserData", bodySetUserData},
    {"getOneWay", bodyGetOneWay},
    {"setOneWay", bodySetOneWay},
    {"dropThrough", bodyDropThrough},
    {"getCategory", bodyGetCategory},
    {"setCategory", bodySetCategory},
    {"getMask", bodyGetMask},
    {"setMask", bodySetMask},
    {"getSeparation", bodyGetSeparation},
    {"getTouching", bodyGetTouching},
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
    lua_createtable(L, 0, 48);
    luaL_setfuncs(L, kBodyMethods, 0);
    lua_setfield(L, -2, "__index");
    lua_pushcfunction(L, bodyToString);
    lua_setfield(L, -2, "__tostring");
    lua_pushliteral(L, "jostle.Body");
    lua_setfield(L, -2, "__name");
    lua_pop(L, 1);
}

} // namespace jostle::lua
