// A C++ exception thrown from a move filter, which a program in C++ (or a language whose
// foreign-function calls can raise) may hand to the C API, is caught and reported by
// jostle_body_move: it never reaches the caller, nothing moves, and the world stays
// usable (the filter's refusals end with the move).
#include <jostle/jostle.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

#define CHECK(cond)                                                                                \
    do {                                                                                           \
        if (!(cond)) {                                                                             \
            std::fprintf(stderr, "%s:%d: CHECK(%s) failed\n  last error: \"%s\"\n", __FILE__,      \
                         __LINE__, #cond, jostle_last_error());                                    \
            std::exit(1);                                                                          \
        }                                                                                          \
    } while (0)

namespace {

jostle_response throwing(jostle_body_id, void*) {
    throw std::runtime_error("the filter threw");
}

jostle_body_id box(jostle_world* world, float x) {
    jostle_body_def def = jostle_default_body_def();
    def.type = JOSTLE_BODY_KINEMATIC;
    def.x = x;
    def.hw = 1;
    def.hh = 1;
    return jostle_body_create(world, &def);
}

} // namespace

int main() {
    jostle_world_def def = jostle_default_world_def();
    jostle_world* world = jostle_world_create(&def);
    const jostle_body_id item = box(world, 0);
    box(world, 10); // in the way

    jostle_move_result result;
    bool returned = false, crossed = false;
    try {
        returned = jostle_body_move(world, item, {20, 0}, throwing, nullptr, &result);
    } catch (...) {
        crossed = true; // an exception crossed jostle_body_move
    }
    CHECK(!crossed);
    CHECK(!returned);
    CHECK(std::strcmp(jostle_last_error(), "jostle_body_move: the filter threw") == 0);
    CHECK(result.centre.x == 0 && result.count == 0);
    CHECK(jostle_body_get_position(world, item).x == 0);
    jostle_clear_error();

    // The world is not left refusing changes.
    CHECK(jostle_body_move(world, item, {20, 0}, nullptr, nullptr, &result));
    CHECK(result.centre.x == 8 && result.count == 1);
    CHECK(jostle_world_step(world, 1.0f / 60.0f));
    CHECK(jostle_world_destroy(world));
    CHECK(jostle_last_error()[0] == '\0');
    std::printf("test_c_api_exceptions: all checks passed\n");
    return 0;
}
