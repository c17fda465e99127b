// jostle/jostle.h: the C API of jostle (C99 or later; also compiles as C++).
//
//     jostle_world_def wdef = jostle_default_world_def();
//     wdef.gravity.y = 800;                        // y grows downward, as on screen
//     jostle_world* world = jostle_world_create(&wdef);
//
//     jostle_body_def floor = jostle_default_body_def();
//     floor.type = JOSTLE_BODY_STATIC;
//     floor.y = 300; floor.hw = 400; floor.hh = 10;
//     jostle_body_create(world, &floor);
//
//     jostle_body_def crate = jostle_default_body_def();
//     crate.hw = 10; crate.hh = 10; crate.bounce = 0.3f;
//     jostle_body_id box = jostle_body_create(world, &crate);
//
//     for (int i = 0; i < 120; ++i) jostle_world_step(world, 1.0f / 60.0f);
//     jostle_vec2 p = jostle_body_get_position(world, box);   // on the floor: y = 280
//     jostle_world_destroy(world);
//
// This header is the C reference; docs/c-api.md is the guide. It wraps the C++ API
// (world.hpp, body.hpp, query.hpp, tilemap.hpp, fixed_step.hpp), whose comments explain
// the physics behind each function in more depth. Link with the jostle library and the
// C++ standard library (in CMake: find_package(jostle), target_link_libraries(game
// jostle::jostle), and enable CXX in the project so that CMake links with it).
//
// --- Conventions --------------------------------------------------------------------
//
// Names. The C++ names, in snake case, behind the prefix jostle_ and the thing they act
// on: World::setGravity is jostle_world_set_gravity; World::position and setPosition of a
// body are jostle_body_get_position and jostle_body_set_position (is_ stays: isBullet is
// jostle_body_is_bullet); createTileMap is jostle_tile_map_create; queryPoint and rayCast
// are jostle_query_point and jostle_ray_cast. Fields: BodyDef::gravityScale is
// jostle_body_def.gravity_scale (scene files use the C++ member names, so a scene field
// is the C field in camel case). Enum constants: BodyType::Kinematic is
// JOSTLE_BODY_KINEMATIC.
//
// Definitions. A jostle_*_def struct describes a thing to create. Always start from the
// value its jostle_default_*_def() function returns, then set the fields you need: the
// defaults are not all zero (friction 0.5, density 1, mask all ones...), and the field
// internal_cookie, set by that function, lets jostle catch a def that was not made by it
// (a zeroed or uninitialised struct). The query filter, jostle_query_filter, is made the
// same way, by jostle_default_query_filter().
//
// Handles. Worlds and fixed-step clocks are opaque pointers you create and destroy.
// Bodies and tile maps are small value handles (jostle_body_id, jostle_tile_map_id) that
// carry the world that made them and a generation count: a handle to a destroyed body,
// or a body of another world, is detected, never mistaken for a body of this world. The
// null handle is all zeros.
//
// Units and axes are yours (pixels are fine); y grows downward in the examples, but
// only gravity decides what a "floor" is. Floats throughout. Same inputs give the same
// results bit for bit.
//
// --- Misuse: the error contract -------------------------------------------------------
//
// Every function checks its arguments: a NULL pointer where one is required, a stale or
// null handle, a NaN or infinite number, a size <= 0, a value out of its range, an
// unknown enum value, a def not made by its jostle_default_*_def(), dt <= 0, a call that
// is not allowed from inside a callback. Misuse never crashes and never throws. Instead
// the function
//
//   1. does nothing: the world is left exactly as it was before the call;
//   2. records a message for jostle_last_error(), naming the C function first, then what
//      is wrong, e.g. "jostle_body_create: createBody: BodyDef.hw: must be > 0" (after
//      the C function's name comes the C++ library's own message, which names C++
//      functions and members: the same names in camel case);
//   3. calls the error handler, if one is set (jostle_set_error_handler);
//   4. returns a neutral value: false for functions that return bool, the null handle,
//      NULL, a count of 0, and for getters zero (0, false, NULL, {0, 0}, the enum constant
//      of value 0, a struct of all zeros); it writes nothing to output arguments except
//      where a function says otherwise.
//
// So a function that returns bool returns true when it did what was asked. Functions
// whose false or zero is also an ordinary answer (jostle_body_is_valid, the ray cast
// that hits nothing, a query that finds nothing) say so; tell the two apart with
// jostle_last_error() if you need to. Running out of memory is reported the same way
// ("...: out of memory").
//
// What cannot be checked: a jostle_world* or jostle_fixed_step* that was destroyed or
// never came from jostle (pass only live pointers), output buffers smaller than the
// capacity you say they have, and calls on one world from several threads at once.
//
// --- Threads ----------------------------------------------------------------------------
//
// Different worlds may be used on different threads freely. One world is used by one
// thread at a time, except that getters, event arrays and queries may run on several
// threads at once while no thread changes the world. The last error is per thread; the
// error handler is one for the whole process.
#ifndef JOSTLE_JOSTLE_H
#define JOSTLE_JOSTLE_H

