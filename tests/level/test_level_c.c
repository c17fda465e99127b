/* The C face of levels (include/jostle/level.h) from a program compiled as C11: the
 * example level (examples/levels/, docs/levels.md) loaded from Tiled's and LDtk's files,
 * its world made, its objects read by name with their bodies and properties, and the
 * refusals with their messages. */
#include "jostle/level.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

static int failures = 0;

#define CHECK(cond, what)                                                                          \
    do {                                                                                           \
        if (!(cond)) {                                                                             \
            printf("FAIL %s:%d: %s\n", __FILE__, __LINE__, what);                                  \
            ++failures;                                                                            \
        }                                                                                          \
    } while (0)

/* The example level, from either file: a spawn point at (40, 200); a kinematic lift whose
 * property top is 104; two crates that fall onto the floor (top at y 224) and rest
 * stacked at 216 and 200; three coins. */
static void example(jostle_level* level) {
    CHECK(level != NULL, jostle_last_error());
    if (level == NULL)
        return;
    jostle_world* world = jostle_level_create_world(level, NULL);
    CHECK(world != NULL, jostle_last_error());
    CHECK(jostle_level_object_count(level) == 7, "7 objects: spawn, lift, 2 crates, 3 coins");

    jostle_level_object spawn;
    CHECK(jostle_level_get_object(level, jostle_level_find(level, "spawn"), &spawn), "the spawn point");
    CHECK(spawn.centre.x == 40 && spawn.centre.y == 200 && jostle_body_id_is_null(spawn.body),
          "the spawn point is at (40, 200), no body");

    const int lift = jostle_level_find(level, "lift");
    jostle_level_object o;
    CHECK(jostle_level_get_object(level, lift, &o) && o.body_count == 1, "the lift has a body");
    CHECK(jostle_body_get_type(world, o.body) == JOSTLE_BODY_KINEMATIC, "the lift is kinematic");
    double top = 0;
    CHECK(jostle_level_get_property(level, lift, "top", NULL, &top, NULL) == JOSTLE_PROPERTY_NUMBER && top == 104,
          "the lift's property top is 104");
    CHECK(jostle_level_get_property(level, lift, "nothing", NULL, NULL, NULL) == JOSTLE_PROPERTY_NONE,
          "a property it has not");

    for (int i = 0; i < 120; ++i)
        jostle_world_step(world, 1.0f / 60.0f);
    float lowest = 0, highest = 1e9f;
    for (int i = 0; i < jostle_level_object_count(level); ++i) {
        CHECK(jostle_level_get_object(level, i, &o), "every object");
        if (strcmp(o.name, "crate") != 0)
            continue;
        const float y = jostle_body_get_position(world, jostle_level_get_body(level, i, 0)).y;
        lowest = y > lowest ? y : lowest;
        highest = y < highest ? y : highest;
    }
    CHECK(fabsf(lowest - 216) < 0.05f && fabsf(highest - 200) < 0.05f, "the crates rest stacked at 216 and 200");
    jostle_world_destroy(world);
    jostle_level_destroy(level);
}

int main(int argc, char** argv) {
    if (argc != 2) {
        printf("usage: test_level_c <examples/levels>\n");
        return 2;
    }
    char path[4096];
    snprintf(path, sizeof path, "%s/level.tmx", argv[1]);
    example(jostle_level_load_tiled(path));
    snprintf(path, sizeof path, "%s/level.ldtk", argv[1]);
    example(jostle_level_load_ldtk(path, "Level_0", NULL, 0));

    /* Refusals: NULL, the message naming the function and the file. */
    CHECK(jostle_level_load_tiled("nowhere.tmj") == NULL, "a file that is not there");
    CHECK(strcmp(jostle_last_error(), "jostle_level_load_tiled: nowhere.tmj: cannot read the file") == 0,
          jostle_last_error());
    const jostle_intgrid_kind lava = {1, "lava"};
    CHECK(jostle_level_load_ldtk(path, "Level_0", &lava, 1) == NULL, "a kind that is none");
    CHECK(strstr(jostle_last_error(), "IntGrid value 1: the kinds table: expected") != NULL, jostle_last_error());
    CHECK(jostle_level_object_count(NULL) == 0 && strstr(jostle_last_error(), "level") != NULL, "a NULL level");
    jostle_level_destroy(NULL);
    printf(failures == 0 ? "all passed\n" : "%d failed\n", failures);
    return failures == 0 ? 0 : 1;
}
