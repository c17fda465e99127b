// world:debugDraw(draw [, options]) and jostle.rgba(colour) (docs/lua.md#debug-drawing):
// World::debugDraw into the world's DebugDrawList, then each call made on the Lua table's
// functions; those it lacks are drawn with its `line`, as DebugDraw draws them.
#include "binding.hpp"

#include <climits>
#include <cmath>

namespace jostle::lua {

namespace {

/// A colour as Lua sees it: one whole number, 0xRRGGBBAA.
std::uint32_t packed(Colour c) {
    return std::uint32_t{c.r} << 24 | std::uint32_t{c.g} << 16 | std::uint32_t{c.b} << 8 |
           std::uint32_t{c.a};
}

Colour unpacked(std::uint32_t value) {
    return {std::uint8_t(value >> 24), std::uint8_t(value >> 16), std::uint8_t(value >> 8),
            std::uint8_t(value)};
}

constexpr const char* kPaletteColours[] = {
    "staticBody", "kinematicBody", "dynamicBody", "bulletOutline", "oneWayFace", "contact",
    "velocity",   "touching",      "gridCell",    "gridBox",       nullptr};

Colour DebugPalette::*const kPaletteMembers[] = {
    &DebugPalette::staticBody,    &DebugPalette::kinematicBody, &DebugPalette::dynamicBody,
    &DebugPalette::bulletOutline, &DebugPalette::oneWayFace,    &DebugPalette::contact,
    &DebugPalette::velocity,      &DebugPalette::touching,      &DebugPalette::gridCell,
    &DebugPalette::gridBox};

void readPalette(lua_State* L, int table, const char* where, DebugPalette& palette) {
    if (lua_type(L, table) != LUA_TTABLE)
        raise(L, where, "options.palette: expected a table, got %s", typeName(L, table));
    const Fields fields(L, table, where, "options.palette.");
    static constexpr const char* kNames[] = {
        "staticBody",      "kinematicBody",  "dynamicBody", "bulletOutline", "oneWayFace",
        "contact",         "velocity",       "touching",    "gridCell",      "gridBox",
        "sleepingPercent", "outlinePercent", nullptr};
    fields.allowOnly(kNames);
    for (int i = 0; kPaletteColours[i]; ++i) {
        std::uint32_t value = 0;
        if (fields.bits(kPaletteColours[i], value))
            palette.*kPaletteMembers[i] = unpacked(value);
    }
    // Any whole number here: the library checks the range, in its words.
    fields.whole("sleepingPercent", palette.sleepingPercent, INT_MIN, INT_MAX);
    fields.whole("outlinePercent", palette.outlinePercent, INT_MIN, INT_MAX);
}

DebugDrawOptions readOptions(lua_State* L, int table, const char* where) {
    DebugDrawOptions options;
    if (lua_isnoneornil(L, table))
        return options;
    if (lua_type(L, table) != LUA_TTABLE)
        raise(L, where, "options: expected a table or nil, got %s", typeName(L, table));
    const Fields fields(L, table, where, "options.");
    static constexpr const char* kNames[] = {"shapes",  "contacts",   "velocities", "touching",
                                             "grid",    "markLength", "viewMin",    "viewMax",
                                             "palette", nullptr};
    fields.allowOnly(kNames);
    fields.boolean("shapes", options.shapes);
    fields.boolean("contacts", options.contacts);
    fields.boolean("velocities", options.velocities);
    fields.boolean("touching", options.touching);
    fields.boolean("grid", options.grid);
    fields.number("markLength", options.markLength);
    fields.vec2("viewMin", options.viewMin);
    fields.vec2("viewMax", options.viewMax);
    fields.push("palette");
    if (!lua_isnil(L, -1))
        readPalette(L, lua_gettop(L), where, options.palette);
    lua_pop(L, 1);
    return options;
}

/// The Lua renderer's functions at stack slots (0: absent), each called protected; after
/// the first error no more are called and the error value waits on top.
class LuaDraw final : public DebugDraw {
public:
    enum Function { kLine, kBox, kRoundedBox, kTriangle, kPoint, kFunctions };
    static constexpr const char* kNames[] = {"line",     "box",   "roundedBox",
                                             "triangle", "point", nullptr};

    LuaDraw(lua_State* L, const int (&slots)[kFunctions]) : L_(L) {
        for (int i = 0; i < kFunctions; ++i)
            slots_[i] = slots[i];
    }
    bool failed() const { return failed_; }

