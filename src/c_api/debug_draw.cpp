// The C API's debug drawing: jostle_world_debug_draw over World::debugDraw, the C
// renderer's functions behind a DebugDraw, the NULL ones left to its lines.
#include "c_api.hpp"

using namespace jostle;
using namespace jostle::c_api;

namespace {

jostle_colour toC(Colour c) {
    return {c.r, c.g, c.b, c.a};
}

Colour toCpp(jostle_colour c) {
    return {c.r, c.g, c.b, c.a};
}

jostle_debug_palette toC(const DebugPalette& p) {
    return {toC(p.staticBody), toC(p.kinematicBody), toC(p.dynamicBody), p.sleepingPercent,
            p.outlinePercent,  toC(p.bulletOutline), toC(p.oneWayFace),  toC(p.contact),
            toC(p.velocity),   toC(p.touching),      toC(p.gridCell),    toC(p.gridBox)};
}

DebugPalette toCpp(const jostle_debug_palette& p) {
    return {toCpp(p.static_body),  toCpp(p.kinematic_body), toCpp(p.dynamic_body),
            p.sleeping_percent,    p.outline_percent,       toCpp(p.bullet_outline),
            toCpp(p.one_way_face), toCpp(p.contact),        toCpp(p.velocity),
            toCpp(p.touching),     toCpp(p.grid_cell),      toCpp(p.grid_box)};
}

DebugDrawOptions toCpp(const jostle_debug_draw_options& o) {
    requireCookie(o.internal_cookie, "options", "jostle_default_debug_draw_options");
    return {o.shapes,
            o.contacts,
            o.velocities,
            o.touching,
            o.grid,
            o.mark_length,
            jostle::c_api::toCpp(o.view_min),
            jostle::c_api::toCpp(o.view_max),
            toCpp(o.palette)};
}

/// The C renderer as a DebugDraw: each function it has, else DebugDraw's lines.
class CDraw final : public DebugDraw {
public:
    explicit CDraw(const jostle_debug_draw& draw) : draw_(draw) {}

    void line(Vec2 from, Vec2 to, Colour colour) override {
        draw_.line(c_api::toC(from), c_api::toC(to), toC(colour), draw_.user);
    }
    void box(Vec2 centre, Vec2 half, Colour fill, Colour outline) override {
        if (draw_.box == nullptr)
            return DebugDraw::box(centre, half, fill, outline);
        draw_.box(c_api::toC(centre), c_api::toC(half), toC(fill), toC(outline), draw_.user);
    }
    void roundedBox(Vec2 centre, Vec2 half, float radius, Colour fill, Colour outline) override {
        if (draw_.rounded_box == nullptr)
            return DebugDraw::roundedBox(centre, half, radius, fill, outline);
        draw_.rounded_box(c_api::toC(centre), c_api::toC(half), radius, toC(fill), toC(outline),
                          draw_.user);
    }
    void triangle(Vec2 a, Vec2 b, Vec2 c, Colour fill, Colour outline) override {
        if (draw_.triangle == nullptr)
            return DebugDraw::triangle(a, b, c, fill, outline);
        draw_.triangle(c_api::toC(a), c_api::toC(b), c_api::toC(c), toC(fill), toC(outline),
                       draw_.user);
    }
    void point(Vec2 at, float size, Colour colour) override {
        if (draw_.point == nullptr)
            return DebugDraw::point(at, size, colour);
        draw_.point(c_api::toC(at), size, toC(colour), draw_.user);
    }

private:
    const jostle_debug_draw& draw_;
};

} // namespace

extern "C" {

jostle_debug_draw_options jostle_default_debug_draw_options(void) {
    const DebugDrawOptions o;
    return {o.shapes,       o.contacts,   o.velocities,          o.touching,
            o.grid,         o.markLength, c_api::toC(o.viewMin), c_api::toC(o.viewMax),
            toC(o.palette), kCookie};
}

bool jostle_world_debug_draw(const jostle_world* world, const jostle_debug_draw* draw,
                             const jostle_debug_draw_options* options) {
    return guard(__func__, false, [&] {
        const World& w = worldOf(world).world;
        const jostle_debug_draw& d = required(draw, "draw");
        if (d.line == nullptr)
            misuse("draw->line is NULL (the one function a renderer must have)");
        CDraw drawing(d);
        w.debugDraw(drawing, options != nullptr ? toCpp(*options) : DebugDrawOptions{});
        return true;
    });
}

} // extern "C"
