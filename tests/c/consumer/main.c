/* Drops a box on a floor through the installed package's C API; exits 0 if it landed. */
#include <jostle/jostle.h>

#include <stdio.h>
#include <string.h>

int main(void) {
    jostle_world_def def = jostle_default_world_def();
    def.gravity.y = 800;
    jostle_world* world = jostle_world_create(&def);

    jostle_body_def floor = jostle_default_body_def();
    floor.type = JOSTLE_BODY_STATIC;
    floor.y = 100;
    floor.hw = 100;
    floor.hh = 10;
    jostle_body_create(world, &floor);

    jostle_body_def crate = jostle_default_body_def();
    crate.hw = 10;
    crate.hh = 10;
    jostle_body_id box = jostle_body_create(world, &crate);

    for (int i = 0; i < 120; ++i)
        jostle_world_step(world, 1.0f / 60.0f);
    /* The floor's top is at y = 90, so the resting box's centre is at 80. */
    float y = jostle_body_get_position(world, box).y;
    printf("box at y = %g, errors: \"%s\"; library %s, headers %s\n", (double)y,
           jostle_last_error(), jostle_version(), JOSTLE_VERSION_STRING);
    jostle_world_destroy(world);
    const int sameVersion = strcmp(jostle_version(), JOSTLE_VERSION_STRING) == 0;
    return (y > 79.0f && y < 81.0f && jostle_last_error()[0] == '\0' && sameVersion) ? 0 : 1;
}