#include "jostle/version.h"
#include "jostle/visibility.h"

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
// In C++ every enum of this header is an int with any value: a bad value coming from C
// is then an argument to report, not undefined behaviour.
#define JOSTLE_ENUM_BASE_ : int
extern "C" {
#else
#define JOSTLE_ENUM_BASE_
#endif
JOSTLE_EXPORT_BEGIN

// === Version ===============================================================================

/// The version of the library this program runs with, "major.minor.patch" (for example
/// "0.1.0"). Compare it with JOSTLE_VERSION_STRING (jostle/version.h), the headers' version,
/// to catch a program built against other headers than the library it loads.
const char* jostle_version(void);

// === Errors ================================================================================

/// The message of the last misuse on this thread, or "" if there was none since the
/// thread started or since jostle_clear_error(). Never NULL. The text lives in a buffer
/// of this thread, overwritten by the next misuse: copy it to keep it. Messages longer
/// than 511 bytes are cut.
const char* jostle_last_error(void);

/// Forgets the last error of this thread: jostle_last_error() returns "" until the next
/// misuse. Successful calls never clear it themselves, so a batch of calls can be checked
/// once at its end.
void jostle_clear_error(void);

/// Called on every misuse, with the same message jostle_last_error() returns.
typedef void (*jostle_error_fn)(const char* message, void* context);

/// Installs `handler` for the whole process (NULL removes it); `context` is handed back
/// to it. It is called on the thread of the misuse, after the message is recorded and
/// before the misused function returns its neutral value: log the message, count it, or
/// abort() to stop at the first mistake. It may call jostle functions (a misuse inside
/// it is recorded but does not call it again). It must return, or end the process: it
/// must not longjmp out, nor throw (a C++ exception thrown from it is swallowed).
void jostle_set_error_handler(jostle_error_fn handler, void* context);

// === Vectors and handles ===================================================================

/// A position, a velocity, half extents or a normal.
typedef struct jostle_vec2 {
    float x;
    float y;
} jostle_vec2;

/// A handle to a body of one world (mirrors jostle::BodyId). The null handle is
/// {0, 0, 0}: generation is 0 only there. A handle of a destroyed body is stale, and
/// one of another world is foreign: given to a function, either is misuse ("stale
/// BodyId", "BodyId of another world"), and jostle_body_is_valid says false.
typedef struct jostle_body_id {
    uint32_t index;      ///< the storage slot
    uint32_t generation; ///< how often the slot was reused; 0 only in the null handle
    uint32_t world;      ///< the serial number of the world that made it; 0 only in null
} jostle_body_id;

/// A handle to a tile map of one world (mirrors jostle::TileMapId), null = {0, 0, 0};
/// checked as a jostle_body_id is.
typedef struct jostle_tile_map_id {
    uint32_t index;
    uint32_t generation;
    uint32_t world;
} jostle_tile_map_id;

static inline bool jostle_body_id_is_null(jostle_body_id id) {
    return id.generation == 0;
}
static inline bool jostle_body_id_equal(jostle_body_id a, jostle_body_id b) {
    return a.index == b.index && a.generation == b.generation && a.world == b.world;
}
static inline bool jostle_tile_map_id_is_null(jostle_tile_map_id id) {
    return id.generation == 0;
}
static inline bool jostle_tile_map_id_equal(jostle_tile_map_id a, jostle_tile_map_id b) {
    return a.index == b.index && a.generation == b.generation && a.world == b.world;
}

// === Worlds ================================================================================

/// A world: it owns its bodies and tile maps, and steps them. Opaque.
typedef struct jostle_world jostle_world;

/// How collisions are resolved (docs/physical-model.md compares the two).
typedef enum jostle_solver JOSTLE_ENUM_BASE_ {
    /// The tutorial to the letter: each dynamic body, in creation order, moves and is
    /// pushed out of what it overlaps, one pair at a time.
    JOSTLE_SOLVER_CLASSIC = 0,
    /// All contacts solved together: stable stacks, mass, Coulomb friction (the default).
    JOSTLE_SOLVER_PHYSICAL = 1,
} jostle_solver;

/// How the physical model combines the friction of a pair.
typedef enum jostle_friction_mix JOSTLE_ENUM_BASE_ {
    JOSTLE_FRICTION_MIX_MIN = 0,            ///< the smaller of the two (the default)
    JOSTLE_FRICTION_MIX_GEOMETRIC_MEAN = 1, ///< sqrt(a * b)
} jostle_friction_mix;

/// Options of the classic model (jostle::ClassicOptions), all off by default.
typedef struct jostle_classic_options {
    bool mass;    ///< impulses shared by inverse mass, momentum conserved
    bool coulomb; ///< friction takes away at most friction * the normal velocity change
    bool ccd;     ///< dynamic bodies are swept and cannot tunnel through walls
} jostle_classic_options;

/// Settings of the physical model (jostle::PhysicalOptions; docs/physical-model.md).
typedef struct jostle_physical_options {
    int velocity_iterations;     ///< in [1, 1000], default 4
    int position_iterations;     ///< in [0, 1000], default 3
    float slop;                  ///< in [0, 0.5], default 0.01 (a fraction of half extents)
    float correction;            ///< in (0, 1], default 0.2
    float restitution_threshold; ///< finite, >= 0; 0 (the default): 2 |gravity| dt
    jostle_friction_mix friction_mix;
    /// The most bodies a dynamic body touches in a step, moving and at rest each, in
    /// [1, 65536], default 64: bounds a step's memory (jostle_world_pairs_left_out).
    int max_contacts_per_body;
} jostle_physical_options;

/// Work jostle hands to a task system: run it for every item of [begin, end) on worker
/// `worker` (in [0, workers), no two ranges at once on one worker). C++: jostle::TaskFn.
typedef void (*jostle_task_fn)(uint32_t begin, uint32_t end, uint32_t worker, void* task_context);
/// Hands `task` over [0, item_count) to the game's job system, in ranges of at least
/// min_range items (but the last) that cover every item once; returns NULL if it ran them
/// all already, else a handle for finish_task. C++: jostle::EnqueueTaskFn.
typedef void* (*jostle_enqueue_task_fn)(jostle_task_fn task, uint32_t item_count,
                                        uint32_t min_range, void* task_context, void* user_context);
/// Waits until every range of the task enqueue_task returned `user_task` for has run.
typedef void (*jostle_finish_task_fn)(void* user_task, void* user_context);

/// How a world shares its step among threads (jostle/tasks.hpp explains it). Results are
/// the same bits whatever the workers.
typedef struct jostle_task_system {
    /// Threads that may work on a step, the calling one included, in [1, 64]; default 1.
    /// More than 1 and no enqueue_task: jostle starts workers - 1 threads of its own.
    int workers;
    jostle_enqueue_task_fn enqueue_task; ///< the game's job system: both or neither
    jostle_finish_task_fn finish_task;
    void* user_context; ///< passed to enqueue_task and finish_task as given
} jostle_task_system;

/// Everything that describes a world (jostle::WorldDef). Start from
/// jostle_default_world_def().
typedef struct jostle_world_def {
    jostle_vec2 gravity; ///< default {0, 0}; scaled by each body's gravity_scale
    /// The largest speed of a dynamic body, > 0; INFINITY (the default): no clamp.
    float max_velocity;
    jostle_solver solver; ///< default JOSTLE_SOLVER_PHYSICAL
    jostle_classic_options classic;
    jostle_physical_options physical;
    /// Bodies at rest fall asleep and cost next to nothing (physical model, default on).
    bool sleeping;
    /// Threads to step on: by default the calling thread alone (workers 1).
    jostle_task_system tasks;
    /// Set by jostle_default_world_def(); leave it alone.
    uint32_t internal_cookie;
} jostle_world_def;

/// The defaults: no gravity, no velocity clamp, the physical model, sleeping on.
jostle_world_def jostle_default_world_def(void);

/// A new, empty world, or NULL on misuse (def NULL, not made by jostle_default_world_def,
/// or a field out of range: "jostle_world_create: World: WorldDef.maxVelocity: must be
/// > 0") and when the process has made UINT32_MAX worlds already (each takes a serial
/// number of its own, never given again, which its handles carry).
jostle_world* jostle_world_create(const jostle_world_def* def);

/// Frees the world with all its bodies and tile maps; every handle to them, and every
/// pointer the world handed out (event arrays), is dead from now on. NULL does nothing
/// and is not an error (as with free). Refused from inside a callback of this world.
bool jostle_world_destroy(jostle_world* world);

/// Advances the world by dt seconds: dt finite and > 0. Refused from inside a callback
/// of this world ("jostle_world_step: called from a callback during jostle_world_step").
/// Events of the step are then read with jostle_world_contact_begins() and the like.
bool jostle_world_step(jostle_world* world, float dt);

jostle_vec2 jostle_world_get_gravity(const jostle_world* world);
/// Finite numbers. Wakes every body.
bool jostle_world_set_gravity(jostle_world* world, jostle_vec2 gravity);

float jostle_world_get_max_velocity(const jostle_world* world);
/// > 0; INFINITY for no clamp.
bool jostle_world_set_max_velocity(jostle_world* world, float max_velocity);

jostle_solver jostle_world_get_solver(const jostle_world* world);
/// Forgets the contacts and events of the last step and wakes every body.
bool jostle_world_set_solver(jostle_world* world, jostle_solver solver);

bool jostle_world_get_sleeping(const jostle_world* world);
/// How many threads step the world (jostle_world_def.tasks.workers); 0 on misuse.
int jostle_world_get_workers(const jostle_world* world);
/// Turning sleeping off wakes every body.
bool jostle_world_set_sleeping(jostle_world* world, bool enabled);

jostle_classic_options jostle_world_get_classic_options(const jostle_world* world);
bool jostle_world_set_classic_options(jostle_world* world, jostle_classic_options options);

jostle_physical_options jostle_world_get_physical_options(const jostle_world* world);
/// Every option in its range (see jostle_physical_options), else nothing changes.
bool jostle_world_set_physical_options(jostle_world* world, jostle_physical_options options);

/// The number of live bodies, tile maps' bodies included.
int jostle_world_body_count(const jostle_world* world);

/// Copies the live bodies, in creation order, into out[0 .. capacity) and returns how
/// many there are, which may be more than capacity: call again with a bigger buffer.
/// out may be NULL when capacity is 0 (to ask for the count). capacity < 0 is misuse.
int jostle_world_bodies(const jostle_world* world, jostle_body_id* out, int capacity);

/// Copies the position of every live body, in the order of jostle_world_bodies, into
/// out[0 .. capacity) and returns how many bodies there are (the buffer rule of
/// jostle_world_bodies). One call for a whole world: for drawing, and for foreign-function
/// interfaces where a call per body costs.
int jostle_world_read_positions(const jostle_world* world, jostle_vec2* out, int capacity);
/// The same for their velocities.
int jostle_world_read_velocities(const jostle_world* world, jostle_vec2* out, int capacity);
/// The same for their half extents: with the positions, every box to draw.
int jostle_world_read_half_extents(const jostle_world* world, jostle_vec2* out, int capacity);

// === Bodies ================================================================================

/// How a body moves.
typedef enum jostle_body_type JOSTLE_ENUM_BASE_ {
    JOSTLE_BODY_STATIC = 0,    ///< never moves: floors, walls; infinitely heavy
    JOSTLE_BODY_KINEMATIC = 1, ///< moves by its own velocity, pushes what is in its way
    JOSTLE_BODY_DYNAMIC = 2,   ///< moved by gravity, velocity and collisions (the default)
} jostle_body_type;

/// Everything that describes a body (jostle::BodyDef; body.hpp explains each field).
/// Start from jostle_default_body_def(); hw and hh must be set.
typedef struct jostle_body_def {
    jostle_body_type type; ///< default JOSTLE_BODY_DYNAMIC
    float x, y;            ///< centre
    float hw, hh;          ///< half width and half height, > 0 (default 0: set them)
    float vx, vy;          ///< velocity, units per second; 0 for a static body
    float bounce;          ///< in [0, 1], default 0; a pair bounces with the larger
    float friction;        ///< in [0, 1], default 0.5; a pair rubs with the smaller
    float mass;            ///< > 0 to set it; 0 (the default): density * area
    float density;         ///< > 0, default 1; area is 4 * hw * hh
    float gravity_scale;   ///< default 1; 0 floats, -1 falls up
    float damping;         ///< >= 0, default 0: velocity /= 1 + damping * dt each step
    bool bullet;           ///< also swept against dynamic bodies
    /// A one-way platform: the outward normal of its one blocking face ({0, -1}: its top
    /// in a y-down world). {0, 0} (the default): solid on every side.
    jostle_vec2 one_way;
    uint32_t category; ///< the filter categories it belongs to, default 1
    uint32_t mask;     ///< the categories it collides with, default 0xFFFFFFFF
    bool sensor;       ///< detects overlaps, never pushes nor is pushed
    void* user_data;   ///< yours: stored and given back, default NULL
    /// A character (jostle::BodyDef::character, docs/characters.md): walks at
    /// jostle_body_set_walk_speed along its ground, rubs only on floors.
    bool character;
    float wall_friction; ///< a character's friction on walls and ceilings, default 0
    /// The steepest floor, in degrees from level, in [0, 90); default 60
    /// (jostle::BodyDef::floorAngle).
    float floor_angle;
    /// Sticks to the ground walking down slopes and over crests, by at most this distance;
    /// >= 0, default 0: off (jostle::BodyDef::snapDown).
    float snap_down;
    /// Slips round corners clipped by at most this much (jostle::BodyDef::cornerCorrection);
    /// >= 0, default 0: off.
    float corner_correction;
    /// A character walks up (and down) steps no taller than this
    /// (jostle::BodyDef::stepUp); >= 0, default 0: off.
    float step_up;
    /// Rounds the corners (jostle::BodyDef::radius): in [0, min(hw, hh)]; hw = hh = radius
    /// is a circle. Default 0. docs/slopes-and-shapes.md.
    float radius;
    /// A ramp (jostle::BodyDef::slope): the corner its sloped face looks towards, each
    /// component -1 or 1; {0, 0} (the default): not cut. Static or kinematic only.
    jostle_vec2 slope;
    bool segment; ///< with a slope: the sloped face alone, a one-sided line
    /// A conveyor's surface velocity, for friction (jostle::BodyDef::surfaceVelocity);
    /// {0, 0} (the default): none. Static or kinematic only.
    jostle_vec2 surface_velocity;
    /// Set by jostle_default_body_def() (and jostle_body_get_def); leave it alone.
    uint32_t internal_cookie;
} jostle_body_def;

/// The defaults: a dynamic body at {0, 0} of size 0 (set hw and hh), friction 0.5,
/// density 1, gravity scale 1, category 1, mask 0xFFFFFFFF.
jostle_body_def jostle_default_body_def(void);

/// Adds a body and returns its handle, or the null handle on misuse (a def field out of
/// range, a static body with a velocity). From inside a callback the body exists at once
/// and takes part in the simulation from the next step on.
jostle_body_id jostle_body_create(jostle_world* world, const jostle_body_def* def);

/// Removes a body; its handle and every copy of it are stale at once. Safe from inside
/// the pre-solve callback, even for a body of the pair being solved: the body is left
/// out of the rest of the step.
bool jostle_body_destroy(jostle_world* world, jostle_body_id body);

/// True if `body` names a live body of this world. A stale, foreign or null handle is an
/// ordinary false, not misuse; only a NULL world is.
bool jostle_body_is_valid(const jostle_world* world, jostle_body_id body);

/// This world's handle of the body `body` names in another world: the body of the same
/// slot and generation here, or the null handle if none is alive (an ordinary answer). For
/// handles kept across a snapshot restored into another world (a saved game loaded by a
/// new run: a handle saved as its index and generation is adopted too).
jostle_body_id jostle_world_adopt_body(const jostle_world* world, jostle_body_id body);

/// The body as a definition: its current position, velocity and settings, ready to be
/// changed and given to jostle_body_create (a copy of the body).
jostle_body_def jostle_body_get_def(const jostle_world* world, jostle_body_id body);

// The getters and setters below mirror World's (world.hpp). Each checks the world and
// the handle, and each setter its value as World does; a setter returns false and
// changes nothing on misuse, a getter returns zero ({0, 0}, 0, false, NULL). Setters of
// a body's physics wake it and what rests on it.

jostle_body_type jostle_body_get_type(const jostle_world* world, jostle_body_id body);
bool jostle_body_set_type(jostle_world* world, jostle_body_id body, jostle_body_type type);

jostle_vec2 jostle_body_get_position(const jostle_world* world, jostle_body_id body);
/// A teleport: nothing is swept on the way. Finite numbers.
bool jostle_body_set_position(jostle_world* world, jostle_body_id body, jostle_vec2 centre);

jostle_vec2 jostle_body_get_velocity(const jostle_world* world, jostle_body_id body);
/// Finite numbers; a static body cannot move.
bool jostle_body_set_velocity(jostle_world* world, jostle_body_id body, jostle_vec2 velocity);

/// {hw, hh}.
jostle_vec2 jostle_body_get_half_extents(const jostle_world* world, jostle_body_id body);
/// Both > 0 and finite.
bool jostle_body_set_half_extents(jostle_world* world, jostle_body_id body, jostle_vec2 half);

float jostle_body_get_bounce(const jostle_world* world, jostle_body_id body);
/// In [0, 1].
bool jostle_body_set_bounce(jostle_world* world, jostle_body_id body, float bounce);

float jostle_body_get_friction(const jostle_world* world, jostle_body_id body);
/// In [0, 1].
bool jostle_body_set_friction(jostle_world* world, jostle_body_id body, float friction);

/// The mass the solver uses: the explicit mass or density * area; INFINITY for static
/// and kinematic bodies.
float jostle_body_get_mass(const jostle_world* world, jostle_body_id body);
/// An explicit mass, finite and > 0.
bool jostle_body_set_mass(jostle_world* world, jostle_body_id body, float mass);
/// Finite and > 0. Drops any explicit mass: the mass is density * area from now on.
bool jostle_body_set_density(jostle_world* world, jostle_body_id body, float density);

float jostle_body_get_gravity_scale(const jostle_world* world, jostle_body_id body);
/// Finite.
bool jostle_body_set_gravity_scale(jostle_world* world, jostle_body_id body, float scale);

float jostle_body_get_damping(const jostle_world* world, jostle_body_id body);
/// Finite and >= 0.
bool jostle_body_set_damping(jostle_world* world, jostle_body_id body, float damping);

bool jostle_body_is_bullet(const jostle_world* world, jostle_body_id body);
bool jostle_body_set_bullet(jostle_world* world, jostle_body_id body, bool bullet);

/// False while the body sleeps (docs/sleeping.md), and on misuse.
bool jostle_body_is_awake(const jostle_world* world, jostle_body_id body);
/// Wakes the body and everything it rests on or carries.
bool jostle_body_wake(jostle_world* world, jostle_body_id body);

void* jostle_body_get_user_data(const jostle_world* world, jostle_body_id body);
bool jostle_body_set_user_data(jostle_world* world, jostle_body_id body, void* data);

jostle_vec2 jostle_body_get_one_way(const jostle_world* world, jostle_body_id body);
/// {0, 0} or one of {+-1, 0}, {0, +-1} (docs/one-way-platforms.md).
bool jostle_body_set_one_way(jostle_world* world, jostle_body_id body, jostle_vec2 normal);
/// Lets the body fall through every one-way platform for the next `seconds` (finite,
/// >= 0; 0 ends it): "down + jump" in a platformer. Only a dynamic body drops through:
/// for a static or kinematic body it returns false and sets the error.
bool jostle_body_drop_through(jostle_world* world, jostle_body_id body, float seconds);

/// Collision filtering (docs/filtering.md): two bodies collide when each one's category
/// shares a bit with the other's mask.
uint32_t jostle_body_get_category(const jostle_world* world, jostle_body_id body);
bool jostle_body_set_category(jostle_world* world, jostle_body_id body, uint32_t bits);
uint32_t jostle_body_get_mask(const jostle_world* world, jostle_body_id body);
bool jostle_body_set_mask(jostle_world* world, jostle_body_id body, uint32_t bits);

bool jostle_body_is_sensor(const jostle_world* world, jostle_body_id body);
bool jostle_body_set_sensor(jostle_world* world, jostle_body_id body, bool sensor);

/// The sum of the vectors that pushed the body out of others during the last step:
/// separation.y < 0 in a y-down world means something held it up (it stands on it).
jostle_vec2 jostle_body_get_separation(const jostle_world* world, jostle_body_id body);

/// What a body touched in the last step, relative to gravity (jostle::Touching).
typedef struct jostle_touching {
    bool floor;      ///< below it, where gravity pulls
    bool ceiling;    ///< above it
    bool wall_left;  ///< on its left, looking along gravity's "down"
    bool wall_right; ///< on its right
} jostle_touching;

/// Physical model (docs/events.md).
jostle_touching jostle_body_get_touching(const jostle_world* world, jostle_body_id body);

// --- Characters (docs/characters.md) -----------------------------------------------------

/// See jostle_body_def.character.
bool jostle_body_is_character(const jostle_world* world, jostle_body_id body);
bool jostle_body_set_character(jostle_world* world, jostle_body_id body, bool character);

/// See jostle_body_def.wall_friction.
float jostle_body_get_wall_friction(const jostle_world* world, jostle_body_id body);
/// In [0, 1].
bool jostle_body_set_wall_friction(jostle_world* world, jostle_body_id body, float friction);

/// See jostle_body_def.floor_angle.
float jostle_body_get_floor_angle(const jostle_world* world, jostle_body_id body);
/// Degrees in [0, 90).
bool jostle_body_set_floor_angle(jostle_world* world, jostle_body_id body, float degrees);

/// See jostle_body_def.surface_velocity. Misuse for a dynamic body, but {0, 0}.
jostle_vec2 jostle_body_get_surface_velocity(const jostle_world* world, jostle_body_id body);
bool jostle_body_set_surface_velocity(jostle_world* world, jostle_body_id body,
                                      jostle_vec2 velocity);
/// See jostle_body_def.corner_correction and step_up; >= 0.
float jostle_body_get_corner_correction(const jostle_world* world, jostle_body_id body);
bool jostle_body_set_corner_correction(jostle_world* world, jostle_body_id body, float distance);
float jostle_body_get_step_up(const jostle_world* world, jostle_body_id body);
bool jostle_body_set_step_up(jostle_world* world, jostle_body_id body, float height);
/// See jostle_body_def.snap_down.
float jostle_body_get_snap_down(const jostle_world* world, jostle_body_id body);
/// >= 0; 0 is off.
bool jostle_body_set_snap_down(jostle_world* world, jostle_body_id body, float distance);

/// The speed a character walks at, default 0: along what it stands on and relative to it,
/// so that it keeps pace with a lift; positive to the right of gravity's "down" (+x in a
/// y-down world); in the air, relative to the world. It holds until changed: set it from
/// the input every frame (0 stands still). Each step the character walks at this speed
/// across gravity unless something stops it (a wall; crates heavier than its feet's grip
/// can push: docs/characters.md); along gravity the velocity is the physics' (set the
/// velocity to jump).
float jostle_body_get_walk_speed(const jostle_world* world, jostle_body_id body);
/// Finite; misuse for a body that is not a character (a dynamic body with `character`).
bool jostle_body_set_walk_speed(jostle_world* world, jostle_body_id body, float speed);

/// What a body stands on (jostle::Ground).
typedef struct jostle_ground {
    jostle_body_id body;  ///< the body under it
    jostle_vec2 normal;   ///< the push of the ground: against gravity
    jostle_vec2 velocity; ///< the ground's velocity now: what a rider moves with
} jostle_ground;

/// What the body stood on at the end of the last step: of the bodies that pushed it
/// against gravity (floors, in jostle_touching's sense), the one that pushed hardest.
/// True and *ground filled if there is one; false, *ground untouched, in the air or if
/// that body has been destroyed since (not misuse), and on misuse (ground NULL...). A
/// sleeping body keeps the ground it fell asleep on. Any body may ask, not only
/// characters.
bool jostle_body_get_ground(const jostle_world* world, jostle_body_id body, jostle_ground* ground);

// --- Forces ------------------------------------------------------------------------------

/// Adds a force (mass * units / s^2) at the body's centre for the next step: its velocity
/// changes by force / mass * dt then. Forces add up until that step, which clears them:
/// apply a lasting force before every step. Finite numbers. Wakes the body. Static and
/// kinematic bodies are infinitely heavy: nothing happens to them (not misuse).
bool jostle_body_apply_force(jostle_world* world, jostle_body_id body, jostle_vec2 force);
/// Changes the body's velocity by impulse / mass (mass * units / s) at once: a kick, a
/// blast, a jump of a given strength. Finite numbers. Wakes the body. Nothing happens to
/// static and kinematic bodies.
bool jostle_body_apply_impulse(jostle_world* world, jostle_body_id body, jostle_vec2 impulse);

// --- Contacts now ------------------------------------------------------------------------

/// A contact of one body with another, as jostle_body_contacts lists it
/// (jostle::ContactInfo).
typedef struct jostle_contact_info {
    jostle_body_id other;
    /// Unit, pointing from `other` towards the body, as in a contact event.
    jostle_vec2 normal;
    /// Where they touch now, as in a contact begin event.
    jostle_vec2 point;
    float impulse; ///< the normal impulse between them in the last step (mass * speed)
} jostle_contact_info;

/// Copies the bodies this one touched at the end of the last step (sensors excluded), in
/// the order of the bodies they pair with, created first first, into out[0 .. capacity)
/// and returns how many there are (the buffer rule of queries).
int jostle_body_contacts(const jostle_world* world, jostle_body_id body, jostle_contact_info* out,
                         int capacity);

/// True if the two bodies touched at the end of the last step; false, an ordinary answer,
/// if they did not. A stale handle is misuse, as everywhere.
bool jostle_body_is_touching(const jostle_world* world, jostle_body_id a, jostle_body_id b);

// === What the last step did (docs/events.md) ===============================================
//
// Each function returns an array filled by the last jostle_world_step and sets *count to
// its length. The array belongs to the world: it stays valid and unchanged until the
// next jostle_world_step, jostle_world_set_solver (which forgets them) or
// jostle_world_destroy of that world; do not free it. When *count is 0 the pointer may
// be NULL. On misuse (world or count NULL) they return NULL and set *count to 0 if count
// is not NULL. Handles in events may be stale by the time you read them (a body
// destroyed since, or the destroyed body of a contact end): check with
// jostle_body_is_valid before using them.

/// Two bodies that started or stopped touching.
typedef struct jostle_contact_event {
    jostle_body_id a; ///< the body created first
    jostle_body_id b; ///< the other one
    /// Unit, pointing from b towards a: along x or y between two sharp boxes. For a pair
    /// with a rounded body, ramp or segment, the normal of the surfaces where they touch:
    /// a slope's, or any direction round a curve or a corner.
    jostle_vec2 normal;
    float approach_speed; ///< begin: how fast they met along the normal (>= 0); end: 0
    /// Begin: where they touch, halfway between the two surfaces along the normal. Where a
    /// face meets a face (two boxes, a box against a ramp's leg, a capsule's side against a
    /// wall), the middle of the stretch they share; where a corner or a curve touches, that
    /// point: a box's corner on a slope, a circle's centre less its radius times the
    /// normal, the corner a circle rolls round. End: {0, 0}.
    jostle_vec2 point;
} jostle_contact_event;

/// A body that started or stopped overlapping a sensor.
typedef struct jostle_sensor_event {
    jostle_body_id sensor;
    jostle_body_id visitor;
} jostle_sensor_event;

/// A body squeezed between a moving kinematic body and something that would not give.
typedef struct jostle_crush_event {
    jostle_body_id body;
    jostle_body_id by;      ///< the kinematic body pushing
    jostle_body_id against; ///< what is on the other side
} jostle_crush_event;

/// Pairs that started touching in the last step (sensors excluded).
const jostle_contact_event* jostle_world_contact_begins(const jostle_world* world, int* count);
/// Pairs that stopped touching in the last step, or one of whose bodies was destroyed.
const jostle_contact_event* jostle_world_contact_ends(const jostle_world* world, int* count);
/// Bodies that started overlapping a sensor in the last step.
const jostle_sensor_event* jostle_world_sensor_begins(const jostle_world* world, int* count);
/// Bodies that stopped overlapping a sensor in the last step.
const jostle_sensor_event* jostle_world_sensor_ends(const jostle_world* world, int* count);
/// Crushes that began in the last step (physical model; World::crushBegins): each squeeze
/// begins once, and the two bodies pass through each other until they no longer overlap.
const jostle_crush_event* jostle_world_crush_begins(const jostle_world* world, int* count);
/// Crushes that ended in the last step: the two no longer overlap, or one was destroyed.
const jostle_crush_event* jostle_world_crush_ends(const jostle_world* world, int* count);
/// Pairs the last step left out because a dynamic body had more than
/// max_contacts_per_body of them (physical model): 0 in a sane scene.
uint64_t jostle_world_pairs_left_out(const jostle_world* world);

/// Where the last step's time went, in milliseconds of wall-clock time, stage by stage
/// (jostle::StepProfile says what each holds; the classic model fills `step` only).
typedef struct jostle_step_profile {
    float step;
    float riders, velocities, pairs, corners, contacts, support, impacts, layers, solve, shock,
        bounces, sweeps, positions, correction, snap, store, events, sleep;
} jostle_step_profile;

/// All 0 before the first step.
jostle_step_profile jostle_world_get_profile(const jostle_world* world);

// === The pre-solve callback ================================================================

/// A pair about to collide, as the solver sees it before it responds (jostle::Collision).
typedef struct jostle_collision {
    jostle_body_id a; ///< classic: the dynamic body that moved; physical: the older one
    jostle_body_id b; ///< the other body
    /// Unit, pointing from b towards a: along x or y between two sharp boxes; for a pair
    /// with a shape, the normal where they touch (as in a contact event).
    jostle_vec2 normal;
    /// How deep they overlap along the normal; negative for a pair that will meet within
    /// the step (-depth is the gap), 0 where the classic ccd sweep stopped a body.
    float depth;
    float bounce; ///< the pair's bounce; the callback may change it (clamped to [0, 1])
    /// The pair's friction; the callback may change it (clamped to [0, 1]). Unless it is
    /// lowered, a character keeps its firm footing on a slope it stands on.
    float friction;
} jostle_collision;

/// Called during jostle_world_step for every pair the solver is about to respond to.
/// Return false to let the pair pass through each other this time (a one-way platform, a
/// ghost, a team mate), true to let the solver respond. Changes to `bounce` and
/// `friction` hold for this pair and this step only (NaN: left as they were); changes to
/// the other fields are ignored. `collision` is valid during the call only.
///
/// From inside the callback you may call: every getter, every query, the event arrays
/// (they still hold the previous step's events), jostle_body_create (the body joins from
/// the next step), jostle_body_destroy (either body of the pair too: the pair is then
/// dropped), the body setters, jostle_tile_map_set_tile and _set_tile_char, and the error
/// functions. In the physical model a body's mass is taken when the step first meets it:
/// a mass or type set from the callback for a body met already counts from the next step.
/// Refused, as misuse, are the functions that change the world as a whole:
/// jostle_world_step (and jostle_fixed_step_update of this world), jostle_world_destroy,
/// jostle_world_set_pre_solve and every other jostle_world_set_*. The callback must
/// return normally: no longjmp out of it.
typedef bool (*jostle_pre_solve_fn)(jostle_collision* collision, void* context);

/// Installs the pre-solve callback of the world, with the `context` handed back to it;
/// NULL removes it. Refused from inside a callback.
bool jostle_world_set_pre_solve(jostle_world* world, jostle_pre_solve_fn callback, void* context);

// === Queries (docs/queries.md; query.hpp is the reference of the rules) ===================
//
// Queries look at every body where it is now, change nothing, and filter bodies as
// collisions do. They see each body's true shape (radius, slope, segment): a ray meets a
// circle at the circle, a ramp on its slope; the box a cast or a move carries is a sharp
// box unless given a radius (jostle_rounded_box_cast, jostle_circle_cast,
// jostle_rounded_move_and_slide). Functions that find several bodies copy them into the
// caller's buffer out[0 .. capacity) and return how many they found, which may be more
// than capacity: the first `capacity` of them are in out, in the same order as a bigger
// buffer would hold them. Grow the buffer and call again to get them all. out may be NULL
// when capacity is 0; capacity < 0 is misuse. On misuse they return 0.
//
// Every query takes a filter; NULL means jostle_default_query_filter().

/// Which bodies a query reports (jostle::QueryFilter). A body is reported when
/// (body.category & filter.mask) != 0 and (filter.category & body.mask) != 0, it is not
/// a sensor (unless include_sensors) and it is not `ignore`.
typedef struct jostle_query_filter {
    uint32_t mask;        ///< the categories to report, default 0xFFFFFFFF
    uint32_t category;    ///< the query's own category, default 0xFFFFFFFF
    bool include_sensors; ///< default false
    /// A body never reported (the character doing the query); the null handle, the
    /// default, ignores nothing; a stale one is misuse.
    jostle_body_id ignore;
    /// Set by jostle_default_query_filter(); leave it alone.
    uint32_t internal_cookie;
} jostle_query_filter;

/// Every body except sensors.
jostle_query_filter jostle_default_query_filter(void);

/// The bodies that contain `point`, in creation order. A point on an edge is on the body
/// (a click on the seam between two tiles picks both). A body is its shape: a point in a
/// circle's box but outside the circle, or in the half of a ramp's box cut away, is not in
/// it; a segment, a line, holds the points on it (within float rounding).
int jostle_query_point(const jostle_world* world, jostle_vec2 point,
                       const jostle_query_filter* filter, jostle_body_id* out, int capacity);

/// The bodies that share some area with the box of centre `centre` and half extents
/// `half` (each >= 0), in creation order; touching edge to edge is not overlapping. A body
/// is its shape (a ramp's slope, a circle's curve); a segment overlaps the boxes it crosses.
int jostle_query_box(const jostle_world* world, jostle_vec2 centre, jostle_vec2 half,
                     const jostle_query_filter* filter, jostle_body_id* out, int capacity);

/// jostle_query_box by corners: min <= max on both axes.
int jostle_query_rect(const jostle_world* world, jostle_vec2 min, jostle_vec2 max,
                      const jostle_query_filter* filter, jostle_body_id* out, int capacity);

/// Where a ray meets a body.
typedef struct jostle_ray_hit {
    jostle_body_id body;
    jostle_vec2 point; ///< from + (to - from) * fraction, exactly on the face it meets
    /// The outward normal of the surface it meets, unit, against the ray: along x or y for
    /// a box's face, a ramp's slope's normal, or a rounded body's normal there.
    jostle_vec2 normal;
    float fraction; ///< in [0, 1]
} jostle_ray_hit;

/// The first body on the segment from `from` to `to`: true and *hit filled if there is
/// one; false, *hit untouched, if there is none (not misuse) or on misuse (hit NULL,
/// numbers not finite...). The rules (a ray starting inside a box hits it at fraction 0,
/// a zero-length ray hits nothing, ties go to the body created first) are rayCast's.
bool jostle_ray_cast(const jostle_world* world, jostle_vec2 from, jostle_vec2 to,
                     const jostle_query_filter* filter, jostle_ray_hit* hit);

/// Every body on the segment, nearest first (ties in creation order), each once.
int jostle_ray_cast_all(const jostle_world* world, jostle_vec2 from, jostle_vec2 to,
                        const jostle_query_filter* filter, jostle_ray_hit* out, int capacity);

/// Where a box swept along a translation first touches a body.
typedef struct jostle_box_cast_hit {
    jostle_body_id body;
    jostle_vec2 centre; ///< where the box's centre stops, touching the body
    /// Unit, pointing from the body towards the box: along x or y for a box's face, the
    /// slope's normal for a ramp's slope, the normal there for a rounded body's curve.
    jostle_vec2 normal;
    float fraction; ///< the fraction of the translation travelled, in [0, 1]
} jostle_box_cast_hit;

/// Sweeps the box (half extents > 0) along `translation`: true and *hit filled if it
/// runs into a body; false, *hit untouched, if it runs into none or on misuse. Touching
/// is not running into: a box on a floor moving sideways is free (boxCast's rules).
bool jostle_box_cast(const jostle_world* world, jostle_vec2 centre, jostle_vec2 half,
                     jostle_vec2 translation, const jostle_query_filter* filter,
                     jostle_box_cast_hit* hit);

/// jostle_box_cast of the box rounded by `radius`, in [0, min(half.x, half.y)]
/// (jostle_body_def.radius's shapes: half.x == half.y == radius is a circle, half.x ==
/// radius < half.y an upright capsule): it meets bodies with its curve.
bool jostle_rounded_box_cast(const jostle_world* world, jostle_vec2 centre, jostle_vec2 half,
                             float radius, jostle_vec2 translation,
                             const jostle_query_filter* filter, jostle_box_cast_hit* hit);

/// jostle_box_cast of a circle (radius > 0).
bool jostle_circle_cast(const jostle_world* world, jostle_vec2 centre, float radius,
                        jostle_vec2 translation, const jostle_query_filter* filter,
                        jostle_box_cast_hit* hit);

/// A body met by jostle_move_and_slide.
typedef struct jostle_move_hit {
    jostle_body_id body;
    jostle_vec2 normal; ///< unit, pointing from the body towards the box (as a box cast's)
} jostle_move_hit;

/// Moves a box by `translation` as bump.lua moves its items: until it runs into a body,
/// then sliding along it for the rest of the way. Writes where the box ends up to
/// *new_centre (required), copies the bodies met, in the order met, into hits[0 ..
/// capacity) and returns how many it met (capacity may be 0 and hits NULL). Nothing in
/// the world moves: set the character's position yourself, and name its body in
/// filter->ignore. On misuse *new_centre is `centre` (if new_centre is not NULL) and it
/// returns 0.
int jostle_move_and_slide(const jostle_world* world, jostle_vec2 centre, jostle_vec2 half,
                          jostle_vec2 translation, const jostle_query_filter* filter,
                          jostle_vec2* new_centre, jostle_move_hit* hits, int capacity);

/// jostle_move_and_slide of the box rounded by `radius` (jostle_rounded_box_cast's): a
/// circle or a capsule rolls over a crest and round a corner where a box would stop.
int jostle_rounded_move_and_slide(const jostle_world* world, jostle_vec2 centre, jostle_vec2 half,
                                  float radius, jostle_vec2 translation,
                                  const jostle_query_filter* filter, jostle_vec2* new_centre,
                                  jostle_move_hit* hits, int capacity);

// === Moving a body by hand, bump.lua's way (move in query.hpp) ============================
//
// jostle_body_move is bump.lua's world:move in one call: the body's own box, swept from
// where it is by a delta, each body in the way answered as a filter says, the body put
// where the move ends, and every body met reported. Unlike the queries above, it changes
// the world (the body's position).

/// How a moved body answers a body in its way (jostle::Response, bump.lua's responses).
typedef enum jostle_response JOSTLE_ENUM_BASE_ {
    /// Stops going into it and goes on along its face for the rest of the move (the
    /// default for solid bodies).
    JOSTLE_RESPONSE_SLIDE = 0,
    JOSTLE_RESPONSE_TOUCH = 1,  ///< stops where it touches it: the move ends there
    JOSTLE_RESPONSE_CROSS = 2,  ///< goes through it, reported (the default for sensors)
    JOSTLE_RESPONSE_BOUNCE = 3, ///< turns back off its face for the rest of the move
    JOSTLE_RESPONSE_IGNORE = 4, ///< goes through it, unreported
} jostle_response;

/// Chooses the response to `other`, a body in the way of the move (jostle::MoveFilter);
/// `context` is the one given to jostle_body_move. Called at most once per body and move.
/// Returning a value that is not a jostle_response is misuse of jostle_body_move.
///
/// From inside the filter you may read the world: every getter, every query, the event
/// arrays. Every function that changes the world is refused as misuse (it would change
/// what the move is sweeping through): jostle_body_move itself, jostle_body_create and
/// jostle_body_destroy, the body setters, the tile map functions that change a map, and
/// the jostle_world_* functions that change the world. The filter must return normally:
/// no longjmp out of it.
typedef jostle_response (*jostle_move_filter_fn)(jostle_body_id other, void* context);

/// A body jostle_body_move met (jostle::MoveCollision).
typedef struct jostle_move_collision {
    jostle_body_id other;
    jostle_response response; ///< what the filter chose for it
    jostle_vec2 normal;       ///< unit, pointing from `other` towards the body (as a box cast's)
    /// The moved body's centre when it touched `other`, placed exactly against its face.
    jostle_vec2 touch;
    /// When, as a fraction of the whole move, in [0, 1]: the move takes unit time, and keeps
    /// going at the same pace after a slide or a bounce.
    float time;
    jostle_vec2 other_centre; ///< the other body's box: its centre
    jostle_vec2 other_half;   ///< and its half extents
} jostle_move_collision;

/// What jostle_body_move did.
typedef struct jostle_move_result {
    jostle_vec2 centre; ///< where the body is now
    /// The bodies met, in the order met (bodies met at the same moment in creation
    /// order); NULL when count is 0. The array belongs to the world: it stays valid and
    /// unchanged until the next jostle_body_move on that world or jostle_world_destroy;
    /// do not free it.
    const jostle_move_collision* collisions;
    int count;
} jostle_move_result;

/// Moves `body` by `delta` the way bump.lua's world:move does: its box goes from where
/// the body is towards where it would be, and each body it runs into answers by `filter`
/// (NULL: JOSTLE_RESPONSE_SLIDE for solid bodies, JOSTLE_RESPONSE_CROSS for sensors).
/// The rules are jostle_box_cast's: touching is not running into, a body it is already
/// inside does not stop it, a one-way platform stops it only from its blocking side, and
/// nothing is tunnelled through; and, as in bump.lua, a body reached just as the move
/// ends is not met (the next move into it meets it, once). Bodies the moved body's category and
/// mask leave out are never met. The body is put where the move ends (as by
/// jostle_body_set_position: it wakes what it leaves and what it reaches); its velocity is left
/// alone. After 32 stops the body stays where the last one left it.
///
/// Any body may be moved; a kinematic body is the usual choice for a character moved by
/// hand (docs/characters.md). Writes what happened to *result, which may be NULL (the
/// move alone). On misuse (a stale body, a delta not finite or that carries the body out
/// of range, a filter answer that is not a jostle_response) nothing moves, it returns
/// false, and *result, if result is not NULL, says so: centre where the body is (zero if
/// there is no such body), no collisions.
bool jostle_body_move(jostle_world* world, jostle_body_id body, jostle_vec2 delta,
                      jostle_move_filter_fn filter, void* context, jostle_move_result* result);

// === Tile maps (docs/tilemaps.md) ==========================================================

/// Everything that describes a tile map (jostle::TileMapDef). Start from
/// jostle_default_tile_map_def(), then set tile, columns, rows and cells.
///
/// Tile (column, row) covers x + column * tile to x + (column + 1) * tile, and likewise
/// in y: in a y-down world row 0 is the top row.
typedef struct jostle_tile_map_def {
    float x, y;  ///< the corner of tile (0, 0) with the smallest x and y
    float tile;  ///< the side of a square tile, > 0
    int columns; ///< >= 1
    int rows;    ///< >= 1
    /// columns * rows bytes, row by row, top row first: cells[row * columns + column] is
    /// 0 or '.' for an empty tile, a ramp's character for a ramp, and any other byte ('#',
    /// 1) for a solid tile. So the rows of a C++ TileMapDef or a scene file, laid end to
    /// end, are cells as they are. The ramps (as read on screen in a y-down world;
    /// tilemap.hpp and docs/slopes-and-shapes.md have pictures): '/' and '\\' 45° floors
    /// rising to the right and to the left, '7' and 'F' 45° ceilings solid at the top right
    /// and top left, "rR" and "Ll" 2:1 floors (two tiles each, low and high half), "cC" and
    /// "Dd" 2:1 ceilings. Read by jostle_tile_map_create only.
    const unsigned char* cells;
    // Settings of every static body of the map, fixed at creation (body defaults).
    float friction;
    float bounce;
    uint32_t category;
    uint32_t mask;
    jostle_vec2 one_way; ///< {0, -1}: jump-through platforms in a y-down world
    bool sensor;         ///< water, lava, a trigger zone drawn in tiles
    void* user_data;     ///< given to every body of the map
    /// Set by jostle_default_tile_map_def(); leave it alone.
    uint32_t internal_cookie;
} jostle_tile_map_def;

/// The defaults: at {0, 0}, tile 0 and no cells (set them), friction 0.5, bounce 0,
/// category 1, mask 0xFFFFFFFF.
jostle_tile_map_def jostle_default_tile_map_def(void);

/// Creates the map and the static bodies of its solid tiles (runs of solid tiles merged
/// into few boxes), then one static ramp body per ramp (the two halves of a 2:1 ramp side
/// by side one); the null handle on misuse (def or cells NULL, columns or rows < 1,
/// tile <= 0, a setting out of range, a ramp in a world of the classic model, which has
/// sharp boxes only).
jostle_tile_map_id jostle_tile_map_create(jostle_world* world, const jostle_tile_map_def* def);

/// Destroys the map and all its bodies; what rests on them wakes and falls.
bool jostle_tile_map_destroy(jostle_world* world, jostle_tile_map_id map);

/// True if `map` names a live tile map of this world; stale, foreign or null is an
/// ordinary false.
bool jostle_tile_map_is_valid(const jostle_world* world, jostle_tile_map_id map);

/// jostle_world_adopt_body for a tile map.
jostle_tile_map_id jostle_world_adopt_tile_map(const jostle_world* world, jostle_tile_map_id map);

/// Makes the tile at (column, row) solid or empty; the tile must be inside the map.
/// Only the few boxes around the tile are rebuilt. A ramp there is replaced.
bool jostle_tile_map_set_tile(jostle_world* world, jostle_tile_map_id map, int column, int row,
                              bool solid);

/// Sets the tile at (column, row) to a character of the rows of a C++ TileMapDef: '#'
/// solid, '.' empty, or a ramp ('/', '\\', '7', 'F', 'r', 'R', 'L', 'l', 'c', 'C', 'D',
/// 'd': see jostle_tile_map_def::cells); the tile must be inside the map, and any other
/// character is misuse, as is a ramp in the classic model. The ramps of its row are
/// rebuilt, as are the few boxes around it.
bool jostle_tile_map_set_tile_char(jostle_world* world, jostle_tile_map_id map, int column, int row,
                                   char tile);

/// The character of the tile at (column, row): '#', '.' or a ramp's, as
/// jostle_tile_map_set_tile_char takes them. Outside the map: '.', not misuse. On misuse:
/// '\0'.
char jostle_tile_map_tile_of(const jostle_world* world, jostle_tile_map_id map, int column,
                             int row);

/// True if the tile is solid ('#'; a ramp is not). Outside the map: false, not misuse
/// (the map goes on empty forever).
bool jostle_tile_map_is_solid(const jostle_world* world, jostle_tile_map_id map, int column,
                              int row);

/// The tile that contains `point` (on an edge: the larger column or row): true and
/// *column, *row set (both required); false outside the map (not misuse) or on misuse.
bool jostle_tile_map_tile_at(const jostle_world* world, jostle_tile_map_id map, jostle_vec2 point,
                             int* column, int* row);

/// The size of the map in tiles; 0 on misuse.
int jostle_tile_map_columns(const jostle_world* world, jostle_tile_map_id map);
int jostle_tile_map_rows(const jostle_world* world, jostle_tile_map_id map);

/// Copies the static bodies the map is made of now, in creation order, into out[0 ..
/// capacity) and returns how many there are (the buffer rule of queries). They belong to
/// the map: do not destroy or change them.
int jostle_tile_map_bodies(const jostle_world* world, jostle_tile_map_id map, jostle_body_id* out,
                           int capacity);

/// The map that `body` is part of, or the null handle if none (not misuse; a stale body
/// is).
jostle_tile_map_id jostle_tile_map_of(const jostle_world* world, jostle_body_id body);

// === Snapshots: saving and restoring a whole world (docs/snapshots.md, docs/rollback.md) ===
//
// A snapshot holds everything that decides a world's future, in bytes that are the same on
// every machine: restored, the world steps on bit for bit as the one it was taken from.
// userData, the pre-solve callback and the workers are the restoring world's own; the
// last step's events are empty after a restore. All four are refused from a callback.

/// The length in bytes of a snapshot of the world as it is now; 0 on misuse.
size_t jostle_world_snapshot_size(const jostle_world* world);

/// Writes a snapshot of the world into out[0 .. capacity) and returns its length; 0 on
/// misuse, a capacity below jostle_world_snapshot_size() included ("jostle_world_snapshot:
/// snapshot: the buffer holds 100 bytes, the snapshot needs 5032"). Allocates nothing.
size_t jostle_world_snapshot(const jostle_world* world, void* out, size_t capacity);

/// Makes the world what it was when `snapshot` (`size` bytes) was taken: handles held then
/// are valid again, bodies and maps created since are gone. False, the world unchanged, for
/// bytes that are not a whole snapshot of this format ("jostle_world_restore: restore:
/// truncated snapshot: 120 bytes, its header says 5032").
bool jostle_world_restore(jostle_world* world, const void* snapshot, size_t size);

/// A 64-bit hash of exactly what a snapshot holds (its checksum), computed without writing
/// one: peers compare it to find out that their worlds differ. 0 on misuse.
uint64_t jostle_world_state_hash(const jostle_world* world);

// === Debug drawing (docs/debug-draw.md) ====================================================

/// A colour: red, green, blue and opacity, 0 to 255 each (jostle::Colour).
typedef struct jostle_colour {
    uint8_t r;
    uint8_t g;
    uint8_t b;
    uint8_t a;
} jostle_colour;

/// The colours jostle_world_debug_draw uses (jostle::DebugPalette, whose comments say what
/// each is for). A body's fill is its type's colour, scaled by sleeping_percent while it
/// sleeps; its outline is the fill scaled by outline_percent. Percentages in [0, 100].
typedef struct jostle_debug_palette {
    jostle_colour static_body;
    jostle_colour kinematic_body;
    jostle_colour dynamic_body;
    int sleeping_percent;
    int outline_percent;
    jostle_colour bullet_outline;
    jostle_colour one_way_face;
    jostle_colour contact;
    jostle_colour velocity;
    jostle_colour touching;
    jostle_colour grid_cell;
    jostle_colour grid_box;
} jostle_debug_palette;

/// What jostle_world_debug_draw draws (jostle::DebugDrawOptions): start from
/// jostle_default_debug_draw_options(), then set what you need.
typedef struct jostle_debug_draw_options {
    bool shapes;       ///< every body in its shape, tile maps' merged boxes among them (true)
    bool contacts;     ///< every touching pair: where it touches, and its normal
    bool velocities;   ///< awake dynamic bodies: a tenth of a second of their motion
    bool touching;     ///< the sides each dynamic body touched in the last step
    bool grid;         ///< the broadphase's occupied cells and its moving boxes
    float mark_length; ///< the longest a normal, a segment's tick or a point's cross is (>= 0)
    /// Only what touches this box is drawn; min > max on either axis draws everything.
    jostle_vec2 view_min;
    jostle_vec2 view_max;
    jostle_debug_palette palette;
    uint32_t internal_cookie;
} jostle_debug_draw_options;

jostle_debug_draw_options jostle_default_debug_draw_options(void);

/// The game's renderer: its functions, each given `user`. `line` is required; each other
/// one may be NULL, and is then drawn with lines. Points and lengths are in world units. A
/// fill whose opacity `a` is 0 is not filled: only the outline is drawn. The functions may
/// read the world, not change it: a change from inside them is misuse.
typedef struct jostle_debug_draw {
    void (*line)(jostle_vec2 from, jostle_vec2 to, jostle_colour colour, void* user);
    /// An axis-aligned box by its centre and half extents.
    void (*box)(jostle_vec2 centre, jostle_vec2 half, jostle_colour fill, jostle_colour outline,
                void* user);
    /// A box whose corners are rounded by `radius`: a circle when both half extents are
    /// the radius, a capsule when one is.
    void (*rounded_box)(jostle_vec2 centre, jostle_vec2 half, float radius, jostle_colour fill,
                        jostle_colour outline, void* user);
    /// A triangle (a ramp), its corners in order around it.
    void (*triangle)(jostle_vec2 a, jostle_vec2 b, jostle_vec2 c, jostle_colour fill,
                     jostle_colour outline, void* user);
    /// A point (a contact), `size` wide.
    void (*point)(jostle_vec2 at, float size, jostle_colour colour, void* user);
    void* user;
} jostle_debug_draw;

/// Draws the world as the engine sees it through `draw` (World::debugDraw): every body in
/// its shape and colour, and what `options` asks for (NULL: the defaults). False on misuse
/// (draw or draw->line NULL, options not made by jostle_default_debug_draw_options, a mark
/// length not a finite number >= 0, a view corner not finite, a percentage outside
/// [0, 100]); then nothing was drawn.
bool jostle_world_debug_draw(const jostle_world* world, const jostle_debug_draw* draw,
                             const jostle_debug_draw_options* options);

// === A fixed time step (docs/fixed-step.md) ================================================

/// Turns variable frame times into a whole number of steps of a fixed dt
/// (jostle::FixedStep). Opaque.
typedef struct jostle_fixed_step jostle_fixed_step;

/// A clock of step `dt` seconds, in [1e-6, 3600], giving at most `max_steps_per_frame`
/// steps a frame, in [1, 100000] (8 is a good choice: see fixed_step.hpp). NULL on
/// misuse.
jostle_fixed_step* jostle_fixed_step_create(float dt, int max_steps_per_frame);

/// Frees the clock. NULL does nothing and is not an error.
void jostle_fixed_step_destroy(jostle_fixed_step* clock);

/// Adds the time of one frame (finite, >= 0) and returns how many steps of dt to take
/// now, from 0 to max_steps_per_frame; the time left over waits for later frames.
int jostle_fixed_step_advance(jostle_fixed_step* clock, float frame_seconds);

/// jostle_fixed_step_advance, then jostle_world_step(world, dt) that many times; returns
/// the number of steps taken. Before the last of them it keeps where every body is, for
/// jostle_fixed_step_draw_position. If a step fails (from inside a callback, say), the
/// steps left are not taken, their time is lost, the error is recorded and it returns the
/// steps taken so far.
int jostle_fixed_step_update(jostle_fixed_step* clock, jostle_world* world, float frame_seconds);

/// What jostle_fixed_step_update_each calls after each step, with the world and the
/// context it was given.
typedef void (*jostle_after_step_fn)(jostle_world* world, void* context);

/// jostle_fixed_step_update, calling after_step(world, context) after each step: where a
/// game reads the step's events. A world's events are the last step's, so a frame of
/// several steps that reads them once, after jostle_fixed_step_update, misses the others'.
/// after_step may change the world, as between any two steps, but not destroy it. NULL
/// after_step: as jostle_fixed_step_update.
int jostle_fixed_step_update_each(jostle_fixed_step* clock, jostle_world* world,
                                  float frame_seconds, jostle_after_step_fn after_step,
                                  void* context);

/// Keeps where every body of `world` is now, for jostle_fixed_step_draw_position:
/// jostle_fixed_step_update calls it before the last step it takes; a game that steps the
/// world by hand (jostle_fixed_step_advance, then jostle_world_step) calls it before the
/// last step of a frame.
bool jostle_fixed_step_remember_positions(jostle_fixed_step* clock, const jostle_world* world);

/// How far the time left over reaches towards the next step, in [0, 1): draw bodies at
/// previous + (current - previous) * alpha. 0 on misuse.
float jostle_fixed_step_alpha(const jostle_fixed_step* clock);

/// Where to draw a body now: between where it was before the last step
/// jostle_fixed_step_update took and where it is, by alpha, so that motion looks smooth
/// when the frame rate and the step rate differ. Where it is for a body the clock has not
/// stepped yet (created since). {0, 0} on misuse (a stale body...).
jostle_vec2 jostle_fixed_step_draw_position(const jostle_fixed_step* clock,
                                            const jostle_world* world, jostle_body_id body);

/// jostle_fixed_step_draw_position of every live body, in the order of
/// jostle_world_bodies, into out[0 .. capacity); returns how many bodies there are (the
/// buffer rule of jostle_world_bodies).
int jostle_fixed_step_read_draw_positions(const jostle_fixed_step* clock, const jostle_world* world,
                                          jostle_vec2* out, int capacity);

/// The seconds the last advance dropped because of the cap.
double jostle_fixed_step_dropped_seconds(const jostle_fixed_step* clock);

float jostle_fixed_step_dt(const jostle_fixed_step* clock);
int jostle_fixed_step_max_steps_per_frame(const jostle_fixed_step* clock);

/// Forgets the time left over, the dropped time and where bodies were before the last step,
/// as a new clock would (after a pause, a level load or a restored snapshot: a restored
/// world is then drawn where it is).
bool jostle_fixed_step_reset(jostle_fixed_step* clock);

/// The time left over, not yet stepped, in whole nanoseconds: all the clock carries from
/// frame to frame, to save beside a world's snapshot (docs/rollback.md). 0 on misuse.
int64_t jostle_fixed_step_pending_nanoseconds(const jostle_fixed_step* clock);

/// Puts back what jostle_fixed_step_pending_nanoseconds gave, of a clock with the same dt;
/// false, changing nothing, for a value no such clock can have.
bool jostle_fixed_step_set_pending_nanoseconds(jostle_fixed_step* clock, int64_t nanoseconds);

JOSTLE_EXPORT_END
#ifdef __cplusplus
} // extern "C"
#endif

#endif // JOSTLE_JOSTLE_H
