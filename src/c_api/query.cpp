// The C API's queries: results copied into the caller's buffers.
#include "c_api.hpp"

using namespace jostle;
using namespace jostle::c_api;

namespace {

// The C++ queries fill vectors; these keep their memory from one query to the next. One
// set per thread, as queries may run on several threads at once.
thread_local std::vector<BodyId> foundBodies;
thread_local std::vector<RayHit> foundHits;

/// The point, box and rect queries: `query` fills foundBodies from the world.
template <class Query>
int findBodies(const char* function, const jostle_world* world, jostle_body_id* out, int capacity,
               Query&& query) {
    return guard(function, 0, [&] {
        const World& w = worldOf(world).world;
        checkBuffer(out, capacity);
        query(w);
        return copyOut(std::span<const BodyId>(foundBodies), out, capacity);
    });
}

/// jostle_rounded_box_cast under the name of the function the caller called.
bool roundedBoxCast(const char* function, const jostle_world* world, jostle_vec2 centre,
                    jostle_vec2 half, float radius, jostle_vec2 translation,
                    const jostle_query_filter* filter, jostle_box_cast_hit* hit) {
    return guard(function, false, [&] {
        const World& w = worldOf(world).world;
        jostle_box_cast_hit& result = required(hit, "hit");
        return answer(
            boxCast(w, toCpp(centre), toCpp(half), radius, toCpp(translation), toCpp(filter)),
            result);
    });
}

/// jostle_rounded_move_and_slide under the name of the function the caller called.
int roundedMoveAndSlide(const char* function, const jostle_world* world, jostle_vec2 centre,
                        jostle_vec2 half, float radius, jostle_vec2 translation,
                        const jostle_query_filter* filter, jostle_vec2* new_centre,
                        jostle_move_hit* hits, int capacity) {
    // On misuse the box stays where it was.
    if (new_centre != nullptr)
        *new_centre = centre;
    return guard(function, 0, [&] {
        const World& w = worldOf(world).world;
        jostle_vec2& end = required(new_centre, "new_centre");
        checkBuffer(hits, capacity);
        const MoveResult moved =
            moveAndSlide(w, toCpp(centre), toCpp(half), radius, toCpp(translation), toCpp(filter));
        end = toC(moved.centre);
        return copyOut(std::span<const MoveHit>(moved.hits), hits, capacity);
    });
}

} // namespace

extern "C" {

jostle_query_filter jostle_default_query_filter(void) {
    const QueryFilter defaults;
    jostle_query_filter f{};
    f.mask = defaults.mask;
    f.category = defaults.category;
    f.include_sensors = defaults.includeSensors;
    f.ignore = toC(defaults.ignore);
    f.internal_cookie = kCookie;
    return f;
}

int jostle_query_point(const jostle_world* world, jostle_vec2 point,
                       const jostle_query_filter* filter, jostle_body_id* out, int capacity) {
    return findBodies(__func__, world, out, capacity, [&](const World& w) {
        queryPoint(w, toCpp(point), toCpp(filter), foundBodies);
    });
}

int jostle_query_box(const jostle_world* world, jostle_vec2 centre, jostle_vec2 half,
                     const jostle_query_filter* filter, jostle_body_id* out, int capacity) {
    return findBodies(__func__, world, out, capacity, [&](const World& w) {
        queryBox(w, toCpp(centre), toCpp(half), toCpp(filter), foundBodies);
    });
}

int jostle_query_rect(const jostle_world* world, jostle_vec2 min, jostle_vec2 max,
                      const jostle_query_filter* filter, jostle_body_id* out, int capacity) {
    return findBodies(__func__, world, out, capacity, [&](const World& w) {
        queryRect(w, toCpp(min), toCpp(max), toCpp(filter), foundBodies);
    });
}

bool jostle_ray_cast(const jostle_world* world, jostle_vec2 from, jostle_vec2 to,
                     const jostle_query_filter* filter, jostle_ray_hit* hit) {
    return guard(__func__, false, [&] {
        const World& w = worldOf(world).world;
        jostle_ray_hit& result = required(hit, "hit");
        return answer(rayCast(w, toCpp(from), toCpp(to), toCpp(filter)), result);
    });
}

int jostle_ray_cast_all(const jostle_world* world, jostle_vec2 from, jostle_vec2 to,
                        const jostle_query_filter* filter, jostle_ray_hit* out, int capacity) {
    return guard(__func__, 0, [&] {
        const World& w = worldOf(world).world;
        checkBuffer(out, capacity);
        rayCastAll(w, toCpp(from), toCpp(to), toCpp(filter), foundHits);
        return copyOut(std::span<const RayHit>(foundHits), out, capacity);
    });
}

bool jostle_box_cast(const jostle_world* world, jostle_vec2 centre, jostle_vec2 half,
                     jostle_vec2 translation, const jostle_query_filter* filter,
                     jostle_box_cast_hit* hit) {
    return roundedBoxCast(__func__, world, centre, half, 0.0f, translation, filter, hit);
}

bool jostle_rounded_box_cast(const jostle_world* world, jostle_vec2 centre, jostle_vec2 half,
                             float radius, jostle_vec2 translation,
                             const jostle_query_filter* filter, jostle_box_cast_hit* hit) {
    return roundedBoxCast(__func__, world, centre, half, radius, translation, filter, hit);
}

bool jostle_circle_cast(const jostle_world* world, jostle_vec2 centre, float radius,
                        jostle_vec2 translation, const jostle_query_filter* filter,
                        jostle_box_cast_hit* hit) {
    return roundedBoxCast(__func__, world, centre, {radius, radius}, radius, translation, filter,
                          hit);
}

int jostle_move_and_slide(const jostle_world* world, jostle_vec2 centre, jostle_vec2 half,
                          jostle_vec2 translation, const jostle_query_filter* filter,
                          jostle_vec2* new_centre, jostle_move_hit* hits, int capacity) {
    return roundedMoveAndSlide(__func__, world, centre, half, 0.0f, translation, filter, new_centre,
                               hits, capacity);
}

int jostle_rounded_move_and_slide(const jostle_world* world, jostle_vec2 centre, jostle_vec2 half,
                                  float radius, jostle_vec2 translation,
                                  const jostle_query_filter* filter, jostle_vec2* new_centre,
                                  jostle_move_hit* hits, int capacity) {
    return roundedMoveAndSlide(__func__, world, centre, half, radius, translation, filter,
                               new_centre, hits, capacity);
}

} // extern "C"
