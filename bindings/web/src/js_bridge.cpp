// What the npm package's JavaScript (package/, docs/javascript.md) needs of the module
// beside jostle.h's functions: where the members of jostle.h's structs are, read from the
// header by the compiler instead of copied into JavaScript; and the C callbacks (pre-solve,
// a move's filter) that hand each call to the JavaScript function the game gave.
#include "jostle/jostle.h"
#include "jostle/world.hpp"

#include <emscripten/emscripten.h>

#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

namespace {

using Members = std::initializer_list<std::pair<const char*, std::size_t>>;

/// `"name": {"size": n, "member": offset, ...}` of one struct.
void addStruct(std::string& out, const char* name, std::size_t size, Members members) {
    out += out.size() > 1 ? ",\"" : "\"";
    out += name;
    out += "\":{\"size\":" + std::to_string(size);
    for (const auto& [member, offset] : members)
        out += ",\"" + std::string(member) + "\":" + std::to_string(offset);
    out += '}';
}

#define JOSTLE_MEMBER(type, member)                                                                \
    { #member, offsetof(type, member) }

std::string layoutJson() {
    std::string out = "{";
    addStruct(out, "body_id", sizeof(jostle_body_id),
              {JOSTLE_MEMBER(jostle_body_id, index), JOSTLE_MEMBER(jostle_body_id, generation),
               JOSTLE_MEMBER(jostle_body_id, world)});
    addStruct(out, "touching", sizeof(jostle_touching),
              {JOSTLE_MEMBER(jostle_touching, floor), JOSTLE_MEMBER(jostle_touching, ceiling),
               JOSTLE_MEMBER(jostle_touching, wall_left),
               JOSTLE_MEMBER(jostle_touching, wall_right)});
    addStruct(out, "ground", sizeof(jostle_ground),
              {JOSTLE_MEMBER(jostle_ground, body), JOSTLE_MEMBER(jostle_ground, normal),
               JOSTLE_MEMBER(jostle_ground, velocity)});
    addStruct(
        out, "contact_info", sizeof(jostle_contact_info),
        {JOSTLE_MEMBER(jostle_contact_info, other), JOSTLE_MEMBER(jostle_contact_info, normal),
         JOSTLE_MEMBER(jostle_contact_info, point), JOSTLE_MEMBER(jostle_contact_info, impulse)});
    addStruct(out, "contact_event", sizeof(jostle_contact_event),
              {JOSTLE_MEMBER(jostle_contact_event, a), JOSTLE_MEMBER(jostle_contact_event, b),
               JOSTLE_MEMBER(jostle_contact_event, normal),
               JOSTLE_MEMBER(jostle_contact_event, approach_speed),
               JOSTLE_MEMBER(jostle_contact_event, point)});
    addStruct(
        out, "sensor_event", sizeof(jostle_sensor_event),
        {JOSTLE_MEMBER(jostle_sensor_event, sensor), JOSTLE_MEMBER(jostle_sensor_event, visitor)});
    addStruct(out, "crush_event", sizeof(jostle_crush_event),
              {JOSTLE_MEMBER(jostle_crush_event, body), JOSTLE_MEMBER(jostle_crush_event, by),
               JOSTLE_MEMBER(jostle_crush_event, against)});
    addStruct(out, "collision", sizeof(jostle_collision),
              {JOSTLE_MEMBER(jostle_collision, a), JOSTLE_MEMBER(jostle_collision, b),
               JOSTLE_MEMBER(jostle_collision, normal), JOSTLE_MEMBER(jostle_collision, depth),
               JOSTLE_MEMBER(jostle_collision, bounce), JOSTLE_MEMBER(jostle_collision, friction)});
    addStruct(out, "query_filter", sizeof(jostle_query_filter),
              {JOSTLE_MEMBER(jostle_query_filter, mask),
               JOSTLE_MEMBER(jostle_query_filter, category),
               JOSTLE_MEMBER(jostle_query_filter, include_sensors),
               JOSTLE_MEMBER(jostle_query_filter, ignore)});
    addStruct(out, "ray_hit", sizeof(jostle_ray_hit),
              {JOSTLE_MEMBER(jostle_ray_hit, body), JOSTLE_MEMBER(jostle_ray_hit, point),
               JOSTLE_MEMBER(jostle_ray_hit, normal), JOSTLE_MEMBER(jostle_ray_hit, fraction)});
    addStruct(out, "box_cast_hit", sizeof(jostle_box_cast_hit),
              {JOSTLE_MEMBER(jostle_box_cast_hit, body), JOSTLE_MEMBER(jostle_box_cast_hit, centre),
               JOSTLE_MEMBER(jostle_box_cast_hit, normal),
               JOSTLE_MEMBER(jostle_box_cast_hit, fraction)});
    addStruct(out, "move_hit", sizeof(jostle_move_hit),
              {JOSTLE_MEMBER(jostle_move_hit, body), JOSTLE_MEMBER(jostle_move_hit, normal)});
    addStruct(out, "move_collision", sizeof(jostle_move_collision),
              {JOSTLE_MEMBER(jostle_move_collision, other),
               JOSTLE_MEMBER(jostle_move_collision, response),
               JOSTLE_MEMBER(jostle_move_collision, normal),
               JOSTLE_MEMBER(jostle_move_collision, touch),
               JOSTLE_MEMBER(jostle_move_collision, time),
               JOSTLE_MEMBER(jostle_move_collision, other_centre),
               JOSTLE_MEMBER(jostle_move_collision, other_half)});
    addStruct(out, "move_result", sizeof(jostle_move_result),
              {JOSTLE_MEMBER(jostle_move_result, centre),
               JOSTLE_MEMBER(jostle_move_result, collisions),
               JOSTLE_MEMBER(jostle_move_result, count)});
    addStruct(out, "classic_options", sizeof(jostle_classic_options),
              {JOSTLE_MEMBER(jostle_classic_options, mass),
               JOSTLE_MEMBER(jostle_classic_options, coulomb),
               JOSTLE_MEMBER(jostle_classic_options, ccd)});
    addStruct(out, "physical_options", sizeof(jostle_physical_options),
              {JOSTLE_MEMBER(jostle_physical_options, velocity_iterations),
               JOSTLE_MEMBER(jostle_physical_options, position_iterations),
               JOSTLE_MEMBER(jostle_physical_options, slop),
               JOSTLE_MEMBER(jostle_physical_options, correction),
               JOSTLE_MEMBER(jostle_physical_options, restitution_threshold),
               JOSTLE_MEMBER(jostle_physical_options, friction_mix),
               JOSTLE_MEMBER(jostle_physical_options, max_contacts_per_body)});
    addStruct(out, "debug_draw_options", sizeof(jostle_debug_draw_options),
              {JOSTLE_MEMBER(jostle_debug_draw_options, shapes),
               JOSTLE_MEMBER(jostle_debug_draw_options, contacts),
               JOSTLE_MEMBER(jostle_debug_draw_options, velocities),
               JOSTLE_MEMBER(jostle_debug_draw_options, touching),
               JOSTLE_MEMBER(jostle_debug_draw_options, grid),
               JOSTLE_MEMBER(jostle_debug_draw_options, mark_length),
               JOSTLE_MEMBER(jostle_debug_draw_options, view_min),
               JOSTLE_MEMBER(jostle_debug_draw_options, view_max),
               JOSTLE_MEMBER(jostle_debug_draw_options, palette)});
    addStruct(out, "debug_palette", sizeof(jostle_debug_palette),
              {JOSTLE_MEMBER(jostle_debug_palette, static_body),
               JOSTLE_MEMBER(jostle_debug_palette, kinematic_body),
               JOSTLE_MEMBER(jostle_debug_palette, dynamic_body),
               JOSTLE_MEMBER(jostle_debug_palette, sleeping_percent),
               JOSTLE_MEMBER(jostle_debug_palette, outline_percent),
               JOSTLE_MEMBER(jostle_debug_palette, bullet_outline),
               JOSTLE_MEMBER(jostle_debug_palette, one_way_face),
               JOSTLE_MEMBER(jostle_debug_palette, contact),
               JOSTLE_MEMBER(jostle_debug_palette, velocity),
               JOSTLE_MEMBER(jostle_debug_palette, touching),
               JOSTLE_MEMBER(jostle_debug_palette, grid_cell),
               JOSTLE_MEMBER(jostle_debug_palette, grid_box)});
    // The profile's stages, by the names StepProfile gives them, each a float in order.
    out += ",\"profile\":[";
    for (const jostle::StepProfileField& field : jostle::kStepProfileFields)
        out += std::string(&field == jostle::kStepProfileFields ? "\"" : ",\"") + field.name + '"';
    out += "]}";
    return out;
}

#undef JOSTLE_MEMBER

// The JavaScript side of the callbacks, declared with EM_JS because emscripten checks every
// import against the JavaScript it knows. A standalone module keeps no JavaScript: the
// imports are given by the package's loader (package/src/module.js, `env`), and these
// bodies only say what it gives.
EM_JS(int, jostle_js_pre_solve, (jostle_collision * collision, void* context),
      { return Module.jostlePreSolve(collision, context) ? 1 : 0; });
EM_JS(int, jostle_js_move_filter, (const jostle_body_id* other, void* context),
      { return Module.jostleMoveFilter(other, context); });

bool preSolve(jostle_collision* collision, void* context) {
    return jostle_js_pre_solve(collision, context) != 0;
}

jostle_response moveFilter(jostle_body_id other, void* context) {
    return static_cast<jostle_response>(jostle_js_move_filter(&other, context));
}

// The calls of the last jostle_web_debug_draw, kept by the C renderer's functions. The
// package reads each Command as nine 32-bit words: values[0..5] (floats), fill and outline
// (bytes r, g, b, a), kind (0 line, 1 box, 2 rounded box, 3 triangle, 4 point).
using Command = jostle::DebugDrawList::Command;
static_assert(sizeof(Command) == 36 && offsetof(Command, fill) == 24 &&
              offsetof(Command, outline) == 28 && offsetof(Command, kind) == 32);
jostle::DebugDrawList drawn;

jostle::Vec2 vec(jostle_vec2 v) {
    return {v.x, v.y};
}
jostle::Colour colour(jostle_colour c) {
    return {c.r, c.g, c.b, c.a};
}

void keepLine(jostle_vec2 from, jostle_vec2 to, jostle_colour c, void*) {
    drawn.line(vec(from), vec(to), colour(c));
}
void keepBox(jostle_vec2 centre, jostle_vec2 half, jostle_colour fill, jostle_colour outline,
             void*) {
    drawn.box(vec(centre), vec(half), colour(fill), colour(outline));
}
void keepRoundedBox(jostle_vec2 centre, jostle_vec2 half, float radius, jostle_colour fill,
                    jostle_colour outline, void*) {
    drawn.roundedBox(vec(centre), vec(half), radius, colour(fill), colour(outline));
}
void keepTriangle(jostle_vec2 a, jostle_vec2 b, jostle_vec2 c, jostle_colour fill,
                  jostle_colour outline, void*) {
    drawn.triangle(vec(a), vec(b), vec(c), colour(fill), colour(outline));
}
void keepPoint(jostle_vec2 at, float size, jostle_colour c, void*) {
    drawn.point(vec(at), size, colour(c));
}

} // namespace

extern "C" {

/// jostle_world_debug_draw into a list of Command that the package walks, calling the
/// game's functions: *count of them at the address returned (NULL on misuse). `functions`
/// says which the game has beside line (1 box, 2 rounded box, 4 triangle, 8 point): the
/// others come as lines.
EMSCRIPTEN_KEEPALIVE const Command* jostle_web_debug_draw(const jostle_world* world,
                                                          const jostle_debug_draw_options* options,
                                                          int functions, int* count) {
    drawn.clear();
    const jostle_debug_draw draw{keepLine,
                                 (functions & 1) != 0 ? keepBox : nullptr,
                                 (functions & 2) != 0 ? keepRoundedBox : nullptr,
                                 (functions & 4) != 0 ? keepTriangle : nullptr,
                                 (functions & 8) != 0 ? keepPoint : nullptr,
                                 nullptr};
    *count = 0;
    if (!jostle_world_debug_draw(world, &draw, options))
        return nullptr;
    const auto commands = drawn.commands();
    *count = static_cast<int>(commands.size());
    // Never NULL when it worked, nothing drawn or not.
    return commands.empty() ? reinterpret_cast<const Command*>(&drawn) : commands.data();
}

/// jostle.h's structs as JSON: {"contact_event": {"size": 44, "a": 0, "normal": 24, ...},
/// ..., "profile": [stage names]}, read once by the package when it loads.
EMSCRIPTEN_KEEPALIVE const char* jostle_web_layout() {
    static const std::string layout = layoutJson();
    return layout.c_str();
}

/// jostle_world_set_pre_solve with the package's callback, which calls the function the
/// game gave for the world `context` names; or none.
EMSCRIPTEN_KEEPALIVE bool jostle_web_set_pre_solve(jostle_world* world, bool enabled) {
    return jostle_world_set_pre_solve(world, enabled ? preSolve : nullptr, world);
}

/// jostle_body_move with the package's filter, which calls the game's function; none
/// when `filtered` is false (the default responses).
/// Every body's shape, in the order of jostle_world_bodies, six floats each into
/// out[0 .. 6 * capacity): half width, half height, radius, slope x, slope y, and flags
/// (type: 0 static, 1 kinematic, 2 dynamic; + 4 sensor, + 8 segment, + 16 awake); returns
/// how many bodies there are (the buffer rule). A body's shape is fixed when it is made:
/// read this when bodies come and go, not every frame (it costs a definition a body).
EMSCRIPTEN_KEEPALIVE int jostle_web_read_shapes(const jostle_world* world, float* out,
                                                int capacity) {
    if (world == nullptr || capacity < 0 || (capacity > 0 && out == nullptr))
        return -1;
    const int count = jostle_world_body_count(world);
    std::vector<jostle_body_id> ids(static_cast<std::size_t>(count));
    jostle_world_bodies(world, ids.data(), count);
    for (int i = 0; i < count && i < capacity; ++i) {
        const jostle_body_def def = jostle_body_get_def(world, ids[static_cast<std::size_t>(i)]);
        const int flags = static_cast<int>(def.type) + (def.sensor ? 4 : 0) +
                          (def.segment ? 8 : 0) +
                          (jostle_body_is_awake(world, ids[static_cast<std::size_t>(i)]) ? 16 : 0);
        float* shape = out + 6 * i;
        shape[0] = def.hw;
        shape[1] = def.hh;
        shape[2] = def.radius;
        shape[3] = def.slope.x;
        shape[4] = def.slope.y;
        shape[5] = static_cast<float>(flags);
    }
    return count;
}

EMSCRIPTEN_KEEPALIVE bool jostle_web_body_move(jostle_world* world, const jostle_body_id* body,
                                               const jostle_vec2* delta, bool filtered,
                                               jostle_move_result* result) {
    return jostle_body_move(world, *body, *delta, filtered ? moveFilter : nullptr, world, result);
}

} // extern "C"
