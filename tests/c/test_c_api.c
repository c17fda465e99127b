// The C API from a program compiled as C11: worlds, bodies, events, the pre-solve
// callback, queries, tile maps and the fixed step, each checked against values worked
// out by hand, and every kind of misuse checked against the error contract of jostle.h.
// getrlimit and sysconf, for the test of threads that cannot start.
#define _XOPEN_SOURCE 700

#include <jostle/jostle.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <unistd.h>

#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define SANITIZED 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer)
#define SANITIZED 1
#endif
#endif

// --- Checks: print where and what, exit non-zero at the first failure --------------------

#define CHECK(cond, what)                                                                          \
    do {                                                                                           \
        if (!(cond)) {                                                                             \
            fprintf(stderr, "%s:%d: CHECK(%s) failed: %s\n  last error: \"%s\"\n", __FILE__,       \
                    __LINE__, #cond, what, jostle_last_error());                                   \
            exit(1);                                                                               \
        }                                                                                          \
    } while (0)

#define CHECK_NEAR(actual, expected, tolerance)                                                    \
    do {                                                                                           \
        const double a_ = (double)(actual), e_ = (double)(expected);                               \
        if (!(fabs(a_ - e_) <= (double)(tolerance))) {                                             \
            fprintf(stderr, "%s:%d: %s = %.9g, expected %s = %.9g within %g\n", __FILE__,          \
                    __LINE__, #actual, a_, #expected, e_, (double)(tolerance));                    \
            exit(1);                                                                               \
        }                                                                                          \
    } while (0)

/// The last error starts with the C function's name and contains `phrase`.
#define CHECK_ERROR(function, phrase)                                                              \
    do {                                                                                           \
        const char* m_ = jostle_last_error();                                                      \
        if (strncmp(m_, function ": ", strlen(function ": ")) != 0 || !strstr(m_, phrase)) {       \
            fprintf(stderr, "%s:%d: expected an error from %s about \"%s\", got \"%s\"\n",         \
                    __FILE__, __LINE__, function, phrase, m_);                                     \
            exit(1);                                                                               \
        }                                                                                          \
        jostle_clear_error();                                                                      \
    } while (0)

#define CHECK_NO_ERROR() CHECK(jostle_last_error()[0] == '\0', "no error expected")

/// The last error is exactly `message`.
#define CHECK_MESSAGE(message)                                                                     \
    do {                                                                                           \
        const char* m_ = jostle_last_error();                                                      \
        if (strcmp(m_, message) != 0) {                                                            \
            fprintf(stderr, "%s:%d: expected the error \"%s\", got \"%s\"\n", __FILE__, __LINE__,  \
                    message, m_);                                                                  \
            exit(1);                                                                               \
        }                                                                                          \
        jostle_clear_error();                                                                      \
    } while (0)

static bool same(jostle_body_id a, jostle_body_id b) {
    return jostle_body_id_equal(a, b);
}

// --- Scenes ------------------------------------------------------------------------------

static const float kDt = 1.0f / 60.0f;
static const float kG = 800.0f; // y grows downward

static jostle_world* make_world(float gravity) {
    jostle_world_def def = jostle_default_world_def();
    def.gravity.y = gravity;
    jostle_world* world = jostle_world_create(&def);
    CHECK(world != NULL, "jostle_world_create");
    return world;
}

static jostle_body_id add_box(jostle_world* world, jostle_body_type type, float x, float y,
                              float hw, float hh) {
    jostle_body_def def = jostle_default_body_def();
    def.type = type;
    def.x = x;
    def.y = y;
    def.hw = hw;
    def.hh = hh;
    jostle_body_id id = jostle_body_create(world, &def);
    CHECK(!jostle_body_id_is_null(id), "jostle_body_create");
    return id;
}

static bool at(jostle_vec2 v, float x, float y) {
    return v.x == x && v.y == y;
}

/// A character 12 x 16 at (x, y), in a world of gravity kG where nothing sleeps.
static jostle_body_id add_character(jostle_world* world, float x, float y, float wall_friction) {
    CHECK(jostle_world_set_sleeping(world, false), "no sleeping");
    jostle_body_def def = jostle_default_body_def();
    def.x = x;
    def.y = y;
    def.hw = 6;
    def.hh = 8;
    def.character = true;
    def.wall_friction = wall_friction;
    jostle_body_id id = jostle_body_create(world, &def);
    CHECK(!jostle_body_id_is_null(id), "a character");
    return id;
}

static void run(jostle_world* world, int steps) {
    for (int i = 0; i < steps; ++i)
        CHECK(jostle_world_step(world, kDt), "step");
}

// --- Defaults ----------------------------------------------------------------------------

static void test_defaults(void) {
    jostle_world_def w = jostle_default_world_def();
    CHECK(w.gravity.x == 0 && w.gravity.y == 0, "no gravity by default");
    CHECK(isinf(w.max_velocity) && w.max_velocity > 0, "no velocity clamp by default");
    CHECK(w.solver == JOSTLE_SOLVER_PHYSICAL, "the physical model by default");
    CHECK(w.sleeping, "sleeping on by default");
    CHECK(w.physical.velocity_iterations == 4 && w.physical.position_iterations == 3,
          "physical iterations");
    CHECK(w.physical.friction_mix == JOSTLE_FRICTION_MIX_MIN, "friction mix");
    CHECK(w.physical.max_contacts_per_body == 64, "contact budget");
    CHECK(!w.classic.mass && !w.classic.coulomb && !w.classic.ccd, "classic options off");

    jostle_body_def b = jostle_default_body_def();
    CHECK(b.type == JOSTLE_BODY_DYNAMIC, "dynamic by default");
    CHECK(b.hw == 0 && b.hh == 0, "no size by default");
    CHECK(b.friction == 0.5f && b.density == 1.0f && b.gravity_scale == 1.0f, "body numbers");
    CHECK(b.category == 1u && b.mask == 0xFFFFFFFFu && !b.sensor && b.user_data == NULL,
          "body filter");
    CHECK(!b.character && b.wall_friction == 0, "not a character, no wall friction");

    jostle_query_filter f = jostle_default_query_filter();
    CHECK(f.mask == 0xFFFFFFFFu && f.category == 0xFFFFFFFFu && !f.include_sensors &&
              jostle_body_id_is_null(f.ignore),
          "query filter");

    jostle_tile_map_def t = jostle_default_tile_map_def();
    CHECK(t.friction == 0.5f && t.bounce == 0 && t.mask == 0xFFFFFFFFu && t.cells == NULL,
          "tile map def");
    CHECK(jostle_last_error()[0] == '\0', "a fresh thread has no error");
}

// --- Falling and landing -----------------------------------------------------------------

/// Semi-implicit Euler: v += g dt, then y += v dt. After n steps from rest,
/// v = n g dt and y = g dt^2 (1 + 2 + ... + n) = g dt^2 n (n + 1) / 2.
static void test_free_fall(void) {
    jostle_world* world = make_world(kG);
    jostle_body_id box = add_box(world, JOSTLE_BODY_DYNAMIC, 0, 0, 10, 10);
    const int n = 30;
    for (int i = 0; i < n; ++i)
        CHECK(jostle_world_step(world, kDt), "step");
    const double dt = (double)kDt;
    const jostle_vec2 p = jostle_body_get_position(world, box);
    const jostle_vec2 v = jostle_body_get_velocity(world, box);
    CHECK_NEAR(p.x, 0.0, 0.0);
    CHECK_NEAR(p.y, kG * dt * dt * n * (n + 1) / 2, 1e-3);
    CHECK_NEAR(v.y, n * kG * dt, 1e-3);
    CHECK(jostle_world_destroy(world), "destroy");
    CHECK_NO_ERROR();
}

/// A box dropped from y = 0 onto a floor whose top is at y = 290 comes to rest at
/// 290 - hh = 280 (within the slop, 0.01 hh), after one contact begin between the two
/// whose approach speed is sqrt(2 g h), h = 280, within one step's gravity.
static void test_landing_and_contact_events(void) {
    jostle_world* world = make_world(kG);
    jostle_body_id floor = add_box(world, JOSTLE_BODY_STATIC, 0, 300, 400, 10);
    jostle_body_id box = add_box(world, JOSTLE_BODY_DYNAMIC, 0, 0, 10, 10);

    int begins = 0;
    for (int i = 0; i < 120; ++i) {
        CHECK(jostle_world_step(world, kDt), "step");
        int count = -1;
        const jostle_contact_event* events = jostle_world_contact_begins(world, &count);
        CHECK(count >= 0, "count written");
        for (int k = 0; k < count; ++k) {
            CHECK(same(events[k].a, floor), "a is the body created first");
            CHECK(same(events[k].b, box), "b is the box");
            CHECK(events[k].normal.x == 0 && events[k].normal.y == 1, "from b towards a");
            CHECK_NEAR(events[k].approach_speed, sqrt(2.0 * kG * 280.0), kG * kDt);
            // The middle of the face they share (x -10..10), on the floor's top.
            CHECK_NEAR(events[k].point.x, 0.0, 1e-4);
            CHECK_NEAR(events[k].point.y, 290.0, 0.1 + 1e-3);
            ++begins;
        }
        // The array stays put until the next step.
        int again = -1;
        CHECK(jostle_world_contact_begins(world, &again) == events && again == count,
              "the same array until the next step");
    }
    CHECK(begins == 1, "one contact begin when it lands, none while it rests");

    const jostle_vec2 p = jostle_body_get_position(world, box);
    CHECK_NEAR(p.y, 280.0, 0.1 + 1e-3);
    const jostle_touching t = jostle_body_get_touching(world, box);
    CHECK(t.floor && !t.ceiling && !t.wall_left && !t.wall_right, "touching the floor only");
    CHECK(jostle_body_get_separation(world, box).y < 0, "pushed up by the floor");

    // A jump ends the contact.
    CHECK(jostle_body_set_velocity(world, box, (jostle_vec2){0, -300}), "jump");
    int ends = 0;
    for (int i = 0; i < 10; ++i) {
        CHECK(jostle_world_step(world, kDt), "step");
        int count = 0;
        const jostle_contact_event* events = jostle_world_contact_ends(world, &count);
        for (int k = 0; k < count; ++k) {
            CHECK(same(events[k].a, floor) && same(events[k].b, box), "the pair that parted");
            CHECK(events[k].approach_speed == 0, "an end has no approach speed");
            CHECK(events[k].point.x == 0 && events[k].point.y == 0, "nor a point");
            ++ends;
        }
    }
    CHECK(ends == 1, "one contact end after the jump");
    CHECK(!jostle_body_get_touching(world, box).floor, "in the air");
    CHECK(jostle_world_destroy(world), "destroy");
    CHECK_NO_ERROR();
}

/// A box falls through a sensor zone (y 130 to 170) onto the floor (top 290): it enters
/// the zone, leaves it, and the zone does not slow it down.
static void test_sensor_events(void) {
    jostle_world* world = make_world(kG);
    add_box(world, JOSTLE_BODY_STATIC, 0, 300, 400, 10);
    jostle_body_def zone_def = jostle_default_body_def();
    zone_def.type = JOSTLE_BODY_STATIC;
    zone_def.y = 150;
    zone_def.hw = 50;
    zone_def.hh = 20;
    zone_def.sensor = true;
    jostle_body_id zone = jostle_body_create(world, &zone_def);
    CHECK(jostle_body_is_sensor(world, zone), "a sensor");
    jostle_body_id box = add_box(world, JOSTLE_BODY_DYNAMIC, 0, 0, 10, 10);

    int begins = 0, ends = 0;
    for (int i = 0; i < 120; ++i) {
        CHECK(jostle_world_step(world, kDt), "step");
        int count = 0;
        const jostle_sensor_event* in = jostle_world_sensor_begins(world, &count);
        for (int k = 0; k < count; ++k, ++begins)
            CHECK(same(in[k].sensor, zone) && same(in[k].visitor, box), "sensor begin");
        const jostle_sensor_event* out = jostle_world_sensor_ends(world, &count);
        for (int k = 0; k < count; ++k, ++ends)
            CHECK(same(out[k].sensor, zone) && same(out[k].visitor, box), "sensor end");
        int contacts = 0;
        const jostle_contact_event* c = jostle_world_contact_begins(world, &contacts);
        for (int k = 0; k < contacts; ++k)
            CHECK(!same(c[k].a, zone) && !same(c[k].b, zone), "sensors make no contacts");
    }
    CHECK(begins == 1 && ends == 1, "entered and left the zone once");
    CHECK_NEAR(jostle_body_get_position(world, box).y, 280.0, 0.1 + 1e-3);
    CHECK(jostle_world_destroy(world), "destroy");
    CHECK_NO_ERROR();
}

/// A kinematic block moving down onto a box that rests on the floor crushes it.
static void test_crush_event(void) {
    jostle_world* world = make_world(kG);
    jostle_body_id floor = add_box(world, JOSTLE_BODY_STATIC, 0, 50, 1000, 50); // top at 0
    jostle_body_id box = add_box(world, JOSTLE_BODY_DYNAMIC, 0, -5, 5, 5);
    jostle_body_def block_def = jostle_default_body_def();
    block_def.type = JOSTLE_BODY_KINEMATIC;
    block_def.y = -40;
    block_def.hw = 30;
    block_def.hh = 10;
    block_def.vy = 60;
    jostle_body_id block = jostle_body_create(world, &block_def);

    // It begins once, and ends once the block's top has passed the floor's (50 steps).
    int begins = 0, ends = 0;
    for (int i = 0; i < 120; ++i) {
        CHECK(jostle_world_step(world, kDt), "step");
        int count = 0;
        const jostle_crush_event* crushes = jostle_world_crush_begins(world, &count);
        for (int k = 0; k < count; ++k) {
            CHECK(same(crushes[k].body, box), "the box is crushed");
            CHECK(same(crushes[k].by, block), "by the block");
            CHECK(same(crushes[k].against, floor), "against the floor");
            ++begins;
        }
        const jostle_crush_event* ended = jostle_world_crush_ends(world, &count);
        for (int k = 0; k < count; ++k) {
            CHECK(same(ended[k].body, box) && same(ended[k].by, block), "the crush ends");
            ++ends;
        }
        // Never deeper in the floor than the crush depth (a tenth of 5) and the slop.
        CHECK(jostle_body_get_position(world, box).y <= -5 + 0.55, "never pushed into the floor");
    }
    CHECK(begins == 1 && ends == 1, "a crush begins once and ends once");
    CHECK(jostle_world_destroy(world), "destroy");
    CHECK_NO_ERROR();
}

// --- World settings and body properties --------------------------------------------------

static void test_world_settings(void) {
    jostle_world* world = make_world(kG);
    CHECK(jostle_world_set_gravity(world, (jostle_vec2){3, -4}), "set gravity");
    jostle_vec2 g = jostle_world_get_gravity(world);
    CHECK(g.x == 3 && g.y == -4, "gravity back");
    CHECK(jostle_world_set_max_velocity(world, 500), "set max velocity");
    CHECK(jostle_world_get_max_velocity(world) == 500, "max velocity back");
    CHECK(jostle_world_set_solver(world, JOSTLE_SOLVER_CLASSIC), "set solver");
    CHECK(jostle_world_get_solver(world) == JOSTLE_SOLVER_CLASSIC, "solver back");
    CHECK(jostle_world_set_sleeping(world, false), "set sleeping");
    CHECK(!jostle_world_get_sleeping(world), "sleeping back");

    jostle_classic_options classic = {true, true, true};
    CHECK(jostle_world_set_classic_options(world, classic), "set classic options");
    classic = jostle_world_get_classic_options(world);
    CHECK(classic.mass && classic.coulomb && classic.ccd, "classic options back");

    jostle_physical_options physical = jostle_world_get_physical_options(world);
    physical.velocity_iterations = 12;
    physical.slop = 0.02f;
    physical.friction_mix = JOSTLE_FRICTION_MIX_GEOMETRIC_MEAN;
    physical.max_contacts_per_body = 8;
    CHECK(jostle_world_set_physical_options(world, physical), "set physical options");
    physical = jostle_world_get_physical_options(world);
    CHECK(physical.velocity_iterations == 12 && physical.slop == 0.02f &&
              physical.friction_mix == JOSTLE_FRICTION_MIX_GEOMETRIC_MEAN &&
              physical.max_contacts_per_body == 8,
          "physical options back");
    physical.max_contacts_per_body = 0;
    CHECK(!jostle_world_set_physical_options(world, physical), "a budget of 0 is refused");
    jostle_clear_error();
    CHECK(jostle_world_destroy(world), "destroy");
    CHECK_NO_ERROR();
}

static void test_body_properties(void) {
    jostle_world* world = make_world(kG);
    jostle_body_id a = add_box(world, JOSTLE_BODY_DYNAMIC, 1, 2, 3, 4);
    jostle_body_id b = add_box(world, JOSTLE_BODY_STATIC, 0, 100, 50, 5);
    int marker = 42;

    CHECK(jostle_body_get_type(world, a) == JOSTLE_BODY_DYNAMIC, "type");
    CHECK(jostle_body_set_position(world, a, (jostle_vec2){5, 6}), "set position");
    CHECK(jostle_body_get_position(world, a).x == 5 && jostle_body_get_position(world, a).y == 6,
          "position");
    CHECK(jostle_body_set_velocity(world, a, (jostle_vec2){7, 8}), "set velocity");
    CHECK(jostle_body_get_velocity(world, a).x == 7, "velocity");
    CHECK(jostle_body_set_half_extents(world, a, (jostle_vec2){2, 3}), "set half extents");
    CHECK(jostle_body_get_half_extents(world, a).x == 2 &&
              jostle_body_get_half_extents(world, a).y == 3,
          "half extents");
    CHECK(jostle_body_set_bounce(world, a, 0.25f) && jostle_body_get_bounce(world, a) == 0.25f,
          "bounce");
    CHECK(jostle_body_set_friction(world, a, 0.75f) && jostle_body_get_friction(world, a) == 0.75f,
          "friction");
    // Mass: density x area, area = 4 hw hh = 24.
    CHECK(jostle_body_get_mass(world, a) == 24.0f, "mass from density 1");
    CHECK(jostle_body_set_mass(world, a, 5) && jostle_body_get_mass(world, a) == 5.0f, "mass");
    CHECK(jostle_body_set_density(world, a, 2) && jostle_body_get_mass(world, a) == 48.0f,
          "density drops the explicit mass");
    CHECK(isinf(jostle_body_get_mass(world, b)), "a static body is infinitely heavy");
    CHECK(jostle_body_set_gravity_scale(world, a, -1) &&
              jostle_body_get_gravity_scale(world, a) == -1,
          "gravity scale");
    CHECK(jostle_body_set_damping(world, a, 0.5f) && jostle_body_get_damping(world, a) == 0.5f,
          "damping");
    CHECK(jostle_body_set_bullet(world, a, true) && jostle_body_is_bullet(world, a), "bullet");
    CHECK(jostle_body_set_user_data(world, a, &marker) &&
              jostle_body_get_user_data(world, a) == &marker,
          "user data");
    CHECK(jostle_body_set_one_way(world, b, (jostle_vec2){0, -1}) &&
              jostle_body_get_one_way(world, b).y == -1,
          "one way");
    CHECK(jostle_body_drop_through(world, a, 0.5f), "drop through");
    CHECK(!jostle_body_drop_through(world, b, 0.5f), "a static body does not drop through");
    CHECK_ERROR("jostle_body_drop_through", "only a dynamic body drops through");
    CHECK(jostle_body_set_category(world, a, 4) && jostle_body_get_category(world, a) == 4,
          "category");
    CHECK(jostle_body_set_mask(world, a, 6) && jostle_body_get_mask(world, a) == 6, "mask");
    CHECK(jostle_body_set_sensor(world, a, true) && jostle_body_is_sensor(world, a), "sensor");
    CHECK(jostle_body_set_type(world, a, JOSTLE_BODY_KINEMATIC) &&
              jostle_body_get_type(world, a) == JOSTLE_BODY_KINEMATIC,
          "type");
    CHECK(!jostle_body_drop_through(world, a, 0.5f), "a kinematic body does not drop through");
    CHECK_ERROR("jostle_body_drop_through", "only a dynamic body drops through");
    CHECK(jostle_body_is_awake(world, a), "awake");
    CHECK(jostle_body_wake(world, a), "wake");

    // A body's def makes a copy of it.
    jostle_body_def def = jostle_body_get_def(world, a);
    CHECK(def.x == 5 && def.hw == 2 && def.category == 4 && def.user_data == &marker &&
              def.type == JOSTLE_BODY_KINEMATIC && def.density == 2,
          "the def of a body");
    jostle_body_id copy = jostle_body_create(world, &def);
    CHECK(!jostle_body_id_is_null(copy), "created from a body's def");

    // The body list, in creation order, with the buffer rule.
    CHECK(jostle_world_body_count(world) == 3, "three bodies");
    CHECK(jostle_world_bodies(world, NULL, 0) == 3, "the count alone");
    jostle_body_id list[3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
    CHECK(jostle_world_bodies(world, list, 2) == 3, "the full count with a small buffer");
    CHECK(same(list[0], a) && same(list[1], b) && jostle_body_id_is_null(list[2]),
          "the first two, and nothing beyond the capacity");
    CHECK(jostle_world_bodies(world, list, 3) == 3 && same(list[2], copy), "all three");

    CHECK(jostle_body_destroy(world, a), "destroy a body");
    CHECK(!jostle_body_is_valid(world, a), "stale after destroy");
    CHECK(jostle_body_is_valid(world, b), "the other is alive");
    CHECK(jostle_world_body_count(world) == 2, "two bodies");
    CHECK(jostle_world_destroy(world), "destroy");
    CHECK_NO_ERROR();
}

// --- Characters, forces and contacts now -------------------------------------------------

/// The character fields of a def reach the body, come back in its def, and have setters.
static void test_character_def(void) {
    jostle_world* world = make_world(kG);
    jostle_body_def def = jostle_default_body_def();
    def.hw = 6;
    def.hh = 8;
    def.character = true;
    def.wall_friction = 0.25f;
    jostle_body_id hero = jostle_body_create(world, &def);
    CHECK(jostle_body_is_character(world, hero), "a character");
    CHECK(jostle_body_get_wall_friction(world, hero) == 0.25f, "its wall friction");
    jostle_body_def back = jostle_body_get_def(world, hero);
    CHECK(back.character && back.wall_friction == 0.25f, "in its def");
    jostle_body_id copy = jostle_body_create(world, &back);
    CHECK(jostle_body_is_character(world, copy) &&
              jostle_body_get_wall_friction(world, copy) == 0.25f,
          "and in a copy made from it");

    CHECK(jostle_body_set_character(world, hero, false) && !jostle_body_is_character(world, hero),
          "set character");
    CHECK(jostle_body_set_wall_friction(world, hero, 0.75f) &&
              jostle_body_get_wall_friction(world, hero) == 0.75f,
          "set wall friction");
    back = jostle_body_get_def(world, hero);
    CHECK(!back.character && back.wall_friction == 0.75f, "the def follows");
    CHECK(jostle_body_get_walk_speed(world, hero) == 0, "standing by default");
    CHECK(!jostle_body_set_walk_speed(world, hero, -40) &&
              jostle_body_get_walk_speed(world, hero) == 0,
          "a body that is not a character does not walk");
    CHECK_ERROR("jostle_body_set_walk_speed", "the body is not a character");
    CHECK(jostle_body_set_character(world, hero, true) &&
              jostle_body_set_walk_speed(world, hero, -40) &&
              jostle_body_get_walk_speed(world, hero) == -40,
          "a character walks");

    CHECK(!jostle_body_set_wall_friction(world, hero, 2), "wall friction 2");
    CHECK_ERROR("jostle_body_set_wall_friction", "[0, 1]");
    CHECK(!jostle_body_set_walk_speed(world, hero, NAN), "NaN walk speed");
    CHECK_ERROR("jostle_body_set_walk_speed", "finite");
    CHECK(jostle_body_get_walk_speed(world, hero) == -40, "unchanged");
    def.wall_friction = -1;
    CHECK(jostle_body_id_is_null(jostle_body_create(world, &def)), "wall friction < 0");
    CHECK_ERROR("jostle_body_create", "BodyDef.wallFriction");
    CHECK(jostle_world_destroy(world), "destroy");
    CHECK_NO_ERROR();
}

static void test_footing(void) {
    jostle_world* world = make_world(kG);
    jostle_body_def def = jostle_default_body_def();
    CHECK(def.floor_angle == 60 && def.snap_down == 0, "floor angle 60 and no snapping by default");
    def.hw = 6;
    def.hh = 8;
    def.floor_angle = 45;
    def.snap_down = 4;
    jostle_body_id hero = jostle_body_create(world, &def);
    CHECK(jostle_body_get_floor_angle(world, hero) == 45 &&
              jostle_body_get_snap_down(world, hero) == 4,
          "floor angle and snap down as given");
    jostle_body_def back = jostle_body_get_def(world, hero);
    CHECK(back.floor_angle == 45 && back.snap_down == 4, "in its def");
    CHECK(jostle_body_set_floor_angle(world, hero, 0) && jostle_body_set_snap_down(world, hero, 0),
          "set");
    back = jostle_body_get_def(world, hero);
    CHECK(back.floor_angle == 0 && back.snap_down == 0, "the def follows");
    CHECK(!jostle_body_set_floor_angle(world, hero, 90), "floor angle 90");
    CHECK_ERROR("jostle_body_set_floor_angle", "[0, 90)");
    CHECK(!jostle_body_set_snap_down(world, hero, -1), "snap down -1");
    CHECK_ERROR("jostle_body_set_snap_down", ">= 0");
    def.floor_angle = NAN;
    CHECK(jostle_body_id_is_null(jostle_body_create(world, &def)), "NaN floor angle");
    CHECK_ERROR("jostle_body_create", "BodyDef.floorAngle");
    CHECK(jostle_world_destroy(world), "destroy");
    CHECK_NO_ERROR();
}

static void test_rounded_casts(void) {
    // The box (0, 0) +- 1. Along y = -1.8 from x = -5, a box of half extent 1 meets its side
    // at x = -2; a circle of radius 1 meets its corner (-1, -1) 0.6 before it (0.6² + 0.8²
    // = 1), at x = -1.6, with the normal (-0.6, -0.8).
    jostle_world* world = make_world(0);
    jostle_body_def def = jostle_default_body_def();
    def.type = JOSTLE_BODY_STATIC;
    def.hw = def.hh = 1;
    const jostle_body_id box = jostle_body_create(world, &def);
    jostle_box_cast_hit hit;
    const jostle_vec2 from = {-5, -1.8f}, unit = {1, 1}, across = {10, 0};
    CHECK(jostle_box_cast(world, from, unit, across, NULL, &hit) && fabsf(hit.centre.x + 2) < 1e-5f,
          "a box meets the side");
    CHECK(jostle_circle_cast(world, from, 1, across, NULL, &hit) &&
              jostle_body_id_equal(hit.body, box) && fabsf(hit.centre.x + 1.6f) < 1e-3f &&
              fabsf(hit.normal.x + 0.6f) < 1e-3f && fabsf(hit.normal.y + 0.8f) < 1e-3f,
          "a circle meets the corner on its curve");
    CHECK(jostle_rounded_box_cast(world, from, unit, 1, across, NULL, &hit) &&
              fabsf(hit.centre.x + 1.6f) < 1e-3f,
          "a rounded box with hw = hh = radius is that circle");
    CHECK(!jostle_rounded_box_cast(world, from, unit, 2, across, NULL, &hit), "radius > hw");
    CHECK_ERROR("jostle_rounded_box_cast", "radius");
    // An upright capsule (1 x 3, radius 1) from (20, -10) moved (10, 20) onto a floor whose
    // top is y = 0: its bottom meets it after 7 of the 20 down (fraction 0.35, 3.5 across);
    // what is left, (6.5, 13), loses its part into the floor: it ends at (30, -3).
    def.x = 25;
    def.y = 5;
    def.hw = 20;
    def.hh = 5;
    const jostle_body_id floor = jostle_body_create(world, &def);
    jostle_vec2 end;
    jostle_move_hit met[2];
    const jostle_vec2 capsule = {1, 3}, start = {20, -10}, motion = {10, 20};
    CHECK(jostle_rounded_move_and_slide(world, start, capsule, 1, motion, NULL, &end, met, 2) ==
                  1 &&
              jostle_body_id_equal(met[0].body, floor) && fabsf(end.x - 30) < 1e-4f &&
              fabsf(end.y + 3) < 1e-4f,
          "a capsule slid onto a floor goes on along it");
    CHECK(jostle_world_destroy(world), "destroy");
    CHECK_NO_ERROR();
}

// --- Shapes: rounded bodies, ramps and segments ------------------------------------------

/// A body from `def` with the shape's fields set; null on refusal.
static jostle_body_id add_shape(jostle_world* world, jostle_body_type type, float hw, float hh,
                                float radius, float sx, float sy, bool segment) {
    jostle_body_def def = jostle_default_body_def();
    def.type = type;
    def.hw = hw;
    def.hh = hh;
    def.radius = radius;
    def.slope.x = sx;
    def.slope.y = sy;
    def.segment = segment;
    return jostle_body_create(world, &def);
}

/// The shape of `body` read back by jostle_body_get_def, and a copy made from that def
/// has it too.
static bool has_shape(jostle_world* world, jostle_body_id body, float radius, float sx, float sy,
                      bool segment) {
    const jostle_body_def def = jostle_body_get_def(world, body);
    const jostle_body_id copy = jostle_body_create(world, &def);
    const jostle_body_def again = jostle_body_get_def(world, copy);
    return def.radius == radius && at(def.slope, sx, sy) && def.segment == segment &&
           again.radius == radius && at(again.slope, sx, sy) && again.segment == segment;
}

/// Refused with an error from `function` about `phrase`, and the world keeps its count.
#define CHECK_REFUSED_SHAPE(world, id, phrase)                                                     \
    do {                                                                                           \
        const int count_ = jostle_world_body_count(world);                                         \
        CHECK(jostle_body_id_is_null(id), phrase);                                                 \
        CHECK_ERROR("jostle_body_create", phrase);                                                 \
        CHECK(jostle_world_body_count(world) == count_, "nothing made");                           \
    } while (0)

/// The fields carry through jostle_body_def both ways: a circle (hw = hh = radius), a
/// capsule (hw = radius < hh), a ramp and a segment; the defaults are a sharp box.
static void test_shapes(void) {
    jostle_body_def b = jostle_default_body_def();
    CHECK(b.radius == 0 && at(b.slope, 0, 0) && !b.segment, "a sharp box by default");

    jostle_world* world = make_world(kG);
    jostle_body_id floor = add_box(world, JOSTLE_BODY_STATIC, 0, 100, 200, 10);
    jostle_body_id ball = add_shape(world, JOSTLE_BODY_DYNAMIC, 5, 5, 5, 0, 0, false);
    jostle_body_id capsule = add_shape(world, JOSTLE_BODY_DYNAMIC, 3, 8, 3, 0, 0, false);
    jostle_body_id ramp = add_shape(world, JOSTLE_BODY_STATIC, 40, 20, 0, -1, -1, false);
    jostle_body_id face = add_shape(world, JOSTLE_BODY_KINEMATIC, 40, 20, 0, 1, -1, true);
    CHECK_NO_ERROR();
    CHECK(has_shape(world, floor, 0, 0, 0, false), "the box");
    CHECK(has_shape(world, ball, 5, 0, 0, false), "the circle");
    CHECK(has_shape(world, capsule, 3, 0, 0, false), "the capsule");
    CHECK(has_shape(world, ramp, 0, -1, -1, false), "the ramp");
    CHECK(has_shape(world, face, 0, 1, -1, true), "the segment");
    CHECK_NO_ERROR();
    CHECK(jostle_world_body_count(world) == 10, "five bodies and their copies");
    run(world, 10);
    CHECK_NO_ERROR();

    // What the rules between the fields refuse, each named (checkBodyDef's words).
    CHECK_REFUSED_SHAPE(world, add_shape(world, JOSTLE_BODY_DYNAMIC, 5, 4, 4.5f, 0, 0, false),
                        "BodyDef.radius: must be <= hw and hh");
    CHECK_REFUSED_SHAPE(world, add_shape(world, JOSTLE_BODY_DYNAMIC, 5, 5, -1, 0, 0, false),
                        "BodyDef.radius: must be >= 0");
    CHECK_REFUSED_SHAPE(world, add_shape(world, JOSTLE_BODY_DYNAMIC, 5, 5, NAN, 0, 0, false),
                        "BodyDef.radius: must be a finite number");
    CHECK_REFUSED_SHAPE(world, add_shape(world, JOSTLE_BODY_STATIC, 5, 5, 0, 1, 0, false),
                        "BodyDef.slope: must be {0, 0} or each component -1 or 1");
    CHECK_REFUSED_SHAPE(world, add_shape(world, JOSTLE_BODY_STATIC, 5, 5, 0, INFINITY, 1, false),
                        "BodyDef.slope: must be a finite number");
    CHECK_REFUSED_SHAPE(world, add_shape(world, JOSTLE_BODY_DYNAMIC, 5, 5, 0, -1, -1, false),
                        "BodyDef.slope: a ramp or segment must be static or kinematic");
    CHECK_REFUSED_SHAPE(world, add_shape(world, JOSTLE_BODY_STATIC, 5, 5, 1, -1, -1, false),
                        "BodyDef.radius: must be 0 for a ramp or segment");
    CHECK_REFUSED_SHAPE(world, add_shape(world, JOSTLE_BODY_STATIC, 5, 5, 0, 0, 0, true),
                        "BodyDef.segment: needs a slope");
    jostle_body_def round = jostle_default_body_def();
    round.hw = round.hh = round.radius = 2;
    round.one_way.y = -1;
    CHECK_REFUSED_SHAPE(world, jostle_body_create(world, &round),
                        "BodyDef.oneWay: must be {0, 0} for a rounded body, ramp or segment");

    // A shape is fixed at creation: the setters that would break its rules are refused,
    // and the body stays as it was.
    CHECK(!jostle_body_set_type(world, ramp, JOSTLE_BODY_DYNAMIC), "a dynamic ramp");
    CHECK_ERROR("jostle_body_set_type", "a ramp or segment must be static or kinematic");
    CHECK(jostle_body_get_type(world, ramp) == JOSTLE_BODY_STATIC, "still static");
    CHECK(jostle_body_set_type(world, face, JOSTLE_BODY_STATIC), "a static segment is fine");
    CHECK(!jostle_body_set_half_extents(world, ball, (jostle_vec2){4, 5}), "smaller than r");
    CHECK_ERROR("jostle_body_set_half_extents", "halfExtents must be >= the body's radius");
    CHECK(at(jostle_body_get_half_extents(world, ball), 5, 5), "still 5 x 5");
    CHECK(jostle_body_set_half_extents(world, ball, (jostle_vec2){6, 5}), "not smaller than r");
    CHECK(!jostle_body_set_one_way(world, capsule, (jostle_vec2){0, -1}), "a one-way capsule");
    CHECK_ERROR("jostle_body_set_one_way", "cannot be one-way");
    CHECK(at(jostle_body_get_one_way(world, capsule), 0, 0), "solid all round");

    // The classic model has sharp boxes only: a world with shapes cannot switch to it
    // until they are gone, and a classic world refuses them.
    CHECK(!jostle_world_set_solver(world, JOSTLE_SOLVER_CLASSIC), "classic with shapes");
    CHECK_ERROR("jostle_world_set_solver", "the classic model has sharp boxes only");
    CHECK(jostle_world_get_solver(world) == JOSTLE_SOLVER_PHYSICAL, "still physical");
    jostle_body_id bodies[16];
    const int count = jostle_world_bodies(world, bodies, 16);
    for (int i = 0; i < count; ++i)
        if (!same(bodies[i], floor))
            CHECK(jostle_body_destroy(world, bodies[i]), "destroy");
    CHECK(jostle_world_set_solver(world, JOSTLE_SOLVER_CLASSIC), "classic with boxes alone");
    CHECK_REFUSED_SHAPE(world, add_shape(world, JOSTLE_BODY_DYNAMIC, 5, 5, 5, 0, 0, false),
                        "BodyDef.radius: the classic model has sharp boxes only");
    CHECK_REFUSED_SHAPE(world, add_shape(world, JOSTLE_BODY_STATIC, 5, 5, 0, 1, 1, true),
                        "BodyDef.slope: the classic model has sharp boxes only");
    CHECK(jostle_world_destroy(world), "destroy");
    CHECK_NO_ERROR();
}

/// A character 12 x 16 walks at the commanded 150 on a floor (top at y = 0), exactly; an
/// ordinary body set to 150 before each step loses friction * g * dt to the floor in it
/// (friction 0.5: 150 - 0.5 * 800 / 60 = 143.33). The character knows it stands on the
/// floor, which is at rest.
static void test_walking(void) {
    jostle_world* world = make_world(kG);
    jostle_body_id floor = add_box(world, JOSTLE_BODY_STATIC, 0, 50, 5000, 50);
    jostle_body_id hero = add_character(world, 0, -8, 0);
    jostle_body_id crate = add_box(world, JOSTLE_BODY_DYNAMIC, 1000, -8, 6, 8);
    run(world, 10); // settle
    CHECK(jostle_body_set_walk_speed(world, hero, 150), "walk");
    for (int i = 0; i < 30; ++i) {
        CHECK(jostle_body_set_velocity(world, crate, (jostle_vec2){150, 0}), "push the crate");
        CHECK(jostle_world_step(world, kDt), "step");
        CHECK(jostle_body_get_velocity(world, hero).x == 150, "the character walks at 150");
        CHECK_NEAR(jostle_body_get_velocity(world, crate).x, 150.0 - 0.5 * kG * kDt, 1e-3);
    }
    jostle_ground ground;
    CHECK(jostle_body_get_ground(world, hero, &ground), "on the ground");
    CHECK(same(ground.body, floor), "the floor");
    CHECK(at(ground.normal, 0, -1) && at(ground.velocity, 0, 0), "pushing up, at rest");
    CHECK(jostle_body_get_ground(world, crate, &ground) && same(ground.body, floor),
          "any body may ask");
    CHECK(jostle_world_destroy(world), "destroy");
    CHECK_NO_ERROR();
}

/// A conveyor (surface_velocity {80, 0}) carries a character that stands on it at 80, one
/// that walks at 40 at 120; a dynamic body is no conveyor.
static void test_conveyor(void) {
    jostle_world* world = make_world(kG);
    jostle_body_def def = jostle_default_body_def();
    CHECK(def.surface_velocity.x == 0 && def.surface_velocity.y == 0, "no belt by default");
    def.type = JOSTLE_BODY_STATIC;
    def.y = 50;
    def.hw = 5000;
    def.hh = 50;
    def.surface_velocity = (jostle_vec2){80, 0};
    jostle_body_id belt = jostle_body_create(world, &def);
    jostle_body_id hero = add_character(world, 0, -8, 0);
    run(world, 10);
    CHECK_NEAR(jostle_body_get_velocity(world, hero).x, 80, 1e-3);
    CHECK(jostle_body_set_walk_speed(world, hero, 40), "walk");
    run(world, 3);
    CHECK_NEAR(jostle_body_get_velocity(world, hero).x, 120, 1e-3);
    CHECK(jostle_body_get_surface_velocity(world, belt).x == 80, "read back");
    CHECK(!jostle_body_set_surface_velocity(world, hero, (jostle_vec2){1, 0}), "not a conveyor");
    CHECK_ERROR("jostle_body_set_surface_velocity", "static or kinematic");
    def.type = JOSTLE_BODY_DYNAMIC;
    CHECK(jostle_body_id_is_null(jostle_body_create(world, &def)), "a dynamic conveyor");
    CHECK_ERROR("jostle_body_create", "BodyDef.surfaceVelocity");
    CHECK(jostle_world_destroy(world), "destroy");
    CHECK_NO_ERROR();
}

/// A character standing on a lift 80 x 12 (top at y = 0) stands on it, and has the
/// lift's velocity for its ground's; after a jump it stands on nothing.
static void test_ground_of_a_lift(void) {
    jostle_world* world = make_world(kG);
    jostle_body_id lift = add_box(world, JOSTLE_BODY_KINEMATIC, 0, 6, 40, 6);
    jostle_body_id hero = add_character(world, 0, -8, 0);
    run(world, 10);
    CHECK(jostle_body_set_velocity(world, lift, (jostle_vec2){30, -20}), "the lift moves");
    run(world, 1);
    jostle_ground ground;
    CHECK(jostle_body_get_ground(world, hero, &ground), "on the lift");
    CHECK(same(ground.body, lift), "the lift");
    CHECK(at(ground.normal, 0, -1) && at(ground.velocity, 30, -20), "the lift's velocity");

    // In the air: an ordinary false, *ground untouched.
    CHECK(jostle_body_set_velocity(world, hero, (jostle_vec2){0, -400}), "jump");
    run(world, 2);
    ground.velocity.x = 77;
    CHECK(!jostle_body_get_ground(world, hero, &ground), "in the air");
    CHECK(ground.velocity.x == 77, "untouched");
    CHECK(!jostle_body_get_ground(world, lift, &ground), "nothing under the lift");
    CHECK_NO_ERROR();
    CHECK(!jostle_body_get_ground(world, hero, NULL), "no output");
    CHECK_ERROR("jostle_body_get_ground", "ground is NULL");
    CHECK(jostle_world_destroy(world), "destroy");
    CHECK_NO_ERROR();
}

/// A character 12 x 16 pressed into a wall (its left face at x = 100, walking into it at
/// 150) and let go from rest high up falls as in open air: after n steps,
/// g dt^2 n (n + 1) / 2 (46.67 for 20). With a wall friction of 0.5 the wall holds it:
/// it falls less than a quarter of that.
static void test_wall_friction(void) {
    for (int asked = 0; asked < 2; ++asked) {
        jostle_world* world = make_world(kG);
        add_box(world, JOSTLE_BODY_STATIC, 0, 50, 500, 50);
        add_box(world, JOSTLE_BODY_STATIC, 150, -200, 50, 200);
        jostle_body_id hero = add_character(world, 94, -8, asked ? 0.5f : 0);
        CHECK(jostle_body_set_walk_speed(world, hero, 150), "into the wall");
        run(world, 5);
        CHECK(jostle_body_set_position(world, hero, (jostle_vec2){94, -300}), "high up");
        CHECK(jostle_body_set_velocity(world, hero, (jostle_vec2){0, 0}), "at rest");
        run(world, 20);
        const double fall = jostle_body_get_position(world, hero).y + 300;
        const double open_air = kG * (double)kDt * kDt * 20 * 21 / 2;
        if (asked)
            CHECK(fall < 0.25 * open_air, "held by the wall");
        else
            CHECK_NEAR(fall, open_air, 1e-3);
        CHECK(jostle_body_get_touching(world, hero).wall_right, "against the wall");
        CHECK(jostle_world_destroy(world), "destroy");
    }
    CHECK_NO_ERROR();
}

/// A 20 x 10 box of density 2 (mass 400) without gravity: a force of (800, -400) for one
/// step changes its velocity by (800, -400) / 400 / 60 = (1/30, -1/60), and the next step
/// nothing more. An impulse of (8, -2) on a box of mass 4 changes its velocity by
/// (2, -0.5) at once. Static bodies are not moved.
static void test_forces(void) {
    jostle_world* world = make_world(0);
    jostle_body_def def = jostle_default_body_def();
    def.hw = 10;
    def.hh = 5;
    def.density = 2;
    jostle_body_id box = jostle_body_create(world, &def);
    CHECK(jostle_body_apply_force(world, box, (jostle_vec2){800, -400}), "a force");
    CHECK(jostle_body_get_velocity(world, box).x == 0, "for the next step");
    run(world, 1);
    CHECK_NEAR(jostle_body_get_velocity(world, box).x, 1.0 / 30.0, 1e-6);
    CHECK_NEAR(jostle_body_get_velocity(world, box).y, -1.0 / 60.0, 1e-6);
    run(world, 1);
    CHECK_NEAR(jostle_body_get_velocity(world, box).x, 1.0 / 30.0, 1e-6);

    def.mass = 4;
    def.x = 100;
    jostle_body_id light = jostle_body_create(world, &def);
    CHECK(jostle_body_apply_impulse(world, light, (jostle_vec2){8, -2}), "an impulse");
    const jostle_vec2 v = jostle_body_get_velocity(world, light);
    CHECK(v.x == 2 && v.y == -0.5f, "at once");

    jostle_body_id wall = add_box(world, JOSTLE_BODY_STATIC, -100, 0, 5, 5);
    CHECK(jostle_body_apply_force(world, wall, (jostle_vec2){1e6f, 0}) &&
              jostle_body_apply_impulse(world, wall, (jostle_vec2){1e6f, 0}),
          "accepted, and nothing happens");
    run(world, 1);
    CHECK(jostle_body_get_velocity(world, wall).x == 0, "a static body stays");
    CHECK_NO_ERROR();

    CHECK(!jostle_body_apply_force(world, box, (jostle_vec2){NAN, 0}), "NaN");
    CHECK_ERROR("jostle_body_apply_force", "force must be finite");
    CHECK(!jostle_body_apply_impulse(world, box, (jostle_vec2){0, INFINITY}), "infinite");
    CHECK_ERROR("jostle_body_apply_impulse", "impulse must be finite");
    CHECK_NEAR(jostle_body_get_velocity(world, box).x, 1.0 / 30.0, 1e-6); // unchanged
    CHECK(jostle_world_destroy(world), "destroy");
    CHECK_NO_ERROR();
}

/// A 10 x 10 crate (mass 100) at rest on a floor whose top is y = 0 (x from -100 to 100),
/// under gravity 600, its left edge at x = 20; another box at x = -50, and a sensor
/// around the crate.
static void test_contacts_now(void) {
    jostle_world* world = make_world(600);
    jostle_body_id floor = add_box(world, JOSTLE_BODY_STATIC, 0, 10, 100, 10);
    jostle_body_id crate = add_box(world, JOSTLE_BODY_DYNAMIC, 25, -5, 5, 5);
    jostle_body_id other = add_box(world, JOSTLE_BODY_DYNAMIC, -50, -5, 5, 5);
    jostle_body_def zone = jostle_default_body_def();
    zone.type = JOSTLE_BODY_STATIC;
    zone.x = 25;
    zone.hw = 20;
    zone.hh = 20;
    zone.sensor = true;
    jostle_body_id sensor = jostle_body_create(world, &zone);
    run(world, 30);

    jostle_contact_info contacts[2];
    CHECK(jostle_body_contacts(world, crate, contacts, 2) == 1, "the floor alone, no sensor");
    CHECK(same(contacts[0].other, floor), "the floor");
    CHECK(contacts[0].normal.x == 0 && contacts[0].normal.y == -1, "from the floor to the crate");
    // The middle of the stretch they share, x 20 to 30, on the floor's top.
    CHECK_NEAR(contacts[0].point.x, 25.0, 1e-4);
    CHECK_NEAR(contacts[0].point.y, 0.0, 0.05);
    // Holding the crate up for a step: m g dt = 100 * 600 / 60 = 1000.
    CHECK_NEAR(contacts[0].impulse, 1000.0, 1.0);

    // The floor's, with the buffer rule: in the order of the bodies they pair with.
    const jostle_body_id sentinel = {77, 77, 77};
    contacts[1].other = sentinel;
    CHECK(jostle_body_contacts(world, floor, NULL, 0) == 2, "the count alone");
    CHECK(jostle_body_contacts(world, floor, contacts, 1) == 2, "the full count, one copied");
    CHECK(same(contacts[0].other, crate) && contacts[0].normal.y == 1, "the crate first");
    CHECK(same(contacts[1].other, sentinel), "nothing beyond the capacity");
    CHECK(jostle_body_contacts(world, floor, contacts, 2) == 2 && same(contacts[1].other, other),
          "then the other box");

    CHECK(jostle_body_is_touching(world, crate, floor) &&
              jostle_body_is_touching(world, floor, crate),
          "touching, both ways");
    CHECK(!jostle_body_is_touching(world, crate, other), "apart");
    CHECK(!jostle_body_is_touching(world, crate, sensor), "a sensor is not a contact");
    CHECK_NO_ERROR();

    CHECK(jostle_body_contacts(world, crate, contacts, -1) == 0, "capacity < 0");
    CHECK_ERROR("jostle_body_contacts", "capacity must be >= 0");
    CHECK(jostle_body_destroy(world, other), "destroy");
    CHECK(jostle_body_contacts(world, other, NULL, 0) == 0, "stale");
    CHECK_ERROR("jostle_body_contacts", "stale");
    CHECK(!jostle_body_is_touching(world, floor, other), "stale");
    CHECK_ERROR("jostle_body_is_touching", "stale");
    CHECK(jostle_world_destroy(world), "destroy");
    CHECK_NO_ERROR();
}

/// A contact begin says where the bodies met: a box 20 wide overhanging the left end of a
/// floor (x from -100) lands on x -100 to -85, so at -92.5, on the floor's top.
static void test_contact_point(void) {
    jostle_world* world = make_world(600);
    add_box(world, JOSTLE_BODY_STATIC, 0, 10, 100, 10);
    add_box(world, JOSTLE_BODY_DYNAMIC, -95, -50, 10, 5);
    int met = 0;
    for (int i = 0; i < 60 && !met; ++i) {
        CHECK(jostle_world_step(world, kDt), "step");
        const jostle_contact_event* begins = jostle_world_contact_begins(world, &met);
        for (int k = 0; k < met; ++k) {
            CHECK_NEAR(begins[k].point.x, -92.5, 1e-3);
            CHECK_NEAR(begins[k].point.y, 0.0, 0.05);
        }
    }
    CHECK(met == 1, "it landed");
    CHECK(jostle_world_destroy(world), "destroy");
    CHECK_NO_ERROR();
}

// --- Bulk reads --------------------------------------------------------------------------

static void test_read_positions(void) {
    jostle_world* world = make_world(0);
    jostle_body_def def = jostle_default_body_def();
    def.hw = 1;
    def.hh = 1;
    def.x = 1, def.y = 2, def.vx = 3, def.vy = 4;
    jostle_body_id a = jostle_body_create(world, &def);
    def.x = 5, def.y = 6, def.vx = 7, def.vy = 8;
    jostle_body_create(world, &def);
    def.x = 9, def.y = 10, def.vx = 0, def.vy = 0, def.hw = 2, def.hh = 3;
    jostle_body_create(world, &def);
    CHECK(jostle_body_destroy(world, a), "destroyed: the order is the list's, b then c");

    jostle_vec2 positions[5];
    for (int i = 0; i < 5; ++i)
        positions[i] = (jostle_vec2){-1, -1};
    CHECK(jostle_world_read_positions(world, positions, 5) == 2, "two bodies");
    CHECK(positions[0].x == 5 && positions[0].y == 6, "b");
    CHECK(positions[1].x == 9 && positions[1].y == 10, "c");
    CHECK(positions[2].x == -1 && positions[2].y == -1, "left alone");
    jostle_vec2 velocities[1] = {{-1, -1}};
    CHECK(jostle_world_read_velocities(world, velocities, 1) == 2, "the full count");
    CHECK(velocities[0].x == 7 && velocities[0].y == 8, "b's, as many as fit");
    jostle_vec2 halves[2];
    CHECK(jostle_world_read_half_extents(world, halves, 2) == 2, "two half extents");
    CHECK(halves[0].x == 1 && halves[0].y == 1 && halves[1].x == 2 && halves[1].y == 3, "b, c");
    CHECK(jostle_world_read_positions(world, NULL, 0) == 2, "the count alone");
    CHECK_NO_ERROR();

    CHECK(jostle_world_read_positions(world, NULL, 2) == 0, "NULL with room");
    CHECK_ERROR("jostle_world_read_positions", "out is NULL but capacity is 2");
    CHECK(jostle_world_read_velocities(world, velocities, -1) == 0, "capacity < 0");
    CHECK_ERROR("jostle_world_read_velocities", "capacity must be >= 0");
    CHECK(jostle_world_read_positions(NULL, positions, 5) == 0, "no world");
    CHECK_ERROR("jostle_world_read_positions", "world is NULL");
    CHECK(jostle_world_destroy(world), "destroy");
    CHECK_NO_ERROR();
}

// --- Queries -----------------------------------------------------------------------------

/// A static scene, so every answer follows from the numbers:
///   floor: x -100..100, y 90..110 (top at 90)
///   crate: x -10..10,   y 70..90 (standing on the floor)
///   zone:  a sensor, x 45..55, y 45..55
static void test_queries(void) {
    jostle_world* world = make_world(0);
    jostle_body_id floor = add_box(world, JOSTLE_BODY_STATIC, 0, 100, 100, 10);
    jostle_body_id crate = add_box(world, JOSTLE_BODY_STATIC, 0, 80, 10, 10);
    jostle_body_def zone_def = jostle_default_body_def();
    zone_def.type = JOSTLE_BODY_STATIC;
    zone_def.x = 50;
    zone_def.y = 50;
    zone_def.hw = 5;
    zone_def.hh = 5;
    zone_def.sensor = true;
    jostle_body_id zone = jostle_body_create(world, &zone_def);
    jostle_query_filter with_sensors = jostle_default_query_filter();
    with_sensors.include_sensors = true;
    jostle_body_id found[4];

    // Points: inside the crate; on the seam of crate and floor, which belongs to both.
    CHECK(jostle_query_point(world, (jostle_vec2){0, 80}, NULL, found, 4) == 1, "one body");
    CHECK(same(found[0], crate), "the crate");
    jostle_body_id sentinel = {77, 77, 77};
    found[1] = sentinel;
    CHECK(jostle_query_point(world, (jostle_vec2){0, 90}, NULL, found, 1) == 2,
          "both on the seam, counted though only one fits");
    CHECK(same(found[0], floor) && same(found[1], sentinel), "floor first, nothing beyond");
    CHECK(jostle_query_point(world, (jostle_vec2){50, 50}, NULL, NULL, 0) == 0,
          "sensors are left out by default");
    CHECK(jostle_query_point(world, (jostle_vec2){50, 50}, &with_sensors, found, 4) == 1 &&
              same(found[0], zone),
          "the sensor when asked");

    // Boxes: one inside the crate reaches down to 85, short of the floor.
    CHECK(jostle_query_box(world, (jostle_vec2){0, 80}, (jostle_vec2){5, 5}, NULL, found, 4) == 1 &&
              same(found[0], crate),
          "the crate only");
    CHECK(jostle_query_rect(world, (jostle_vec2){-200, -200}, (jostle_vec2){200, 200}, NULL, found,
                            4) == 2,
          "floor and crate");
    CHECK(jostle_query_rect(world, (jostle_vec2){-200, -200}, (jostle_vec2){200, 200},
                            &with_sensors, found, 4) == 3,
          "and the zone");
    jostle_query_filter not_crate = jostle_default_query_filter();
    not_crate.ignore = crate;
    CHECK(jostle_query_rect(world, (jostle_vec2){-200, -200}, (jostle_vec2){200, 200}, &not_crate,
                            found, 4) == 1 &&
              same(found[0], floor),
          "ignore leaves the crate out");

    // A ray straight down from (0, 0) to (0, 200) meets the crate's top, y = 70, at
    // fraction 70 / 200, and then the floor's top, y = 90, at 90 / 200.
    jostle_ray_hit hit;
    CHECK(jostle_ray_cast(world, (jostle_vec2){0, 0}, (jostle_vec2){0, 200}, NULL, &hit), "a hit");
    CHECK(same(hit.body, crate), "the crate first");
    CHECK(hit.point.x == 0 && hit.point.y == 70, "on its top face");
    CHECK(hit.normal.x == 0 && hit.normal.y == -1, "facing the ray");
    CHECK_NEAR(hit.fraction, 70.0 / 200.0, 1e-6);
    jostle_ray_hit hits[2];
    CHECK(jostle_ray_cast_all(world, (jostle_vec2){0, 0}, (jostle_vec2){0, 200}, NULL, hits, 2) ==
              2,
          "two on the way");
    CHECK(same(hits[0].body, crate) && same(hits[1].body, floor), "nearest first");
    CHECK_NEAR(hits[1].fraction, 90.0 / 200.0, 1e-6);
    CHECK(jostle_ray_cast_all(world, (jostle_vec2){0, 0}, (jostle_vec2){0, 200}, NULL, hits, 1) ==
              2,
          "the full count with room for one");
    // Down x = 50: the zone (top 45, fraction 45 / 200) only if sensors are asked for.
    CHECK(
        jostle_ray_cast(world, (jostle_vec2){50, 0}, (jostle_vec2){50, 200}, &with_sensors, &hit) &&
            same(hit.body, zone),
        "the zone");
    CHECK_NEAR(hit.fraction, 45.0 / 200.0, 1e-6);
    CHECK(jostle_ray_cast(world, (jostle_vec2){50, 0}, (jostle_vec2){50, 200}, NULL, &hit) &&
              same(hit.body, floor),
          "through the zone to the floor");
    // A miss is an ordinary false: no error, and the hit is left as it was.
    hit.fraction = -1;
    CHECK(!jostle_ray_cast(world, (jostle_vec2){500, 0}, (jostle_vec2){500, 10}, NULL, &hit),
          "a miss");
    CHECK(hit.fraction == -1, "untouched");
    CHECK_NO_ERROR();

    // A box of half size 5 dropped from (-50, 0) by 200 stops on the floor: centre
    // y = 90 - 5 = 85, fraction 85 / 200.
    jostle_box_cast_hit cast;
    CHECK(jostle_box_cast(world, (jostle_vec2){-50, 0}, (jostle_vec2){5, 5}, (jostle_vec2){0, 200},
                          NULL, &cast),
          "the box lands");
    CHECK(same(cast.body, floor), "on the floor");
    CHECK(cast.centre.x == -50 && cast.centre.y == 85, "touching it");
    CHECK(cast.normal.x == 0 && cast.normal.y == -1, "pushed up");
    CHECK_NEAR(cast.fraction, 85.0 / 200.0, 1e-6);

    // Move and slide: from (-50, 80) by (30, 20). The box's bottom (85) meets the floor
    // (90) a quarter of the way, at x = -42.5; it slides the rest of x along the floor,
    // to x = -20 (its right side at -15, short of the crate at -10).
    jostle_vec2 end;
    jostle_move_hit met[2];
    CHECK(jostle_move_and_slide(world, (jostle_vec2){-50, 80}, (jostle_vec2){5, 5},
                                (jostle_vec2){30, 20}, NULL, &end, met, 2) == 1,
          "one body met");
    CHECK_NEAR(end.x, -20.0, 1e-4);
    CHECK(end.y == 85, "on the floor");
    CHECK(same(met[0].body, floor) && met[0].normal.y == -1, "the floor, from above");
    CHECK(jostle_move_and_slide(world, (jostle_vec2){-50, 80}, (jostle_vec2){5, 5},
                                (jostle_vec2){30, 20}, NULL, &end, NULL, 0) == 1,
          "the count without a buffer");
    CHECK(jostle_world_destroy(world), "destroy");
    CHECK_NO_ERROR();
}

// --- Moving a body by hand, bump.lua's way -----------------------------------------------
//
// The cases of bump.lua's spec suite (tests/test_move.cpp), without gravity. bump gives a
// rect by its top-left corner and size: rect() makes such a box. The item moved is
// (0, 0, 1, 1), a kinematic body: centre (0.5, 0.5).

static jostle_body_id rect(jostle_world* world, float x, float y, float w, float h,
                           jostle_body_type type) {
    return add_box(world, type, x + w / 2, y + h / 2, w / 2, h / 2);
}

static jostle_world* move_scene(jostle_body_id* item) {
    jostle_world* world = make_world(0);
    *item = rect(world, 0, 0, 1, 1, JOSTLE_BODY_KINEMATIC);
    return world;
}

/// Answers every body with the response `context` points to.
static jostle_response always(jostle_body_id other, void* context) {
    (void)other;
    return *(const jostle_response*)context;
}

static void test_move_responses(void) {
    jostle_body_id item;
    jostle_move_result r;

    // In an empty world it goes all the way.
    jostle_world* world = move_scene(&item);
    CHECK(jostle_body_move(world, item, (jostle_vec2){1, 1}, NULL, NULL, &r), "moved");
    CHECK(at(r.centre, 1.5f, 1.5f) && r.count == 0 && r.collisions == NULL, "all the way");
    CHECK(at(jostle_body_get_position(world, item), 1.5f, 1.5f), "the body is there");
    CHECK(jostle_world_destroy(world), "destroy");

    // Touch: its bottom (1) reaches b's top (2) after 1 of 5, and stops there.
    world = move_scene(&item);
    jostle_body_id b = rect(world, 0, 2, 1, 1, JOSTLE_BODY_STATIC);
    jostle_body_id c = rect(world, 0, 3, 1, 1, JOSTLE_BODY_STATIC);
    jostle_response response = JOSTLE_RESPONSE_TOUCH;
    CHECK(jostle_body_move(world, item, (jostle_vec2){0, 5}, always, &response, &r), "touch");
    CHECK(at(r.centre, 0.5f, 1.5f) && r.count == 1, "stopped on b");
    const jostle_move_collision* hit = &r.collisions[0];
    CHECK(same(hit->other, b) && hit->response == JOSTLE_RESPONSE_TOUCH, "b, touched");
    CHECK(at(hit->normal, 0, -1) && at(hit->touch, 0.5f, 1.5f), "from above, on its top");
    CHECK_NEAR(hit->time, 0.2, 1e-6);
    CHECK(at(hit->other_centre, 0.5f, 2.5f) && at(hit->other_half, 0.5f, 0.5f), "b's box");
    CHECK(at(jostle_body_get_position(world, item), 0.5f, 1.5f), "the body is there");
    // The array stays as it was until the next move, whatever else happens.
    CHECK(jostle_world_step(world, kDt), "step");
    CHECK(same(r.collisions[0].other, b), "still there after a step");

    // Cross: through both, each reported in turn (the item is back at the start).
    CHECK(jostle_body_set_position(world, item, (jostle_vec2){0.5f, 0.5f}), "back");
    response = JOSTLE_RESPONSE_CROSS;
    CHECK(jostle_body_move(world, item, (jostle_vec2){0, 5}, always, &response, &r), "cross");
    CHECK(at(r.centre, 0.5f, 5.5f) && r.count == 2, "all the way, two met");
    CHECK(same(r.collisions[0].other, b) && same(r.collisions[1].other, c), "in turn");
    CHECK_NEAR(r.collisions[0].time, 0.2, 1e-6);
    CHECK_NEAR(r.collisions[1].time, 0.4, 1e-6);
    CHECK(at(r.collisions[1].touch, 0.5f, 2.5f), "c touched at 2.5");

    // Bounce: down 5 onto b's top after 1: the 4 left go back up, from 1.5 to -2.5.
    CHECK(jostle_body_set_position(world, item, (jostle_vec2){0.5f, 0.5f}), "back");
    response = JOSTLE_RESPONSE_BOUNCE;
    CHECK(jostle_body_move(world, item, (jostle_vec2){0, 5}, always, &response, &r), "bounce");
    CHECK(at(r.centre, 0.5f, -2.5f) && r.count == 1, "turned back");
    CHECK(at(r.collisions[0].touch, 0.5f, 1.5f) &&
              r.collisions[0].response == JOSTLE_RESPONSE_BOUNCE,
          "off b's top");
    CHECK(jostle_world_destroy(world), "destroy");

    // Slide, the default: b (0, 2, 1, 2) below the item, c (2, 1, 1, 1). Moving by (5, 5),
    // the item meets c's left face after 1 of 5, at (1.5, 1.5), then slides down the rest,
    // to (1.5, 5.5), past b's corner without entering it.
    world = move_scene(&item);
    rect(world, 0, 2, 1, 2, JOSTLE_BODY_STATIC);
    c = rect(world, 2, 1, 1, 1, JOSTLE_BODY_STATIC);
    CHECK(jostle_body_move(world, item, (jostle_vec2){5, 5}, NULL, NULL, &r), "slide");
    CHECK(at(r.centre, 1.5f, 5.5f) && r.count == 1, "down c's face");
    CHECK(same(r.collisions[0].other, c) && r.collisions[0].response == JOSTLE_RESPONSE_SLIDE,
          "c, slid along");
    CHECK(at(r.collisions[0].normal, -1, 0) && at(r.collisions[0].touch, 1.5f, 1.5f),
          "its left face");
    CHECK_NEAR(r.collisions[0].time, 0.2, 1e-6);
    // Without a result: the move alone. Along y 0..1 it passes over c's top (touching is
    // not running into), and it does not tunnel through a thin wall at x = 50.
    CHECK(jostle_body_set_position(world, item, (jostle_vec2){0.5f, 0.5f}), "back");
    rect(world, 50, -5, 1, 10, JOSTLE_BODY_STATIC);
    CHECK(jostle_body_move(world, item, (jostle_vec2){100, 0}, NULL, NULL, NULL), "no result");
    CHECK(at(jostle_body_get_position(world, item), 49.5f, 0.5f), "stopped by the wall");
    CHECK(jostle_world_destroy(world), "destroy");
    CHECK_NO_ERROR();
}

/// A filter that ignores one body and slides on the others, counting its calls per body.
typedef struct ghost_filter {
    jostle_body_id ghost;
    int calls[8]; // by slot
} ghost_filter;

static jostle_response through_ghost(jostle_body_id other, void* context) {
    ghost_filter* f = (ghost_filter*)context;
    if (other.index < 8)
        ++f->calls[other.index];
    return same(other, f->ghost) ? JOSTLE_RESPONSE_IGNORE : JOSTLE_RESPONSE_SLIDE;
}

static void test_move_filters(void) {
    jostle_body_id item;
    jostle_move_result r;

    // Ignore means through, unreported; the filter is asked once per body.
    jostle_world* world = move_scene(&item);
    ghost_filter f;
    memset(&f, 0, sizeof f);
    f.ghost = rect(world, 3, 0, 1, 1, JOSTLE_BODY_STATIC);
    jostle_body_id wall = rect(world, 6, 0, 1, 1, JOSTLE_BODY_STATIC);
    CHECK(jostle_body_move(world, item, (jostle_vec2){10, 0}, through_ghost, &f, &r), "moved");
    CHECK(at(r.centre, 5.5f, 0.5f) && r.count == 1 && same(r.collisions[0].other, wall),
          "through the ghost, stopped by the wall");
    for (int slot = 0; slot < 8; ++slot)
        CHECK(f.calls[slot] <= 1, "asked at most once per body");
    CHECK(f.calls[f.ghost.index] == 1 && f.calls[wall.index] == 1, "asked of both");
    CHECK(jostle_world_destroy(world), "destroy");

    // By default a sensor is crossed and reported; a body the item's mask leaves out is not
    // met at all.
    world = move_scene(&item);
    jostle_body_def coin_def = jostle_default_body_def();
    coin_def.type = JOSTLE_BODY_STATIC;
    coin_def.x = 3.5f;
    coin_def.y = 0.5f;
    coin_def.hw = 0.5f;
    coin_def.hh = 0.5f;
    coin_def.sensor = true;
    jostle_body_id coin = jostle_body_create(world, &coin_def);
    jostle_body_def left_out = coin_def;
    left_out.x = 6.5f;
    left_out.sensor = false;
    left_out.category = 4;
    jostle_body_create(world, &left_out);
    CHECK(jostle_body_set_mask(world, item, ~4u), "mask");
    CHECK(jostle_body_move(world, item, (jostle_vec2){10, 0}, NULL, NULL, &r), "moved");
    CHECK(at(r.centre, 10.5f, 0.5f) && r.count == 1, "all the way, one met");
    CHECK(same(r.collisions[0].other, coin) && r.collisions[0].response == JOSTLE_RESPONSE_CROSS,
          "the coin, crossed");

    // A one-way platform ({0, -1}: its top) stops it only from above.
    jostle_body_def platform = jostle_default_body_def();
    platform.type = JOSTLE_BODY_STATIC;
    platform.x = 10.5f;
    platform.y = -5;
    platform.hw = 5;
    platform.hh = 0.5f;
    platform.one_way = (jostle_vec2){0, -1};
    jostle_body_create(world, &platform);
    CHECK(jostle_body_move(world, item, (jostle_vec2){0, -10}, NULL, NULL, &r) &&
              at(r.centre, 10.5f, -9.5f) && r.count == 0,
          "up through it");
    CHECK(jostle_body_move(world, item, (jostle_vec2){0, 10}, NULL, NULL, &r) &&
              at(r.centre, 10.5f, -6) && r.count == 1,
          "down onto its top");
    CHECK(jostle_world_destroy(world), "destroy");
    CHECK_NO_ERROR();
}

/// What a filter tries: reading is allowed, changing the world is refused.
typedef struct meddling_filter {
    jostle_world* world;
    jostle_body_id item;
    int found;   // bodies a query inside the filter found
    int refused; // changes refused with the move's message
} meddling_filter;

static void count_refusal(meddling_filter* f, bool ok, const char* function) {
    const char* m = jostle_last_error();
    if (!ok && strncmp(m, function, strlen(function)) == 0 &&
        strstr(m, "called from a filter during jostle_body_move"))
        ++f->refused;
    jostle_clear_error();
}

static jostle_response meddle(jostle_body_id other, void* context) {
    meddling_filter* f = (meddling_filter*)context;
    jostle_body_id found[4];
    f->found =
        jostle_query_point(f->world, jostle_body_get_position(f->world, other), NULL, found, 4);
    count_refusal(f, jostle_body_set_position(f->world, other, (jostle_vec2){100, 100}),
                  "jostle_body_set_position");
    count_refusal(f, jostle_body_destroy(f->world, other), "jostle_body_destroy");
    jostle_body_def def = jostle_default_body_def();
    def.hw = 1;
    def.hh = 1;
    count_refusal(f, !jostle_body_id_is_null(jostle_body_create(f->world, &def)),
                  "jostle_body_create");
    count_refusal(f, jostle_body_move(f->world, f->item, (jostle_vec2){1, 0}, NULL, NULL, NULL),
                  "jostle_body_move");
    count_refusal(f, jostle_world_step(f->world, kDt), "jostle_world_step");
    count_refusal(f, jostle_world_destroy(f->world), "jostle_world_destroy");
    return JOSTLE_RESPONSE_SLIDE;
}

/// Answers with a value that is not a jostle_response.
static jostle_response nonsense(jostle_body_id other, void* context) {
    (void)other;
    (void)context;
    return (jostle_response)9;
}

static void test_move_misuse(void) {
    jostle_body_id item;
    jostle_move_result r;
    jostle_world* world = move_scene(&item);
    jostle_body_id wall = rect(world, 3, 0, 1, 1, JOSTLE_BODY_STATIC);

    // The filter may read the world, not change it.
    meddling_filter f = {world, item, 0, 0};
    CHECK(jostle_body_move(world, item, (jostle_vec2){10, 0}, meddle, &f, &r), "moved");
    CHECK(f.found == 1, "a query from the filter finds the wall");
    CHECK(f.refused == 6, "set_position, destroy, create, move, step and destroy refused");
    CHECK(at(r.centre, 2.5f, 0.5f) && r.count == 1 && same(r.collisions[0].other, wall),
          "the move as if the filter had done nothing");
    CHECK(at(jostle_body_get_position(world, wall), 3.5f, 0.5f), "the wall stays");
    CHECK(jostle_world_body_count(world) == 2, "nothing created or destroyed");
    CHECK(jostle_body_set_position(world, item, (jostle_vec2){0.5f, 0.5f}), "allowed again");
    CHECK_NO_ERROR();

    // A filter's answer out of the enum: nothing moves.
    r.count = 5;
    CHECK(!jostle_body_move(world, item, (jostle_vec2){10, 0}, nonsense, NULL, &r), "refused");
    CHECK_ERROR("jostle_body_move", "got 9");
    CHECK(at(r.centre, 0.5f, 0.5f) && r.count == 0 && r.collisions == NULL, "it did not move");
    CHECK(at(jostle_body_get_position(world, item), 0.5f, 0.5f), "it is where it was");

    // Deltas: not finite, out of range.
    CHECK(!jostle_body_move(world, item, (jostle_vec2){NAN, 0}, NULL, NULL, &r), "NaN");
    CHECK_ERROR("jostle_body_move", "delta must be finite");
    CHECK(at(r.centre, 0.5f, 0.5f) && r.count == 0, "where it was");
    CHECK(!jostle_body_move(world, item, (jostle_vec2){2e9f, 0}, NULL, NULL, NULL), "too far");
    CHECK_ERROR("jostle_body_move", "1e9");

    // Stale and null handles, no world.
    CHECK(jostle_body_destroy(world, wall), "destroy");
    CHECK(!jostle_body_move(world, wall, (jostle_vec2){1, 0}, NULL, NULL, &r), "stale");
    CHECK_ERROR("jostle_body_move", "stale");
    CHECK(at(r.centre, 0, 0) && r.count == 0, "zero: there is no such body");
    CHECK(!jostle_body_move(NULL, item, (jostle_vec2){1, 0}, NULL, NULL, &r), "no world");
    CHECK_ERROR("jostle_body_move", "world is NULL");
    CHECK(jostle_world_destroy(world), "destroy");
    CHECK_NO_ERROR();
}

// --- Tile maps ---------------------------------------------------------------------------

/// The def of a map of tiles of 16 at the origin, 8 columns by 3 rows, of `cells`.
static jostle_tile_map_def tile_map_def_8x3(const unsigned char* cells) {
    jostle_tile_map_def def = jostle_default_tile_map_def();
    def.tile = 16;
    def.columns = 8;
    def.rows = 3;
    def.cells = cells;
    return def;
}

/// Tiles of 16 at the origin:      row 0  ........
///                                 row 1  #......#
///                                 row 2  ########   (top at y = 32)
static void test_tile_map(void) {
    jostle_world* world = make_world(kG);
    static const char* const rows[3] = {"........", "#......#", "########"};
    unsigned char cells[3 * 8];
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 8; ++c)
            cells[r * 8 + c] = rows[r][c] == '#';
    jostle_tile_map_def def = tile_map_def_8x3(cells);
    jostle_tile_map_id map = jostle_tile_map_create(world, &def);
    CHECK(!jostle_tile_map_id_is_null(map) && jostle_tile_map_is_valid(world, map), "created");
    CHECK(jostle_tile_map_columns(world, map) == 8 && jostle_tile_map_rows(world, map) == 3,
          "its size");
    // Two wall tiles and the floor, whose extents differ: three boxes.
    jostle_body_id parts[3];
    CHECK(jostle_tile_map_bodies(world, map, NULL, 0) == 3, "three boxes");
    CHECK(jostle_tile_map_bodies(world, map, parts, 3) == 3, "listed");
    CHECK(jostle_tile_map_id_equal(jostle_tile_map_of(world, parts[2]), map), "part of the map");
    CHECK(jostle_tile_map_is_solid(world, map, 0, 1) && !jostle_tile_map_is_solid(world, map, 1, 1),
          "cells as given");
    CHECK(!jostle_tile_map_is_solid(world, map, -1, 0) &&
              !jostle_tile_map_is_solid(world, map, 8, 2),
          "outside is empty");
    int column = -1, row = -1;
    CHECK(jostle_tile_map_tile_at(world, map, (jostle_vec2){56, 40}, &column, &row), "inside");
    CHECK(column == 3 && row == 2, "tile (3, 2)");
    CHECK(jostle_tile_map_tile_at(world, map, (jostle_vec2){48, 32}, &column, &row) &&
              column == 3 && row == 2,
          "a corner belongs to the larger column and row");
    CHECK(!jostle_tile_map_tile_at(world, map, (jostle_vec2){-1, 0}, &column, &row), "outside");
    CHECK_NO_ERROR();

    // A box of half size 4 over column 3 lands on row 2's top: y = 32 - 4 = 28.
    jostle_body_id box = add_box(world, JOSTLE_BODY_DYNAMIC, 56, 4, 4, 4);
    CHECK(jostle_tile_map_id_is_null(jostle_tile_map_of(world, box)), "not part of a map");
    for (int i = 0; i < 60; ++i)
        CHECK(jostle_world_step(world, kDt), "step");
    CHECK_NEAR(jostle_body_get_position(world, box).y, 28.0, 0.04 + 1e-3);
    CHECK(jostle_body_get_touching(world, box).floor, "standing on the tiles");

    // Dig the tile under it (x 48..64 holds the box's 52..60): it falls through.
    CHECK(jostle_tile_map_set_tile(world, map, 3, 2, false), "dig");
    CHECK(!jostle_tile_map_is_solid(world, map, 3, 2), "dug");
    for (int i = 0; i < 30; ++i)
        CHECK(jostle_world_step(world, kDt), "step");
    CHECK(jostle_body_get_position(world, box).y > 48 + 4, "fallen below the map");

    CHECK(jostle_tile_map_destroy(world, map), "destroy the map");
    CHECK(!jostle_tile_map_is_valid(world, map), "stale");
    CHECK(jostle_world_body_count(world) == 1, "its bodies are gone, the box remains");
    CHECK_NO_ERROR();
    CHECK(!jostle_tile_map_set_tile(world, map, 0, 0, true), "a stale map");
    CHECK_ERROR("jostle_tile_map_set_tile", "stale");
    CHECK(jostle_tile_map_columns(world, map) == 0, "no size");
    CHECK_ERROR("jostle_tile_map_columns", "stale");

    // Misuse of the def.
    jostle_tile_map_def bad = def;
    bad.cells = NULL;
    CHECK(jostle_tile_map_id_is_null(jostle_tile_map_create(world, &bad)), "no cells");
    CHECK_ERROR("jostle_tile_map_create", "def.cells is NULL");
    bad = def;
    bad.columns = 0;
    CHECK(jostle_tile_map_id_is_null(jostle_tile_map_create(world, &bad)), "no columns");
    CHECK_ERROR("jostle_tile_map_create", "def.columns must be >= 1");
    bad = def;
    bad.tile = 0;
    CHECK(jostle_tile_map_id_is_null(jostle_tile_map_create(world, &bad)), "tile 0");
    CHECK_ERROR("jostle_tile_map_create", "TileMapDef.tile");
    map = jostle_tile_map_create(world, &def);
    CHECK(!jostle_tile_map_set_tile(world, map, 8, 0, true), "outside the map");
    CHECK_ERROR("jostle_tile_map_set_tile", "outside the map");
    CHECK(jostle_world_destroy(world), "destroy");
    CHECK_NO_ERROR();
}

/// True if a ray straight down at x hits `map`'s tiles at y with the normal (nx, ny).
static bool ray_down_hits(jostle_world* world, float x, float y, float nx, float ny) {
    jostle_ray_hit hit;
    if (!jostle_ray_cast(world, (jostle_vec2){x, 0}, (jostle_vec2){x, 100}, NULL, &hit))
        return false;
    return fabsf(hit.point.x - x) < 1e-4f && fabsf(hit.point.y - y) < 1e-4f &&
           fabsf(hit.normal.x - nx) < 1e-6f && fabsf(hit.normal.y - ny) < 1e-6f;
}

/// Ramp tiles: the cells of a map taken straight from strings, the old 1 for a solid tile
/// beside them, and ramps set and read one tile at a time. Tiles of 16 at the origin:
///     row 0  ........
///     row 1  ./..#.rR     ('#' given as the byte 1)
///     row 2  ########     (top at y = 32)
/// The '/' at (1, 1) covers x 16..32, y 16..32 and keeps the triangle under the line from
/// (16, 32) to (32, 16): x + y = 48, its normal (-1, -1) / √2.
static void test_ramp_tiles(void) {
    jostle_world* world = make_world(kG);
    const char* level = "........"
                        "./..#.rR"
                        "########";
    unsigned char cells[3 * 8];
    memcpy(cells, level, sizeof cells);
    cells[1 * 8 + 4] = 1;
    jostle_tile_map_def def = tile_map_def_8x3(cells);
    jostle_tile_map_id map = jostle_tile_map_create(world, &def);
    CHECK(!jostle_tile_map_id_is_null(map), "created");
    // The solid tiles first, top row first: (4, 1), the floor; then the ramps: the '/' and
    // the two halves of the 2:1 ramp as one triangle.
    jostle_body_id parts[4];
    CHECK(jostle_tile_map_bodies(world, map, parts, 4) == 4, "two boxes and two ramps");
    CHECK(at(jostle_body_get_position(world, parts[2]), 24, 24) &&
              at(jostle_body_get_half_extents(world, parts[2]), 8, 8),
          "the '/' fills its tile");
    CHECK(at(jostle_body_get_def(world, parts[2]).slope, -1, -1), "a floor rising to the right");
    CHECK(at(jostle_body_get_position(world, parts[3]), 112, 24) &&
              at(jostle_body_get_half_extents(world, parts[3]), 16, 8),
          "'rR' is one triangle over two tiles");
    CHECK(at(jostle_body_get_def(world, parts[3]).slope, -1, -1), "rising to the right too");
    CHECK(jostle_tile_map_tile_of(world, map, 1, 1) == '/' &&
              jostle_tile_map_tile_of(world, map, 6, 1) == 'r' &&
              jostle_tile_map_tile_of(world, map, 7, 1) == 'R',
          "the ramps read back");
    CHECK(jostle_tile_map_tile_of(world, map, 4, 1) == '#' &&
              jostle_tile_map_tile_of(world, map, 0, 1) == '.' &&
              jostle_tile_map_tile_of(world, map, 0, 2) == '#',
          "the byte 1 is a solid tile, '.' an empty one");
    CHECK(jostle_tile_map_tile_of(world, map, -1, 0) == '.' &&
              jostle_tile_map_tile_of(world, map, 8, 2) == '.',
          "outside the map: empty");
    CHECK(!jostle_tile_map_is_solid(world, map, 1, 1) && jostle_tile_map_is_solid(world, map, 4, 1),
          "a ramp is not a solid tile");
    const float k = sqrtf(0.5f);
    CHECK(ray_down_hits(world, 28, 48 - 28, -k, -k), "down at x = 28: the slope, at y = 20");
    CHECK_NO_ERROR();

    // A '\' at (2, 1): x 32..48, y 16..32, solid under the line from (32, 16) to (48, 32),
    // y = x - 16, its normal (1, -1) / √2.
    CHECK(jostle_tile_map_set_tile_char(world, map, 2, 1, '\\'), "set a ramp");
    CHECK(jostle_tile_map_tile_of(world, map, 2, 1) == '\\', "read back");
    CHECK(jostle_tile_map_bodies(world, map, NULL, 0) == 5, "one more body");
    CHECK(ray_down_hits(world, 36, 36 - 16, k, -k), "down at x = 36: its slope, at y = 20");
    CHECK(jostle_tile_map_set_tile_char(world, map, 2, 1, '.'), "empty it again");
    CHECK(jostle_tile_map_bodies(world, map, NULL, 0) == 4, "gone");
    CHECK(ray_down_hits(world, 36, 32, 0, -1), "down at x = 36: the floor");
    // A ramp replaced by a solid tile, by either setter, and the solid tile by nothing.
    CHECK(jostle_tile_map_set_tile_char(world, map, 1, 1, '#'), "the '/' made solid");
    CHECK(jostle_tile_map_tile_of(world, map, 1, 1) == '#' &&
              jostle_tile_map_is_solid(world, map, 1, 1),
          "solid");
    CHECK(ray_down_hits(world, 28, 16, 0, -1), "down at x = 28: the tile's top");
    CHECK(jostle_tile_map_set_tile_char(world, map, 1, 1, '/'), "a ramp again");
    CHECK(jostle_tile_map_set_tile(world, map, 1, 1, false), "emptied by the bool setter");
    CHECK(jostle_tile_map_tile_of(world, map, 1, 1) == '.', "empty");
    CHECK(jostle_tile_map_bodies(world, map, NULL, 0) == 3, "the two boxes and 'rR'");
    CHECK_NO_ERROR();

    // Misuse: no change, a neutral answer.
    CHECK(!jostle_tile_map_set_tile_char(world, map, 1, 1, 'x'), "not a tile");
    CHECK_ERROR("jostle_tile_map_set_tile_char", "expected '#', '.' or a ramp, got 'x'");
    CHECK(!jostle_tile_map_set_tile_char(world, map, 8, 0, '/'), "outside");
    CHECK_ERROR("jostle_tile_map_set_tile_char", "column 8, row 0 is outside the map");
    CHECK(jostle_tile_map_tile_of(world, map, 1, 1) == '.' &&
              jostle_tile_map_bodies(world, map, NULL, 0) == 3,
          "nothing changed");
    CHECK(jostle_tile_map_tile_of(NULL, map, 0, 0) == '\0', "no world");
    CHECK_ERROR("jostle_tile_map_tile_of", "world");
    CHECK(jostle_tile_map_destroy(world, map), "destroy");
    CHECK(jostle_tile_map_tile_of(world, map, 0, 0) == '\0', "a stale map");
    CHECK_ERROR("jostle_tile_map_tile_of", "stale");
    CHECK(!jostle_tile_map_set_tile_char(world, map, 0, 0, '#'), "a stale map");
    CHECK_ERROR("jostle_tile_map_set_tile_char", "stale");
    CHECK(jostle_world_destroy(world), "destroy");

    // The classic model's bodies are sharp boxes: a map with a ramp is refused whole.
    jostle_world_def classic = jostle_default_world_def();
    classic.solver = JOSTLE_SOLVER_CLASSIC;
    world = jostle_world_create(&classic);
    CHECK(jostle_tile_map_id_is_null(jostle_tile_map_create(world, &def)), "refused");
    CHECK_ERROR("jostle_tile_map_create", "rows[1][1]: the classic model has sharp boxes only");
    CHECK(jostle_world_body_count(world) == 0, "nothing made");
    CHECK(jostle_world_destroy(world), "destroy");
    CHECK_NO_ERROR();
}

// --- The pre-solve callback --------------------------------------------------------------

typedef struct callback_state {
    jostle_world* world;
    int calls;
    bool keep;          // what to return
    float bounce;       // NaN: leave it
    bool misbehave;     // try what is refused inside a callback
    bool destroy_box;   // destroy the moving body of the pair
    bool dig;           // remove the tile under the box
    bool change_bodies; // call body setters on the pair
    jostle_tile_map_id map;
    jostle_body_id created;
    int refused;
} callback_state;

static bool pre_solve(jostle_collision* c, void* context) {
    callback_state* s = (callback_state*)context;
    ++s->calls;
    if (!isnan(s->bounce))
        c->bounce = s->bounce;
    if (s->misbehave && s->calls == 1) {
        // Refused: whatever changes the world as a whole.
        if (!jostle_world_step(s->world, kDt) &&
            strstr(jostle_last_error(), "jostle_world_step: called from a callback during "
                                        "jostle_world_step"))
            ++s->refused;
        if (!jostle_world_set_gravity(s->world, (jostle_vec2){0, 1}) &&
            strstr(jostle_last_error(), "jostle_world_set_gravity: called from a callback"))
            ++s->refused;
        if (!jostle_world_set_pre_solve(s->world, NULL, NULL))
            ++s->refused;
        if (!jostle_world_destroy(s->world))
            ++s->refused;
        if (jostle_world_state_hash(s->world) == 0 &&
            strstr(jostle_last_error(), "jostle_world_state_hash: called from a callback during "
                                        "jostle_world_step"))
            ++s->refused;
        jostle_clear_error();
        // Allowed: reading, querying, creating.
        jostle_body_id found[2];
        const jostle_vec2 at = jostle_body_get_position(s->world, c->b);
        if (jostle_query_point(s->world, at, NULL, found, 2) < 1)
            s->refused = -100;
        jostle_body_def def = jostle_default_body_def();
        def.x = 1000;
        def.hw = 1;
        def.hh = 1;
        s->created = jostle_body_create(s->world, &def);
    }
    if (s->destroy_box)
        jostle_body_destroy(s->world, c->b); // the box: created after the floor
    if (s->change_bodies) {
        // Allowed, as in C++: the solver takes the bodies as they are now. Each change to
        // the dynamic body of the pair is undone but its size's, so that the pair keeps
        // touching and the callback keeps coming.
        const jostle_body_id body =
            jostle_body_get_type(s->world, c->b) == JOSTLE_BODY_DYNAMIC ? c->b : c->a;
        const float size = 10.0f + (float)(s->calls % 5);
        jostle_body_set_type(s->world, body, JOSTLE_BODY_KINEMATIC);
        jostle_body_set_type(s->world, body, JOSTLE_BODY_DYNAMIC);
        jostle_body_set_sensor(s->world, body, true);
        jostle_body_set_sensor(s->world, body, false);
        jostle_body_set_half_extents(s->world, body, (jostle_vec2){size, 10});
        jostle_body_set_position(s->world, body, jostle_body_get_position(s->world, body));
        jostle_body_set_mass(s->world, body, size);
        jostle_body_wake(s->world, body);
    }
    if (s->dig && s->calls == 1)
        jostle_tile_map_set_tile(s->world, s->map, 3, 2, false);
    return s->keep;
}

static callback_state callback_defaults(jostle_world* world) {
    callback_state s;
    memset(&s, 0, sizeof s);
    s.world = world;
    s.keep = true;
    s.bounce = NAN;
    return s;
}

/// The landing scene of test_landing_and_contact_events, with a callback.
static jostle_world* landing_scene(callback_state* s, jostle_body_id* box) {
    jostle_world* world = make_world(kG);
    add_box(world, JOSTLE_BODY_STATIC, 0, 300, 400, 10);
    *box = add_box(world, JOSTLE_BODY_DYNAMIC, 0, 0, 10, 10);
    *s = callback_defaults(world);
    CHECK(jostle_world_set_pre_solve(world, pre_solve, s), "set pre-solve");
    return world;
}

static float lowest_vy_after(jostle_world* world, jostle_body_id box, int steps) {
    float lowest = 0;
    for (int i = 0; i < steps; ++i) {
        CHECK(jostle_world_step(world, kDt), "step");
        const float vy = jostle_body_get_velocity(world, box).y;
        if (vy < lowest)
            lowest = vy;
    }
    return lowest;
}

static void test_pre_solve(void) {
    callback_state s;
    jostle_body_id box;

    // Kept, bounce 0: the box lands and stays (never moves up faster than the slop's
    // correction could make it).
    jostle_world* world = landing_scene(&s, &box);
    CHECK(lowest_vy_after(world, box, 90) > -1, "no bounce");
    CHECK(s.calls > 0, "called");
    CHECK(jostle_world_destroy(world), "destroy");

    // Bounce 1 from the callback: it leaves the floor at about its landing speed, 669.
    world = landing_scene(&s, &box);
    s.bounce = 1;
    CHECK(lowest_vy_after(world, box, 90) < -600, "bounced");
    CHECK(jostle_world_destroy(world), "destroy");

    // Vetoed: the box falls through the floor.
    world = landing_scene(&s, &box);
    s.keep = false;
    run(world, 90);
    CHECK(jostle_body_get_position(world, box).y > 310, "fell through");
    CHECK(s.calls > 0, "asked");
    CHECK(jostle_world_destroy(world), "destroy");

    // What a callback may not do is refused; what it may do works.
    world = landing_scene(&s, &box);
    s.misbehave = true;
    run(world, 90);
    CHECK(s.refused == 5, "step, set_gravity, set_pre_solve, destroy and state_hash refused");
    CHECK(jostle_body_is_valid(world, s.created), "created from the callback");
    CHECK(jostle_world_get_gravity(world).y == kG, "gravity unchanged");
    CHECK(jostle_world_step(world, kDt), "stepping again after the callback");
    CHECK(jostle_world_set_pre_solve(world, NULL, NULL), "removed outside a step");
    CHECK(jostle_world_destroy(world), "destroy");
    CHECK_NO_ERROR();

    // Destroying the box from the callback is safe: it leaves the step at once.
    world = landing_scene(&s, &box);
    s.destroy_box = true;
    run(world, 60);
    CHECK(!jostle_body_is_valid(world, box), "destroyed");
    CHECK(s.calls == 1, "asked once: the pair is gone");
    CHECK(jostle_world_body_count(world) == 1, "the floor alone");
    CHECK(jostle_world_destroy(world), "destroy");
    CHECK_NO_ERROR();

    // Body setters from the callback, in both models: the steps go on.
    for (int model = 0; model < 2; ++model) {
        world = landing_scene(&s, &box);
        CHECK(
            jostle_world_set_solver(world, model ? JOSTLE_SOLVER_CLASSIC : JOSTLE_SOLVER_PHYSICAL),
            "model");
        add_box(world, JOSTLE_BODY_DYNAMIC, 5, -30, 10, 10); // a pile, for more pairs
        s.change_bodies = true;
        run(world, 120);
        // The box lands after 0.84 s, sqrt(2 * 280 / g), step 51 of 120; from then on the
        // callback comes at least once a step.
        CHECK(s.calls >= 120 - 51, "called step after step");
        CHECK(jostle_world_destroy(world), "destroy");
        CHECK_NO_ERROR();
    }

    // Digging a tile from the callback: the box falls through the hole.
    world = make_world(kG);
    unsigned char cells[3 * 8] = {0};
    memset(cells + 2 * 8, 1, 8); // row 2 solid, at y 32..48 as in test_tile_map
    jostle_tile_map_def def = tile_map_def_8x3(cells);
    s = callback_defaults(world);
    s.map = jostle_tile_map_create(world, &def);
    s.dig = true;
    box = add_box(world, JOSTLE_BODY_DYNAMIC, 56, 4, 4, 4);
    CHECK(jostle_world_set_pre_solve(world, pre_solve, &s), "set pre-solve");
    run(world, 60);
    CHECK(!jostle_tile_map_is_solid(world, s.map, 3, 2), "dug from the callback");
    CHECK(jostle_body_get_position(world, box).y > 48 + 4, "fell through the hole");
    CHECK(jostle_world_destroy(world), "destroy");
    CHECK_NO_ERROR();
}

// --- The fixed step ----------------------------------------------------------------------

static void test_fixed_step(void) {
    jostle_fixed_step* clock = jostle_fixed_step_create(kDt, 8);
    CHECK(clock != NULL, "created");
    CHECK(jostle_fixed_step_dt(clock) == kDt && jostle_fixed_step_max_steps_per_frame(clock) == 8,
          "its settings");
    CHECK(jostle_fixed_step_advance(clock, kDt) == 1 && jostle_fixed_step_alpha(clock) == 0,
          "a frame of dt is a step");
    CHECK(jostle_fixed_step_advance(clock, kDt / 2) == 0, "half a step waits");
    CHECK_NEAR(jostle_fixed_step_alpha(clock), 0.5, 1e-6);

    // The other half, through update: one step of the world, v = g dt.
    jostle_world* world = make_world(kG);
    jostle_body_id box = add_box(world, JOSTLE_BODY_DYNAMIC, 0, 0, 1, 1);
    CHECK(jostle_fixed_step_update(clock, world, kDt / 2) == 1, "one step");
    CHECK_NEAR(jostle_body_get_velocity(world, box).y, kG * kDt, 1e-4);

    // A second's frame is 60 steps, 8 taken, 52 dropped.
    CHECK(jostle_fixed_step_advance(clock, 1.0f) == 8, "capped");
    CHECK_NEAR(jostle_fixed_step_dropped_seconds(clock), 52.0 / 60.0, 1e-6);
    CHECK(jostle_fixed_step_reset(clock) && jostle_fixed_step_alpha(clock) == 0, "reset");

    // Misuse: nothing counted.
    CHECK(jostle_fixed_step_advance(clock, kDt / 2) == 0, "half a step");
    CHECK(jostle_fixed_step_update(clock, NULL, kDt / 2) == 0, "no world");
    CHECK_ERROR("jostle_fixed_step_update", "world is NULL");
    CHECK_NEAR(jostle_fixed_step_alpha(clock), 0.5, 1e-6); // the frame was not counted
    CHECK(jostle_fixed_step_advance(clock, -1) == 0, "negative frame");
    CHECK_ERROR("jostle_fixed_step_advance", "frameSeconds");
    CHECK(jostle_fixed_step_create(0, 8) == NULL, "dt 0");
    CHECK_ERROR("jostle_fixed_step_create", "dt");
    CHECK(jostle_fixed_step_create(kDt, 0) == NULL, "no steps");
    CHECK_ERROR("jostle_fixed_step_create", "maxStepsPerFrame");
    CHECK(jostle_fixed_step_alpha(NULL) == 0, "no clock");
    CHECK_ERROR("jostle_fixed_step_alpha", "clock is NULL");
    jostle_fixed_step_destroy(NULL);
    jostle_fixed_step_destroy(clock);
    CHECK(jostle_world_destroy(world), "destroy");
    CHECK_NO_ERROR();
}

/// Counts the contacts that began in each step jostle_fixed_step_update_each takes.
static void count_begins(jostle_world* world, void* context) {
    int count = 0;
    jostle_world_contact_begins(world, &count);
    *(int*)context += count;
}

/// Three boxes landing on a floor in the first, third and sixth of one frame's eight steps
/// (fallen g dt^2 n (n + 1) / 2 after n steps: 0.28, then 0.83 and 1.67 after two and three,
/// 4.17 and 5.83 after five and six; gaps of 0.1, 1 and 4.5): each step's begins reach the
/// game through jostle_fixed_step_update_each, only the last step's after an update.
static void test_fixed_step_events_of_each_step(void) {
    int seen[2] = {0, 0};
    for (int each = 0; each < 2; ++each) {
        jostle_world* world = make_world(1000);
        add_box(world, JOSTLE_BODY_STATIC, 0, 10, 100, 10);
        const float gaps[] = {0.1f, 1.0f, 4.5f};
        for (int i = 0; i < 3; ++i)
            add_box(world, JOSTLE_BODY_DYNAMIC, 10 * gaps[i], -1 - gaps[i], 1, 1);
        jostle_fixed_step* clock = jostle_fixed_step_create(1.0f / 60.0f, 8);
        if (each)
            CHECK(jostle_fixed_step_update_each(clock, world, 8.0f / 60.0f, count_begins,
                                                &seen[each]) == 8,
                  "eight steps");
        else {
            CHECK(jostle_fixed_step_update(clock, world, 8.0f / 60.0f) == 8, "eight steps");
            count_begins(world, &seen[each]);
        }
        jostle_fixed_step_destroy(clock);
        CHECK(jostle_world_destroy(world), "destroy");
    }
    CHECK(seen[1] == 3, "every landing, read after each step");
    CHECK(seen[0] < 3, "the last step's landings alone, read after the frame");
    CHECK_NO_ERROR();
}

/// Steps of 0.25 s; a box moving at 4 units/s covers 1 unit a step, so its positions after
/// each step are whole numbers and where it is drawn between them is alpha.
static void test_draw_positions(void) {
    jostle_world* world = make_world(0);
    jostle_body_def def = jostle_default_body_def();
    def.hw = 1;
    def.hh = 1;
    def.vx = 4;
    jostle_body_id box = jostle_body_create(world, &def);
    jostle_fixed_step* clock = jostle_fixed_step_create(0.25f, 8);
    jostle_vec2 p = jostle_fixed_step_draw_position(clock, world, box);
    CHECK(p.x == 0 && p.y == 0, "nothing stepped yet: where it is");
    CHECK(jostle_fixed_step_update(clock, world, 0.375f) == 1, "1.5 steps: at 1, alpha 0.5");
    CHECK_NEAR(jostle_fixed_step_draw_position(clock, world, box).x, 0.5, 1e-6);
    CHECK(jostle_fixed_step_update(clock, world, 0.5f) == 2, "2 steps: at 3, alpha 0.5");
    CHECK_NEAR(jostle_fixed_step_draw_position(clock, world, box).x, 2.5, 1e-6);
    CHECK(jostle_fixed_step_update(clock, world, 0.125f) == 1, "0.125 + 0.125: at 4, alpha 0");
    CHECK_NEAR(jostle_fixed_step_draw_position(clock, world, box).x, 3.0, 1e-6);
    CHECK(jostle_fixed_step_update(clock, world, 0.125f) == 0, "no step: alpha 0.5");
    CHECK_NEAR(jostle_fixed_step_draw_position(clock, world, box).x, 3.5, 1e-6);

    // Stepped by hand: remembered before the step, drawn between 4 and 5 by alpha 0.5.
    CHECK(jostle_fixed_step_advance(clock, 0.25f) == 1, "one step due");
    CHECK(jostle_fixed_step_remember_positions(clock, world), "remembered");
    CHECK(jostle_world_step(world, 0.25f), "stepped by hand");
    CHECK_NEAR(jostle_fixed_step_draw_position(clock, world, box).x, 4.5, 1e-6);
    // Reset: the time and where bodies were forgotten: drawn where it is.
    CHECK(jostle_fixed_step_reset(clock), "reset");
    CHECK(jostle_fixed_step_draw_position(clock, world, box).x == 5, "drawn where it is");
    CHECK(!jostle_fixed_step_remember_positions(clock, NULL), "no world");
    CHECK_ERROR("jostle_fixed_step_remember_positions", "world is NULL");

    // A body made since the last step is drawn where it is; all at once, in list order.
    def.x = 7;
    jostle_body_id late = jostle_body_create(world, &def);
    p = jostle_fixed_step_draw_position(clock, world, late);
    CHECK(p.x == 7 && p.y == 0, "where it is");
    jostle_vec2 all[3] = {{-1, -1}, {-1, -1}, {-1, -1}};
    CHECK(jostle_fixed_step_read_draw_positions(clock, world, all, 3) == 2, "two bodies");
    CHECK(all[0].x == 5, "the box where it is, since the reset");
    CHECK(all[1].x == 7 && all[1].y == 0 && all[2].x == -1, "the new one, nothing beyond");
    CHECK(jostle_fixed_step_read_draw_positions(clock, world, all, 1) == 2, "the full count");
    CHECK(jostle_fixed_step_read_draw_positions(clock, world, NULL, 0) == 2, "the count alone");

    // A slot reused by another body is not mistaken for the old one.
    CHECK(jostle_body_destroy(world, box), "destroyed");
    def.x = -5;
    def.vx = 0;
    jostle_body_id reused = jostle_body_create(world, &def);
    p = jostle_fixed_step_draw_position(clock, world, reused);
    CHECK(p.x == -5 && p.y == 0, "the new body where it is");
    CHECK_NO_ERROR();

    p = jostle_fixed_step_draw_position(clock, world, box);
    CHECK(p.x == 0 && p.y == 0, "zero");
    CHECK_ERROR("jostle_fixed_step_draw_position", "stale");
    CHECK(jostle_fixed_step_draw_position(NULL, world, reused).x == 0, "no clock");
    CHECK_ERROR("jostle_fixed_step_draw_position", "clock is NULL");
    CHECK(jostle_fixed_step_read_draw_positions(clock, NULL, all, 3) == 0, "no world");
    CHECK_ERROR("jostle_fixed_step_read_draw_positions", "world is NULL");
    CHECK(jostle_fixed_step_read_draw_positions(clock, world, NULL, 3) == 0, "no buffer");
    CHECK_ERROR("jostle_fixed_step_read_draw_positions", "out is NULL but capacity is 3");
    jostle_fixed_step_destroy(clock);
    CHECK(jostle_world_destroy(world), "destroy");
    CHECK_NO_ERROR();
}

// --- Misuse ------------------------------------------------------------------------------

typedef struct handler_log {
    int calls;
    char last[512];
} handler_log;

static void log_error(const char* message, void* context) {
    handler_log* log = (handler_log*)context;
    ++log->calls;
    snprintf(log->last, sizeof log->last, "%s", message);
    // A misuse inside the handler is recorded, and does not call the handler again.
    jostle_world_step(NULL, 0);
}

static void test_misuse(void) {
    const jostle_vec2 nan2 = {NAN, 0};
    jostle_body_def def = jostle_default_body_def();
    def.hw = 1;
    def.hh = 1;

    // A NULL world: every kind of function.
    CHECK(!jostle_world_step(NULL, kDt), "step");
    CHECK_ERROR("jostle_world_step", "world is NULL");
    CHECK(jostle_body_id_is_null(jostle_body_create(NULL, &def)), "create");
    CHECK_ERROR("jostle_body_create", "world is NULL");
    jostle_body_id some = {1, 1, 1};
    jostle_vec2 p = jostle_body_get_position(NULL, some);
    CHECK(p.x == 0 && p.y == 0, "a zero vector");
    CHECK_ERROR("jostle_body_get_position", "world is NULL");
    CHECK(!jostle_body_set_position(NULL, some, p), "set");
    CHECK_ERROR("jostle_body_set_position", "world is NULL");
    CHECK(!jostle_body_is_valid(NULL, some), "is_valid");
    CHECK_ERROR("jostle_body_is_valid", "world is NULL");
    CHECK(jostle_world_body_count(NULL) == 0, "count");
    CHECK_ERROR("jostle_world_body_count", "world is NULL");
    CHECK(jostle_world_get_solver(NULL) == JOSTLE_SOLVER_CLASSIC, "the enum of value 0");
    CHECK_ERROR("jostle_world_get_solver", "world is NULL");
    CHECK(jostle_query_point(NULL, p, NULL, NULL, 0) == 0, "query");
    CHECK_ERROR("jostle_query_point", "world is NULL");
    int count = 5;
    CHECK(jostle_world_contact_begins(NULL, &count) == NULL && count == 0, "events");
    CHECK_ERROR("jostle_world_contact_begins", "world is NULL");
    CHECK(jostle_tile_map_rows(NULL, (jostle_tile_map_id){1, 1, 1}) == 0, "tile map");
    CHECK_ERROR("jostle_tile_map_rows", "world is NULL");
    CHECK(jostle_world_destroy(NULL), "destroying NULL is not an error, as with free");
    CHECK_NO_ERROR();

    // Worlds: a NULL, zeroed or out-of-range def.
    CHECK(jostle_world_create(NULL) == NULL, "no def");
    CHECK_ERROR("jostle_world_create", "def is NULL");
    jostle_world_def wdef;
    memset(&wdef, 0, sizeof wdef);
    wdef.max_velocity = 1;
    wdef.physical.velocity_iterations = 1;
    wdef.physical.correction = 1;
    CHECK(jostle_world_create(&wdef) == NULL, "a def not from jostle_default_world_def");
    CHECK_ERROR("jostle_world_create", "def was not made by jostle_default_world_def()");
    wdef = jostle_default_world_def();
    wdef.max_velocity = 0;
    CHECK(jostle_world_create(&wdef) == NULL, "max velocity 0");
    CHECK_ERROR("jostle_world_create", "WorldDef.maxVelocity: must be > 0");
    wdef = jostle_default_world_def();
    wdef.solver = (jostle_solver)7;
    CHECK(jostle_world_create(&wdef) == NULL, "an unknown solver");
    CHECK_ERROR("jostle_world_create", "solver must be JOSTLE_SOLVER_CLASSIC");

    jostle_world* world = make_world(kG);
    jostle_body_id box = jostle_body_create(world, &def);

    // Bodies: sizes, numbers, enums, a zeroed def.
    jostle_body_def bad = def;
    bad.hw = 0;
    CHECK(jostle_body_id_is_null(jostle_body_create(world, &bad)), "hw 0");
    CHECK(strcmp(jostle_last_error(), "jostle_body_create: createBody: BodyDef.hw: must be > 0") ==
              0,
          "the message names the function, the member and the rule");
    jostle_clear_error();
    bad = def;
    bad.hh = -1;
    CHECK(jostle_body_id_is_null(jostle_body_create(world, &bad)), "hh < 0");
    CHECK_ERROR("jostle_body_create", "BodyDef.hh: must be > 0");
    bad = def;
    bad.x = NAN;
    CHECK(jostle_body_id_is_null(jostle_body_create(world, &bad)), "NaN");
    CHECK_ERROR("jostle_body_create", "BodyDef.x: must be a finite number");
    bad = def;
    bad.type = (jostle_body_type)7;
    CHECK(jostle_body_id_is_null(jostle_body_create(world, &bad)), "an unknown type");
    CHECK_ERROR("jostle_body_create", "got 7");
    bad = def;
    bad.type = JOSTLE_BODY_STATIC;
    bad.vx = 1;
    CHECK(jostle_body_id_is_null(jostle_body_create(world, &bad)), "a moving static body");
    CHECK_ERROR("jostle_body_create", "static body cannot move");
    memset(&bad, 0, sizeof bad);
    bad.hw = 1;
    bad.hh = 1;
    bad.density = 1;
    CHECK(jostle_body_id_is_null(jostle_body_create(world, &bad)), "a zeroed def");
    CHECK_ERROR("jostle_body_create", "def was not made by jostle_default_body_def()");
    CHECK(jostle_body_id_is_null(jostle_body_create(world, NULL)), "no def");
    CHECK_ERROR("jostle_body_create", "def is NULL");
    CHECK(jostle_world_body_count(world) == 1, "nothing was created");

    // Setters: a refused value changes nothing.
    CHECK(jostle_body_set_position(world, box, (jostle_vec2){3, 4}), "a good position");
    CHECK(!jostle_body_set_position(world, box, nan2), "NaN");
    CHECK_ERROR("jostle_body_set_position", "finite");
    p = jostle_body_get_position(world, box);
    CHECK(p.x == 3 && p.y == 4, "unchanged");
    CHECK(!jostle_body_set_half_extents(world, box, (jostle_vec2){0, 1}), "size 0");
    CHECK_ERROR("jostle_body_set_half_extents", "must be > 0");
    CHECK(!jostle_body_set_bounce(world, box, 2), "bounce 2");
    CHECK_ERROR("jostle_body_set_bounce", "[0, 1]");
    CHECK(!jostle_body_set_type(world, box, (jostle_body_type)-1), "type -1");
    CHECK_ERROR("jostle_body_set_type", "got -1");
    CHECK(jostle_body_get_type(world, box) == JOSTLE_BODY_DYNAMIC, "type unchanged");
    CHECK(!jostle_body_set_one_way(world, box, (jostle_vec2){1, 1}), "a diagonal one-way");
    CHECK_ERROR("jostle_body_set_one_way", "normal");

    // Stale handles: an ordinary false for is_valid, misuse anywhere else.
    CHECK(jostle_body_destroy(world, box), "destroyed");
    CHECK(!jostle_body_is_valid(world, box), "stale");
    CHECK_NO_ERROR();
    CHECK(!jostle_body_set_position(world, box, (jostle_vec2){0, 0}), "stale");
    CHECK_ERROR("jostle_body_set_position", "stale BodyId (the body was destroyed)");
    CHECK(!jostle_body_destroy(world, box), "twice");
    CHECK_ERROR("jostle_body_destroy", "stale");
    p = jostle_body_get_velocity(world, box);
    CHECK(p.x == 0 && p.y == 0, "zero");
    CHECK_ERROR("jostle_body_get_velocity", "stale");
    CHECK(!jostle_body_get_touching(world, box).floor, "zero");
    CHECK_ERROR("jostle_body_get_touching", "stale");
    jostle_body_def gone = jostle_body_get_def(world, box);
    CHECK(gone.hw == 0 && gone.internal_cookie == 0, "all zeros");
    CHECK_ERROR("jostle_body_get_def", "stale");
    jostle_body_id null_id = {0, 0, 0};
    CHECK(!jostle_body_wake(world, null_id), "null handle");
    CHECK_ERROR("jostle_body_wake", "null BodyId");

    // Steps: dt <= 0, NaN, infinite.
    CHECK(!jostle_world_step(world, 0), "dt 0");
    CHECK_ERROR("jostle_world_step", "dt must be a finite number > 0");
    CHECK(!jostle_world_step(world, -kDt), "dt < 0");
    CHECK_ERROR("jostle_world_step", "dt must be");
    CHECK(!jostle_world_step(world, NAN), "NaN");
    CHECK_ERROR("jostle_world_step", "dt must be");
    CHECK(!jostle_world_step(world, INFINITY), "infinite");
    CHECK_ERROR("jostle_world_step", "dt must be");

    // World settings.
    CHECK(!jostle_world_set_gravity(world, nan2), "NaN gravity");
    CHECK_ERROR("jostle_world_set_gravity", "finite");
    CHECK(!jostle_world_set_max_velocity(world, -1), "max velocity < 0");
    CHECK_ERROR("jostle_world_set_max_velocity", "maxVelocity must be > 0");
    CHECK(!jostle_world_set_solver(world, (jostle_solver)2), "an unknown solver");
    CHECK_ERROR("jostle_world_set_solver", "got 2");
    jostle_physical_options options = jostle_world_get_physical_options(world);
    options.slop = 0.9f;
    CHECK(!jostle_world_set_physical_options(world, options), "slop out of range");
    CHECK_ERROR("jostle_world_set_physical_options", "slop");
    CHECK(jostle_world_get_physical_options(world).slop == 0.01f, "unchanged");
    CHECK(jostle_world_get_gravity(world).y == kG, "unchanged");

    // Buffers and output pointers.
    jostle_body_id out[2];
    CHECK(jostle_world_bodies(world, out, -1) == 0, "capacity < 0");
    CHECK_ERROR("jostle_world_bodies", "capacity must be >= 0");
    CHECK(jostle_query_point(world, p, NULL, NULL, 2) == 0, "NULL buffer with room");
    CHECK_ERROR("jostle_query_point", "out is NULL but capacity is 2");
    CHECK(jostle_world_contact_begins(world, NULL) == NULL, "no count");
    CHECK_ERROR("jostle_world_contact_begins", "count is NULL");
    CHECK(!jostle_ray_cast(world, p, (jostle_vec2){0, 1}, NULL, NULL), "no hit");
    CHECK_ERROR("jostle_ray_cast", "hit is NULL");
    jostle_ray_hit hit;
    CHECK(!jostle_ray_cast(world, nan2, (jostle_vec2){0, 1}, NULL, &hit), "NaN ray");
    CHECK_ERROR("jostle_ray_cast", "finite");
    jostle_query_filter filter = jostle_default_query_filter();
    filter.ignore = box; // destroyed above
    CHECK(jostle_query_point(world, p, &filter, NULL, 0) == 0, "a stale ignore");
    CHECK_ERROR("jostle_query_point", "QueryFilter.ignore");
    memset(&filter, 0, sizeof filter);
    CHECK(jostle_query_point(world, p, &filter, NULL, 0) == 0, "a zeroed filter");
    CHECK_ERROR("jostle_query_point", "filter was not made by jostle_default_query_filter()");
    jostle_vec2 end = {9, 9};
    const jostle_vec2 from = {1, 2};
    CHECK(jostle_move_and_slide(world, from, (jostle_vec2){0, 1}, (jostle_vec2){5, 0}, NULL, &end,
                                NULL, 0) == 0,
          "half 0");
    CHECK_ERROR("jostle_move_and_slide", "half must be > 0");
    CHECK(end.x == 1 && end.y == 2, "the box stays where it was");
    CHECK(jostle_move_and_slide(world, from, (jostle_vec2){1, 1}, (jostle_vec2){5, 0}, NULL, NULL,
                                NULL, 0) == 0,
          "no new_centre");
    CHECK_ERROR("jostle_move_and_slide", "new_centre is NULL");

    // The error contract: sticky until cleared, and the handler sees every misuse.
    CHECK(!jostle_world_step(world, 0), "a misuse");
    CHECK(jostle_world_step(world, kDt), "a success after it");
    CHECK_ERROR("jostle_world_step", "dt"); // still there
    CHECK_NO_ERROR();

    handler_log log;
    memset(&log, 0, sizeof log);
    jostle_set_error_handler(log_error, &log);
    CHECK(!jostle_body_set_bounce(world, null_id, 0), "a misuse");
    CHECK(log.calls == 1, "the handler was called once");
    CHECK(strncmp(log.last, "jostle_body_set_bounce: ", 24) == 0, "with the message");
    CHECK_ERROR("jostle_world_step", "world is NULL"); // the handler's own misuse
    jostle_set_error_handler(NULL, NULL);
    CHECK(!jostle_body_set_bounce(world, null_id, 0), "another misuse");
    CHECK(log.calls == 1, "removed");
    jostle_clear_error();

    CHECK(jostle_world_destroy(world), "destroy");
    CHECK_NO_ERROR();
}

// --- Handles of other worlds ---------------------------------------------------------------

/// A world with one box at (x, 0), in slot 0.
static jostle_world* world_with_a_box(float x, jostle_body_id* box) {
    jostle_world* world = make_world(0);
    *box = add_box(world, JOSTLE_BODY_DYNAMIC, x, 0, 1, 1);
    CHECK(box->index == 0, "slot 0");
    return world;
}

/// Issue 19: a handle of another world is refused, even where its slot and generation
/// name a live body of this world. Until each handle carried its world, the world made
/// 28,657 worlds after another started its generations 52,777 above the other's, so that
/// after as many reuses of slot 0 the two worlds' handles there were equal and
/// jostle_body_set_position moved this world's own body.
static void test_a_handle_of_another_world(void) {
    jostle_body_id mine;
    jostle_world* world = world_with_a_box(0, &mine);
    for (int i = 1; i < 28657; ++i) {
        jostle_world_def def = jostle_default_world_def();
        CHECK(jostle_world_destroy(jostle_world_create(&def)), "an intervening world");
    }
    jostle_body_id theirs;
    jostle_world* other = world_with_a_box(5, &theirs);
    for (int i = 0; i < 52777; ++i) {
        CHECK(jostle_body_destroy(world, mine), "destroyed");
        mine = add_box(world, JOSTLE_BODY_DYNAMIC, 0, 0, 1, 1);
    }
    CHECK(mine.index == theirs.index, "the same slot");
    CHECK(!jostle_body_is_valid(world, theirs), "another world's handle is not valid here");
    CHECK_NO_ERROR();
    CHECK(!jostle_body_set_position(world, theirs, (jostle_vec2){100, 100}), "refused");
    CHECK_ERROR("jostle_body_set_position", "BodyId of another world");
    CHECK(at(jostle_body_get_position(world, mine), 0, 0), "this world's body did not move");
    CHECK(at(jostle_body_get_position(other, theirs), 5, 0), "nor the other world's");
    CHECK(jostle_world_destroy(other), "destroy");

    // Two worlds' first bodies: the same slot and generation, told apart by their world.
    jostle_world* third = world_with_a_box(7, &theirs);
    jostle_body_id first;
    jostle_world* fourth = world_with_a_box(9, &first);
    CHECK(theirs.index == first.index && theirs.generation == first.generation,
          "the same slot and generation");
    CHECK(theirs.world != first.world && !jostle_body_id_equal(theirs, first), "not equal");
    CHECK(!jostle_body_is_valid(fourth, theirs) && !jostle_body_is_valid(third, first),
          "neither valid in the other world");
    CHECK(!jostle_body_destroy(fourth, theirs), "refused");
    CHECK_ERROR("jostle_body_destroy", "BodyId of another world");
    CHECK(jostle_world_body_count(fourth) == 1, "nothing destroyed");

    // Tile maps too.
    static const unsigned char cells[2] = {'#', '#'};
    jostle_tile_map_def map_def = jostle_default_tile_map_def();
    map_def.tile = 4;
    map_def.columns = 2;
    map_def.rows = 1;
    map_def.cells = cells;
    const jostle_tile_map_id map = jostle_tile_map_create(third, &map_def);
    const jostle_tile_map_id other_map = jostle_tile_map_create(fourth, &map_def);
    CHECK(map.index == other_map.index && map.generation == other_map.generation,
          "the same slot and generation");
    CHECK(!jostle_tile_map_id_equal(map, other_map), "not equal");
    CHECK(!jostle_tile_map_is_valid(fourth, map), "another world's map");
    CHECK_NO_ERROR();
    CHECK(!jostle_tile_map_set_tile(fourth, map, 0, 0, false), "refused");
    CHECK_ERROR("jostle_tile_map_set_tile", "TileMapId of another world");

    CHECK(jostle_world_destroy(third) && jostle_world_destroy(fourth) &&
              jostle_world_destroy(world),
          "destroy");
    CHECK_NO_ERROR();
}

// --- Threads ------------------------------------------------------------------------------

/// A job system that runs every range at once, on the calling thread, counting its calls.
static void* run_at_once(jostle_task_fn task, uint32_t items, uint32_t min_range,
                         void* task_context, void* user_context) {
    (void)min_range;
    ++*(int*)user_context;
    task(0, items, 0, task_context);
    return NULL;
}
static void finish_nothing(void* user_task, void* user_context) {
    (void)user_task;
    (void)user_context;
}

/// A crowd of boxes on a floor, 4,000 of them: the step cuts its loops into blocks.
static jostle_world* crowd(jostle_task_system tasks) {
    jostle_world_def def = jostle_default_world_def();
    def.gravity.y = 800;
    def.tasks = tasks;
    jostle_world* world = jostle_world_create(&def);
    CHECK(world, "a world with threads");
    jostle_body_def floor = jostle_default_body_def();
    floor.type = JOSTLE_BODY_STATIC;
    floor.y = 1000;
    floor.hw = 2000;
    floor.hh = 10;
    jostle_body_create(world, &floor);
    for (int i = 0; i < 4000; ++i) {
        jostle_body_def box = jostle_default_body_def();
        box.x = (float)(i % 100) * 12.0f;
        box.y = (float)(i / 100) * 12.0f;
        box.hw = box.hh = 5;
        box.vx = (float)(i % 7) * 10.0f - 30.0f;
        jostle_body_create(world, &box);
    }
    return world;
}

static void test_workers(void) {
    jostle_task_system alone = jostle_default_world_def().tasks;
    CHECK(alone.workers == 1 && !alone.enqueue_task && !alone.finish_task,
          "one worker, no job system by default");

    jostle_task_system own = alone;
    own.workers = 2;
    int calls = 0;
    jostle_task_system game = alone;
    game.workers = 3;
    game.enqueue_task = run_at_once;
    game.finish_task = finish_nothing;
    game.user_context = &calls;
    jostle_world* one = crowd(alone);
    jostle_world* two = crowd(own);
    jostle_world* jobs = crowd(game);
    CHECK(jostle_world_get_workers(two) == 2 && jostle_world_get_workers(jobs) == 3, "workers");
    run(one, 30);
    run(two, 30);
    run(jobs, 30);
    CHECK(calls > 0, "the game's job system was handed work");
    const jostle_step_profile p = jostle_world_get_profile(two);
    const float stages = p.riders + p.velocities + p.pairs + p.corners + p.contacts + p.support +
                         p.impacts + p.layers + p.solve + p.shock + p.bounces + p.sweeps +
                         p.positions + p.correction + p.snap + p.store + p.events + p.sleep;
    CHECK(p.step > 0.0f && p.pairs > 0.0f && stages <= p.step * 1.001f,
          "the last step's profile: its stages are laps within it");
    // The same bits at any worker count, under any job system.
    enum { kBodies = 4001 };
    static jostle_vec2 p1[kBodies], p2[kBodies], p3[kBodies];
    CHECK(jostle_world_read_positions(one, p1, kBodies) == kBodies &&
              jostle_world_read_positions(two, p2, kBodies) == kBodies &&
              jostle_world_read_positions(jobs, p3, kBodies) == kBodies,
          "read positions");
    CHECK(memcmp(p1, p2, sizeof p1) == 0 && memcmp(p1, p3, sizeof p1) == 0,
          "the same positions at 1, 2 and 3 workers");

    // Out of range, or half a job system: refused, with the field named.
    jostle_world_def bad = jostle_default_world_def();
    bad.tasks.workers = 0;
    CHECK(!jostle_world_create(&bad), "0 workers refused");
    CHECK_ERROR("jostle_world_create", "tasks.workers");
    bad.tasks.workers = 2;
    bad.tasks.enqueue_task = run_at_once;
    CHECK(!jostle_world_create(&bad), "enqueue_task without finish_task refused");
    CHECK_ERROR("jostle_world_create", "tasks");
    CHECK(jostle_world_destroy(one) && jostle_world_destroy(two) && jostle_world_destroy(jobs),
          "destroy");
    CHECK_NO_ERROR();
}

/// A job system that breaks the contract: it runs every range twice.
static void* run_twice(jostle_task_fn task, uint32_t items, uint32_t min_range, void* task_context,
                       void* user_context) {
    (void)min_range;
    (void)user_context;
    task(0, items, 0, task_context);
    task(0, items, 0, task_context);
    return NULL;
}

static void test_a_job_system_that_breaks_the_contract(void) {
    jostle_task_system good = jostle_default_world_def().tasks;
    good.workers = 3;
    int calls = 0;
    good.enqueue_task = run_at_once;
    good.finish_task = finish_nothing;
    good.user_context = &calls;
    jostle_task_system twice = good;
    twice.enqueue_task = run_twice;
    jostle_world* right = crowd(good);
    jostle_world* wrong = crowd(twice);
    for (int i = 0; i < 5; ++i) {
        CHECK(jostle_world_step(right, 1.0f / 60.0f), "a good job system");
        CHECK(!jostle_world_step(wrong, 1.0f / 60.0f), "a job system that runs ranges twice");
        CHECK_ERROR("jostle_world_step", "task system broke its contract");
    }
    // Each item was run once all the same: the same bits as the good job system.
    enum { kBodies = 4001 };
    static jostle_vec2 a[kBodies], b[kBodies];
    CHECK(jostle_world_read_positions(right, a, kBodies) == kBodies &&
              jostle_world_read_positions(wrong, b, kBodies) == kBodies,
          "read positions");
    CHECK(memcmp(a, b, sizeof a) == 0, "the same positions whatever the job system did");
    CHECK(jostle_world_destroy(right) && jostle_world_destroy(wrong), "destroy");
}

/// A world whose threads the system will not start is refused, not a terminated process.
/// Kept from starting by a limit on the address space, which a sanitizer cannot live with.
static void test_threads_that_cannot_start(void) {
#ifndef SANITIZED
    struct rlimit was;
    CHECK(getrlimit(RLIMIT_AS, &was) == 0, "getrlimit");
    FILE* statm = fopen("/proc/self/statm", "r");
    unsigned long pages = 0;
    CHECK(statm && fscanf(statm, "%lu", &pages) == 1, "/proc/self/statm");
    fclose(statm);
    struct rlimit tight = was;
    tight.rlim_cur = pages * (unsigned long)sysconf(_SC_PAGESIZE) + (48ul << 20);
    CHECK(setrlimit(RLIMIT_AS, &tight) == 0, "setrlimit");
    jostle_world_def def = jostle_default_world_def();
    def.tasks.workers = 64;
    jostle_world* world = jostle_world_create(&def);
    setrlimit(RLIMIT_AS, &was);
    CHECK(!world, "64 workers in 48 MB refused");
    CHECK_ERROR("jostle_world_create", "the system would start only");
#endif
}

/// The messages of one rule in C's words (docs/reliability.md, "Misuse of the APIs"): the
/// C++ library's, in its notation, which is C's too ({0, -1}, as a jostle_vec2 is written).
/// C has no unknown fields (its definitions are structs) and no ragged tile maps (cells
/// are a grid): those messages are the other languages'.
static void test_messages(void) {
    jostle_world_def world_def = jostle_default_world_def();
    jostle_world* world = jostle_world_create(&world_def);
    jostle_body_def def = jostle_default_body_def();
    def.hw = def.hh = 1;
    def.one_way = (jostle_vec2){1, 1};
    CHECK(jostle_body_id_is_null(jostle_body_create(world, &def)), "a diagonal one-way");
    CHECK_MESSAGE("jostle_body_create: createBody: BodyDef.oneWay: must be {0, 0} or one of "
                  "{1, 0}, {-1, 0}, {0, 1}, {0, -1}");
    def.one_way = (jostle_vec2){0, 0};
    const jostle_body_id crate = jostle_body_create(world, &def);
    CHECK(!jostle_body_set_one_way(world, crate, (jostle_vec2){1, 1}), "a diagonal one-way");
    CHECK_MESSAGE("jostle_body_set_one_way: setOneWay: normal must be {0, 0} or one of {1, 0}, "
                  "{-1, 0}, {0, 1}, {0, -1}");
    const unsigned char cells[2] = {'#', '#'};
    jostle_tile_map_def map = jostle_default_tile_map_def();
    map.tile = 16;
    map.columns = 2;
    map.rows = 1;
    map.cells = cells;
    map.one_way = (jostle_vec2){0, 2};
    CHECK(jostle_tile_map_id_is_null(jostle_tile_map_create(world, &map)), "a one-way of 2");
    CHECK_MESSAGE("jostle_tile_map_create: createTileMap: TileMapDef.oneWay: must be {0, 0} or "
                  "one of {1, 0}, {-1, 0}, {0, 1}, {0, -1}");
    CHECK(!jostle_body_set_walk_speed(world, crate, 50), "a crate does not walk");
    CHECK_MESSAGE("jostle_body_set_walk_speed: setWalkSpeed: the body is not a character (a "
                  "dynamic body with BodyDef::character = true)");
    CHECK(jostle_world_body_count(world) == 1, "nothing refused was made");
    CHECK(jostle_world_destroy(world), "destroy");
    CHECK_NO_ERROR();
}

/* Rollback in C: a snapshot taken, a second of steps, the snapshot restored and the same
 * second stepped again ends where the first did, bit for bit; a short buffer and bad bytes
 * are refused by name. */
static void test_snapshots(void) {
    jostle_world_def world_def = jostle_default_world_def();
    world_def.gravity = (jostle_vec2){0, 600};
    jostle_world* world = jostle_world_create(&world_def);
    jostle_body_def def = jostle_default_body_def();
    def.type = JOSTLE_BODY_STATIC;
    def.y = 10;
    def.hw = 200;
    def.hh = 10;
    jostle_body_create(world, &def);
    def.type = JOSTLE_BODY_DYNAMIC;
    def.hw = def.hh = 5;
    def.bounce = 0.5f;
    jostle_body_id box = {0, 0, 0};
    for (int i = 0; i < 5; ++i) {
        def.x = (float)(i * 12 - 24);
        def.y = (float)(-20 - i * 15);
        box = jostle_body_create(world, &def);
    }
    for (int i = 0; i < 20; ++i)
        jostle_world_step(world, 1.0f / 60.0f);

    const size_t size = jostle_world_snapshot_size(world);
    unsigned char* saved = malloc(size);
    CHECK(jostle_world_snapshot(world, saved, size) == size, "a snapshot");
    const uint64_t hash = jostle_world_state_hash(world);
    for (int i = 0; i < 60; ++i)
        jostle_world_step(world, 1.0f / 60.0f);
    const jostle_vec2 first = jostle_body_get_position(world, box);
    const uint64_t first_hash = jostle_world_state_hash(world);
    CHECK(first_hash != hash, "a second later the world differs");

    CHECK(jostle_world_restore(world, saved, size), "restore");
    CHECK(jostle_world_state_hash(world) == hash, "restored, the hash of the snapshot");
    int begins = -1;
    jostle_world_contact_begins(world, &begins);
    CHECK(begins == 0, "no events after a restore");
    for (int i = 0; i < 60; ++i)
        jostle_world_step(world, 1.0f / 60.0f);
    const jostle_vec2 again = jostle_body_get_position(world, box);
    CHECK(memcmp(&first, &again, sizeof first) == 0, "the same second, the same place");
    CHECK(jostle_world_state_hash(world) == first_hash, "the same second, the same hash");
    CHECK_NO_ERROR();

    unsigned char small[16];
    CHECK(jostle_world_snapshot(world, small, sizeof small) == 0, "too small a buffer");
    CHECK_ERROR("jostle_world_snapshot", "the buffer holds 16 bytes");
    CHECK(!jostle_world_restore(world, saved, size - 1), "a truncated snapshot");
    CHECK_ERROR("jostle_world_restore", "truncated snapshot");
    CHECK(!jostle_world_restore(world, small, 0), "no bytes");
    CHECK_ERROR("jostle_world_restore", "not a jostle snapshot");
    CHECK(jostle_world_state_hash(world) == first_hash, "refused, the world unchanged");

    /* Restored into another world (a saved game loaded anew): the handles are adopted. */
    jostle_world* loaded = make_world(800);
    CHECK(jostle_world_restore(loaded, saved, size), "restored into another world");
    CHECK(!jostle_body_is_valid(loaded, box), "the first world's handle is not this one's");
    const jostle_body_id adopted = jostle_world_adopt_body(loaded, box);
    CHECK(jostle_body_is_valid(loaded, adopted) && adopted.index == box.index &&
              adopted.generation == box.generation,
          "adopted: the same slot and generation");
    jostle_body_id unknown = box;
    unknown.generation += 1;
    CHECK(jostle_body_id_is_null(jostle_world_adopt_body(loaded, unknown)), "none such");
    CHECK_NO_ERROR();
    CHECK(jostle_world_destroy(loaded), "destroy");
    free(saved);
    CHECK(jostle_world_destroy(world), "destroy");

    /* A clock's pending time, saved and put back: 1/8 s of a 1/4 s step is 125,000,000 ns. */
    jostle_fixed_step* clock = jostle_fixed_step_create(0.25f, 8);
    jostle_fixed_step* copy = jostle_fixed_step_create(0.25f, 8);
    jostle_fixed_step_advance(clock, 0.125f);
    CHECK(jostle_fixed_step_pending_nanoseconds(clock) == 125000000, "pending time");
    CHECK(jostle_fixed_step_set_pending_nanoseconds(copy, 125000000), "put back");
    CHECK(jostle_fixed_step_advance(copy, 0.2f) == jostle_fixed_step_advance(clock, 0.2f),
          "the same steps to come");
    CHECK(!jostle_fixed_step_set_pending_nanoseconds(copy, 250000000), "a whole step pending");
    CHECK_ERROR("jostle_fixed_step_set_pending_nanoseconds", "nanoseconds must be from");
    jostle_fixed_step_destroy(clock);
    jostle_fixed_step_destroy(copy);
}

// --- Debug drawing ---------------------------------------------------------------------------

typedef struct drawn {
    int lines, boxes, rounded, triangles, points;
    jostle_vec2 box_centre, box_half;
    jostle_colour box_fill, box_outline;
    float radius;
} drawn;

static void draw_line(jostle_vec2 from, jostle_vec2 to, jostle_colour colour, void* user) {
    (void)from, (void)to, (void)colour;
    ((drawn*)user)->lines++;
}
static void draw_box(jostle_vec2 centre, jostle_vec2 half, jostle_colour fill,
                     jostle_colour outline, void* user) {
    drawn* d = (drawn*)user;
    d->boxes++;
    d->box_centre = centre, d->box_half = half, d->box_fill = fill, d->box_outline = outline;
}
static void draw_rounded(jostle_vec2 centre, jostle_vec2 half, float radius, jostle_colour fill,
                         jostle_colour outline, void* user) {
    (void)centre, (void)half, (void)fill, (void)outline;
    ((drawn*)user)->rounded++;
    ((drawn*)user)->radius = radius;
}
static void draw_triangle(jostle_vec2 a, jostle_vec2 b, jostle_vec2 c, jostle_colour fill,
                          jostle_colour outline, void* user) {
    (void)a, (void)b, (void)c, (void)fill, (void)outline;
    ((drawn*)user)->triangles++;
}
static void draw_point(jostle_vec2 at, float size, jostle_colour colour, void* user) {
    (void)at, (void)size, (void)colour;
    ((drawn*)user)->points++;
}

static void test_debug_draw(void) {
    jostle_world_def wd = jostle_default_world_def();
    wd.gravity = (jostle_vec2){0, 10};
    wd.sleeping = false;
    jostle_world* world = jostle_world_create(&wd);
    jostle_body_def floor = jostle_default_body_def();
    floor.type = JOSTLE_BODY_STATIC, floor.x = 0, floor.y = 1, floor.hw = 10, floor.hh = 1;
    jostle_body_create(world, &floor);
    jostle_body_def ball = jostle_default_body_def();
    ball.x = 0, ball.y = -0.5f, ball.hw = 0.5f, ball.hh = 0.5f, ball.radius = 0.5f;
    jostle_body_create(world, &ball);
    jostle_body_def ramp = jostle_default_body_def();
    ramp.type = JOSTLE_BODY_STATIC, ramp.x = 5, ramp.y = -1, ramp.hw = 1, ramp.hh = 1;
    ramp.slope = (jostle_vec2){1, -1};
    jostle_body_create(world, &ramp);
    for (int i = 0; i < 60; ++i)
        jostle_world_step(world, 1.0f / 60.0f);

    // Every function given: a box (the floor), a rounded box (the ball), a triangle (the
    // ramp), and with contacts asked for, one point and one normal line (ball on floor).
    drawn d = {0};
    const jostle_debug_draw all = {draw_line,     draw_box,   draw_rounded,
                                   draw_triangle, draw_point, &d};
    jostle_debug_draw_options options = jostle_default_debug_draw_options();
    CHECK(options.shapes && !options.contacts && options.palette.outline_percent == 60,
          "the defaults are C++'s");
    options.contacts = true;
    CHECK(jostle_world_debug_draw(world, &all, &options), "drawn");
    CHECK(d.boxes == 1 && d.rounded == 1 && d.triangles == 1 && d.points == 1 && d.lines == 1,
          "one call a shape, a point and a normal");
    CHECK(d.box_centre.x == 0 && d.box_centre.y == 1 && d.box_half.x == 10 && d.box_half.y == 1,
          "the floor's box");
    CHECK(d.box_fill.r == 150 && d.box_fill.a == 255 && d.box_outline.r == 90, "static grey");
    CHECK(d.radius == 0.5f, "the ball's radius");

    // Lines alone: the box's four sides, the triangle's three, the ball's ring of four arcs
    // of six lines each (a circle's straight sides have no length); the default options
    // (NULL) draw no contacts.
    drawn lines = {0};
    const jostle_debug_draw only_lines = {draw_line, NULL, NULL, NULL, NULL, &lines};
    CHECK(jostle_world_debug_draw(world, &only_lines, NULL), "drawn in lines");
    CHECK(lines.lines == 4 + 3 + 4 * 6 && lines.boxes == 0 && lines.points == 0,
          "everything in lines");

    // Misuse: nothing drawn.
    drawn none = {0};
    const jostle_debug_draw no_line = {NULL, draw_box, NULL, NULL, NULL, &none};
    CHECK(!jostle_world_debug_draw(world, &no_line, NULL), "no line function");
    CHECK_ERROR("jostle_world_debug_draw", "draw->line is NULL");
    CHECK(!jostle_world_debug_draw(world, NULL, NULL), "no renderer");
    CHECK_ERROR("jostle_world_debug_draw", "draw is NULL");
    jostle_debug_draw_options zeroed;
    memset(&zeroed, 0, sizeof zeroed);
    const jostle_debug_draw counted = {draw_line, draw_box, NULL, NULL, NULL, &none};
    CHECK(!jostle_world_debug_draw(world, &counted, &zeroed), "options not made by the maker");
    CHECK_ERROR("jostle_world_debug_draw", "jostle_default_debug_draw_options");
    options.mark_length = -1;
    CHECK(!jostle_world_debug_draw(world, &counted, &options), "a negative mark");
    CHECK_ERROR("jostle_world_debug_draw", "markLength must be a finite number >= 0");
    options = jostle_default_debug_draw_options();
    options.palette.sleeping_percent = 200;
    CHECK(!jostle_world_debug_draw(world, &counted, &options), "a percentage above 100");
    CHECK_ERROR("jostle_world_debug_draw", "sleepingPercent must be in [0, 100]");
    CHECK(none.lines == 0 && none.boxes == 0, "nothing drawn on misuse");
    jostle_world_destroy(world);
}

int main(void) {
    test_defaults();
    test_snapshots();
    test_free_fall();
    test_landing_and_contact_events();
    test_sensor_events();
    test_crush_event();
    test_world_settings();
    test_body_properties();
    test_character_def();
    test_shapes();
    test_walking();
    test_ground_of_a_lift();
    test_conveyor();
    test_wall_friction();
    test_footing();
    test_rounded_casts();
    test_forces();
    test_contacts_now();
    test_contact_point();
    test_read_positions();
    test_queries();
    test_move_responses();
    test_move_filters();
    test_move_misuse();
    test_tile_map();
    test_ramp_tiles();
    test_pre_solve();
    test_fixed_step();
    test_draw_positions();
    test_fixed_step_events_of_each_step();
    test_misuse();
    test_messages();
    test_a_handle_of_another_world();
    test_workers();
    test_a_job_system_that_breaks_the_contract();
    test_threads_that_cannot_start();
    test_debug_draw();
    printf("test_c_api: all checks passed\n");
    return 0;
}