    void line(Vec2 from, Vec2 to, Colour colour) override {
        call(kLine, {from.x, from.y, to.x, to.y}, {packed(colour)});
    }
    void box(Vec2 centre, Vec2 half, Colour fill, Colour outline) override {
        if (!slots_[kBox])
            return DebugDraw::box(centre, half, fill, outline);
        call(kBox, {centre.x, centre.y, half.x, half.y}, {packed(fill), packed(outline)});
    }
    void roundedBox(Vec2 centre, Vec2 half, float radius, Colour fill, Colour outline) override {
        if (!slots_[kRoundedBox])
            return DebugDraw::roundedBox(centre, half, radius, fill, outline);
        call(kRoundedBox, {centre.x, centre.y, half.x, half.y, radius},
             {packed(fill), packed(outline)});
    }
    void triangle(Vec2 a, Vec2 b, Vec2 c, Colour fill, Colour outline) override {
        if (!slots_[kTriangle])
            return DebugDraw::triangle(a, b, c, fill, outline);
        call(kTriangle, {a.x, a.y, b.x, b.y, c.x, c.y}, {packed(fill), packed(outline)});
    }
    void point(Vec2 at, float size, Colour colour) override {
        if (!slots_[kPoint])
            return DebugDraw::point(at, size, colour);
        call(kPoint, {at.x, at.y, size}, {packed(colour)});
    }

private:
    /// function(numbers..., colours...): the colours as whole numbers.
    void call(Function function, std::initializer_list<float> numbers,
              std::initializer_list<std::uint32_t> colours) {
        if (failed_)
            return;
        lua_pushvalue(L_, slots_[function]);
        for (const float value : numbers)
            lua_pushnumber(L_, static_cast<lua_Number>(value));
        for (const std::uint32_t colour : colours)
            pushWhole(L_, colour);
        failed_ = lua_pcall(L_, static_cast<int>(numbers.size() + colours.size()), 0, 0) != 0;
    }

    lua_State* L_;
    int slots_[kFunctions];
    bool failed_ = false;
};

/// world:debugDraw(draw [, options]): draw is a table of functions, `line(x1, y1, x2, y2,
/// colour)` required and box, roundedBox, triangle, point optional.
int worldDebugDraw(lua_State* L) {
    const char* where = "World:debugDraw";
    WorldData& world = checkWorld(L, 1, where);
    if (world.drawing)
        raise(L, where, "called from a function of world:debugDraw");
    if (lua_type(L, 2) != LUA_TTABLE)
        raise(L, where, "draw: expected a table of functions, got %s", typeName(L, 2));
    const DebugDrawOptions options = readOptions(L, 3, where);
    lua_settop(L, 3);
    luaL_checkstack(L, LuaDraw::kFunctions + 12, "jostle: World:debugDraw");
    int slots[LuaDraw::kFunctions] = {};
    for (int i = 0; i < LuaDraw::kFunctions; ++i) {
        lua_getfield(L, 2, LuaDraw::kNames[i]);
        const int type = lua_type(L, -1);
        if (type == LUA_TFUNCTION)
            slots[i] = lua_gettop(L);
        else if (type != LUA_TNIL || i == LuaDraw::kLine)
            raise(L, where, "draw.%s: expected a function%s, got %s", LuaDraw::kNames[i],
                  i == LuaDraw::kLine ? "" : " or nil", typeName(L, -1));
    }
    // Drawn into the list first: the Lua functions run with no C++ frame of the core
    // under them, and may read the world.
    guard(L, where, [&] {
        world.drawList.clear();
        world.world.debugDraw(world.drawList, options);
    });
    bool failed = false;
    {
        LuaDraw draw(L, slots);
        world.drawing = true;
        world.drawList.replay(draw);
        world.drawing = false;
        failed = draw.failed();
    }
    if (failed)
        lua_error(L); // the function's own error, on top
    return 0;
}

constexpr luaL_Reg kDebugDrawMethods[] = {
    {"debugDraw", worldDebugDraw},
    {nullptr, nullptr},
};

} // namespace

void registerDebugDrawMethods(lua_State* L, int worldMethods) {
    lua_pushvalue(L, worldMethods);
    luaL_setfuncs(L, kDebugDrawMethods, 0);
    lua_pop(L, 1);
}

/// jostle.rgba(colour) -> r, g, b, a: a colour's parts from 0 to 1, for
/// love.graphics.setColor.
int rgba(lua_State* L) {
    const lua_Number value = luaL_checknumber(L, 1);
    if (!(value >= 0 && value <= 4294967295.0) || value != std::floor(value))
        raise(L, "jostle.rgba", "colour: expected a whole number from 0 to 0xFFFFFFFF");
    const Colour c = unpacked(static_cast<std::uint32_t>(value));
    for (const std::uint8_t channel : {c.r, c.g, c.b, c.a})
        lua_pushnumber(L, channel / 255.0);
    return 4;
}

} // namespace jostle::lua
