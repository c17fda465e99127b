// The one place where the C API's types and the C++ API's are converted, each way, and
// the copies of results into C arrays.
#pragma once

#include "body_properties.hpp"
#include "jostle/jostle.h"
#include "jostle/query.hpp"
#include "jostle/tilemap.hpp"
#include "jostle/world.hpp"
#include "misuse.hpp"
#include "tile_chars.hpp"
#include "world_options.hpp"

#include <algorithm>
#include <cstddef>
#include <optional>
#include <span>
#include <type_traits>
#include <vector>

namespace jostle::c_api {

// --- Conversions --------------------------------------------------------------------------

inline Vec2 toCpp(jostle_vec2 v) {
    return {v.x, v.y};
}
inline jostle_vec2 toC(Vec2 v) {
    return {v.x, v.y};
}

inline BodyId toCpp(jostle_body_id id) {
    return {id.index, id.generation, id.world};
}
inline jostle_body_id toC(BodyId id) {
    return {id.index, id.generation, id.world};
}

inline TileMapId toCpp(jostle_tile_map_id id) {
    return {id.index, id.generation, id.world};
}
inline jostle_tile_map_id toC(TileMapId id) {
    return {id.index, id.generation, id.world};
}

// Enums from C may hold any int: each is checked before it becomes a C++ enum.
inline BodyType toCpp(jostle_body_type type) {
    switch (type) {
    case JOSTLE_BODY_STATIC:
        return BodyType::Static;
    case JOSTLE_BODY_KINEMATIC:
        return BodyType::Kinematic;
    case JOSTLE_BODY_DYNAMIC:
        return BodyType::Dynamic;
    }
    misuse("type must be JOSTLE_BODY_STATIC, JOSTLE_BODY_KINEMATIC or JOSTLE_BODY_DYNAMIC, got " +
           std::to_string(static_cast<int>(type)));
}
inline jostle_body_type toC(BodyType type) {
    switch (type) {
    case BodyType::Static:
        return JOSTLE_BODY_STATIC;
    case BodyType::Kinematic:
        return JOSTLE_BODY_KINEMATIC;
    case BodyType::Dynamic:
        return JOSTLE_BODY_DYNAMIC;
    }
    return JOSTLE_BODY_DYNAMIC; // not reached: the world holds only valid types
}

inline Solver toCpp(jostle_solver solver) {
    switch (solver) {
    case JOSTLE_SOLVER_CLASSIC:
        return Solver::Classic;
    case JOSTLE_SOLVER_PHYSICAL:
        return Solver::Physical;
    }
    misuse("solver must be JOSTLE_SOLVER_CLASSIC or JOSTLE_SOLVER_PHYSICAL, got " +
           std::to_string(static_cast<int>(solver)));
}
inline jostle_solver toC(Solver solver) {
    return solver == Solver::Classic ? JOSTLE_SOLVER_CLASSIC : JOSTLE_SOLVER_PHYSICAL;
}

inline FrictionMix toCpp(jostle_friction_mix mix) {
    switch (mix) {
    case JOSTLE_FRICTION_MIX_MIN:
        return FrictionMix::Min;
    case JOSTLE_FRICTION_MIX_GEOMETRIC_MEAN:
        return FrictionMix::GeometricMean;
    }
    misuse("friction_mix must be JOSTLE_FRICTION_MIX_MIN or JOSTLE_FRICTION_MIX_GEOMETRIC_MEAN, "
           "got " +
           std::to_string(static_cast<int>(mix)));
}
inline jostle_friction_mix toC(FrictionMix mix) {
    return mix == FrictionMix::Min ? JOSTLE_FRICTION_MIX_MIN : JOSTLE_FRICTION_MIX_GEOMETRIC_MEAN;
}

// Numbers, flags, bits and pointers are the same in C and C++.
template <class T>
concept SameInC = std::is_same_v<T, float> || std::is_same_v<T, int> || std::is_same_v<T, bool> ||
    std::is_same_v<T, std::uint32_t> || std::is_same_v<T, void*>;
template <SameInC T> T toCpp(T value) {
    return value;
}
template <SameInC T> T toC(T value) {
    return value;
}

/// Copies each field of a definition's table (body_properties.hpp, world_options.hpp) from
/// the C struct into the C++ definition (an enum is checked on the way), and back.
template <class Def, class CDef, class F, std::size_t N>
void copyFromC(const CDef& from, Def& to, const F (&fields)[N]) {
    for (const F& field : fields)
        field.visitWithC([&](auto member, auto cMember) { to.*member = toCpp(from.*cMember); });
}
template <class Def, class CDef, class F, std::size_t N>
void copyToC(const Def& from, CDef& to, const F (&fields)[N]) {
    for (const F& field : fields)
        field.visitWithC([&](auto member, auto cMember) { to.*cMember = toC(from.*member); });
}

/// A definition made from its C struct by its table, and the C struct from the definition.
template <class Def, class CDef, class F, std::size_t N>
Def fromC(const CDef& from, const F (&fields)[N], Def to = {}) {
    copyFromC(from, to, fields);
    return to;
}
template <class CDef, class Def, class F, std::size_t N>
CDef inC(const Def& from, const F (&fields)[N], CDef to = {}) {
    copyToC(from, to, fields);
    return to;
}

inline ClassicOptions toCpp(const jostle_classic_options& o) {
    return fromC<ClassicOptions>(o, properties::kClassicFields);
}
inline jostle_classic_options toC(const ClassicOptions& o) {
    return inC<jostle_classic_options>(o, properties::kClassicFields);
}

inline PhysicalOptions toCpp(const jostle_physical_options& o) {
    return fromC<PhysicalOptions>(o, properties::kPhysicalFields);
}
inline jostle_physical_options toC(const PhysicalOptions& o) {
    return inC<jostle_physical_options>(o, properties::kPhysicalFields);
}

static_assert(std::is_same_v<jostle_task_fn, TaskFn> &&
              std::is_same_v<jostle_enqueue_task_fn, EnqueueTaskFn> &&
              std::is_same_v<jostle_finish_task_fn, FinishTaskFn>);
// The game's job system is the same functions in C and C++; its settings are a table's.
inline TaskSystem toCpp(const jostle_task_system& t) {
    return fromC(t, properties::kTaskFields,
                 TaskSystem{.enqueueTask = t.enqueue_task,
                            .finishTask = t.finish_task,
                            .userContext = t.user_context});
}
inline jostle_task_system toC(const TaskSystem& t) {
    return inC(t, properties::kTaskFields,
               jostle_task_system{.enqueue_task = t.enqueueTask,
                                  .finish_task = t.finishTask,
                                  .user_context = t.userContext});
}

inline WorldDef toCpp(const jostle_world_def& d) {
    requireCookie(d.internal_cookie, "def", "jostle_default_world_def");
    WorldDef def = fromC<WorldDef>(d, properties::kWorldFields);
    def.classic = toCpp(d.classic);
    def.physical = toCpp(d.physical);
    def.tasks = toCpp(d.tasks);
    return def;
}
inline jostle_world_def toC(const WorldDef& d) {
    return inC(d, properties::kWorldFields,
               jostle_world_def{.classic = toC(d.classic),
                                .physical = toC(d.physical),
                                .tasks = toC(d.tasks),
                                .internal_cookie = kCookie});
}

inline BodyDef toCpp(const jostle_body_def& d) {
    requireCookie(d.internal_cookie, "def", "jostle_default_body_def");
    return fromC<BodyDef>(d, properties::kBodyFields);
}
inline jostle_body_def toC(const BodyDef& d) {
    return inC(d, properties::kBodyFields, jostle_body_def{.internal_cookie = kCookie});
}

/// NULL is the default filter.
inline QueryFilter toCpp(const jostle_query_filter* f) {
    if (f == nullptr)
        return {};
    requireCookie(f->internal_cookie, "filter", "jostle_default_query_filter");
    return {.mask = f->mask,
            .category = f->category,
            .includeSensors = f->include_sensors,
            .ignore = toCpp(f->ignore)};
}

/// A cell of jostle_tile_map_def::cells as a character of TileMapDef::rows: 0 and '.' are
/// empty, a ramp's character is that ramp, and any other byte is solid.
inline char tileOfCell(unsigned char cell) {
    const auto tile = static_cast<char>(cell);
    if (cell == 0 || tile == '.')
        return '.';
    return rampTile(tile) ? tile : '#';
}

/// The cells array becomes the C++ definition's rows.
inline TileMapDef toCpp(const jostle_tile_map_def& d) {
    requireCookie(d.internal_cookie, "def", "jostle_default_tile_map_def");
    if (d.columns < 1)
        misuse("def.columns must be >= 1, got " + std::to_string(d.columns));
    if (d.rows < 1)
        misuse("def.rows must be >= 1, got " + std::to_string(d.rows));
    if (d.cells == nullptr)
        misuse("def.cells is NULL");
    TileMapDef def;
    copyFromC(d, def, properties::kTileMapFields);
    const auto columns = static_cast<std::size_t>(d.columns);
    def.rows.resize(static_cast<std::size_t>(d.rows), std::string(columns, '.'));
    for (std::size_t row = 0; row < def.rows.size(); ++row)
        for (std::size_t column = 0; column < columns; ++column)
            def.rows[row][column] = tileOfCell(d.cells[row * columns + column]);
    return def;
}

inline jostle_contact_event toC(const ContactEvent& e) {
    return {toC(e.a), toC(e.b), toC(e.normal), e.approachSpeed, toC(e.point)};
}
inline jostle_contact_info toC(const ContactInfo& c) {
    return {toC(c.other), toC(c.normal), toC(c.point), c.impulse};
}
inline jostle_ground toC(const Ground& g) {
    return {toC(g.body), toC(g.normal), toC(g.velocity)};
}
inline jostle_sensor_event toC(const SensorEvent& e) {
    return {toC(e.sensor), toC(e.visitor)};
}
inline jostle_crush_event toC(const CrushEvent& e) {
    return {toC(e.body), toC(e.by), toC(e.against)};
}
inline jostle_touching toC(const Touching& t) {
    return {t.floor, t.ceiling, t.wallLeft, t.wallRight};
}
inline jostle_collision toC(const Collision& c) {
    return {toC(c.a), toC(c.b), toC(c.normal), c.depth, c.bounce, c.friction};
}
inline jostle_ray_hit toC(const RayHit& h) {
    return {toC(h.body), toC(h.point), toC(h.normal), h.fraction};
}
inline jostle_box_cast_hit toC(const BoxCastHit& h) {
    return {toC(h.body), toC(h.centre), toC(h.normal), h.fraction};
}
inline jostle_move_hit toC(const MoveHit& h) {
    return {toC(h.body), toC(h.normal)};
}

inline Response toCpp(jostle_response response) {
    switch (response) {
    case JOSTLE_RESPONSE_SLIDE:
        return Response::Slide;
    case JOSTLE_RESPONSE_TOUCH:
        return Response::Touch;
    case JOSTLE_RESPONSE_CROSS:
        return Response::Cross;
    case JOSTLE_RESPONSE_BOUNCE:
        return Response::Bounce;
    case JOSTLE_RESPONSE_IGNORE:
        return Response::Ignore;
    }
    misuse("the filter's response must be JOSTLE_RESPONSE_SLIDE, _TOUCH, _CROSS, _BOUNCE or "
           "_IGNORE, got " +
           std::to_string(static_cast<int>(response)));
}
inline jostle_response toC(Response response) {
    switch (response) {
    case Response::Slide:
        return JOSTLE_RESPONSE_SLIDE;
    case Response::Touch:
        return JOSTLE_RESPONSE_TOUCH;
    case Response::Cross:
        return JOSTLE_RESPONSE_CROSS;
    case Response::Bounce:
        return JOSTLE_RESPONSE_BOUNCE;
    case Response::Ignore:
        return JOSTLE_RESPONSE_IGNORE;
    }
    return JOSTLE_RESPONSE_SLIDE; // not reached: move() reports only these
}
inline jostle_move_collision toC(const MoveCollision& c) {
    return {toC(c.other), toC(c.response),    toC(c.normal),   toC(c.touch),
            c.time,       toC(c.otherCentre), toC(c.otherHalf)};
}

// --- Results ------------------------------------------------------------------------------

/// Copies as many of `items` as fit, converted, and returns how many there are.
template <class From, class To> int copyOut(std::span<const From> items, To* out, int capacity) {
    const std::size_t fit = std::min(items.size(), static_cast<std::size_t>(capacity));
    for (std::size_t i = 0; i < fit; ++i)
        out[i] = toC(items[i]);
    return countOf(items.size());
}

/// `items` in C layout, in `to` (whose memory is kept from one call to the next).
template <class From, class To> void convert(std::span<const From> items, std::vector<To>& to) {
    to.clear();
    to.reserve(items.size());
    for (const From& item : items)
        to.push_back(toC(item));
}

/// An answer that may be none: true and `out` set if there is one, false and `out`
/// untouched if not.
template <class From, class To> bool answer(const std::optional<From>& found, To& out) {
    if (found)
        out = toC(*found);
    return found.has_value();
}

/// The memory of readEach, kept from one read to the next; one per thread, as reads may
/// run on several at once.
inline std::vector<Vec2>& readScratch() {
    thread_local std::vector<Vec2> scratch;
    return scratch;
}

/// The reads of a vector per body (World::readPositions and the like): `read` fills a span
/// of as many as fit from the first body on; they are copied into out, converted, and the
/// number of bodies is returned (the buffer rule).
template <class Read>
int readEach(const World& world, jostle_vec2* out, int capacity, Read&& read) {
    checkBuffer(out, capacity);
    std::vector<Vec2>& scratch = readScratch();
    scratch.resize(std::min(world.bodyCount(), static_cast<std::size_t>(capacity)));
    read(std::span<Vec2>(scratch));
    copyOut(std::span<const Vec2>(scratch), out, capacity);
    return countOf(world.bodyCount());
}

} // namespace jostle::c_api
