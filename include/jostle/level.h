/* jostle/level.h: levels drawn in Tiled or LDtk, for C (docs/levels.md; C99 or later). The
 * C face of jostle/level.hpp, in the library jostle::level beside the scene library:
 *
 *     jostle_level* level = jostle_level_load_tiled("level.tmj");   // NULL: jostle_last_error()
 *     jostle_world* world = jostle_level_create_world(level, NULL);  // its tile maps and bodies
 *     int spawn = jostle_level_find(level, "spawn");
 *     jostle_level_object o;
 *     jostle_level_get_object(level, spawn, &o);                      // o.centre, o.body...
 *     ...
 *     jostle_world_destroy(world);
 *     jostle_level_destroy(level);
 *
 * Errors follow jostle.h's contract: a function that fails returns NULL, false or -1 and
 * records "function: message" for jostle_last_error(), the message naming the file and the
 * place ("jostle_level_load_tiled: level.tmj: layer "ground": tile 37 (column 5, row 2):
 * collision shape is not a rectangle or a ramp"). */
#ifndef JOSTLE_LEVEL_H
#define JOSTLE_LEVEL_H

#include "jostle/jostle.h"

#ifdef __cplusplus
extern "C" {
#endif

/* A level read from a file: its scene and its objects (jostle::Level). Opaque. */
typedef struct jostle_level jostle_level;

/* Reads a Tiled map (.tmj, .json or .tmx) with the external tilesets it names, read beside
 * it (jostle::loadTiled). NULL on a problem. */
jostle_level* jostle_level_load_tiled(const char* path);

/* What an LDtk IntGrid value is: "solid", "oneWay", "none" or a ramp's character. */
typedef struct jostle_intgrid_kind {
    int value;
    const char* kind;
} jostle_intgrid_kind;

/* Reads the level named `level` of an LDtk project (jostle::loadLdtk); `kinds`, `count`
 * pairs (NULL when count is 0), say what IntGrid values are, else their identifiers do. */
jostle_level* jostle_level_load_ldtk(const char* path, const char* level, const jostle_intgrid_kind* kinds,
                                     int count);

/* Frees the level (not a world made from it). NULL does nothing. */
void jostle_level_destroy(jostle_level* level);

/* Makes the level's world: its settings, its tile maps, then its bodies, whose handles the
 * level keeps for jostle_level_get_object. `tasks` (NULL: the calling thread alone) as
 * jostle_world_def.tasks. The world is the caller's: jostle_world_destroy it. NULL on a
 * problem. Each call makes a new world; the objects name the last one's bodies. */
jostle_world* jostle_level_create_world(jostle_level* level, const jostle_task_system* tasks);

/* How many objects the level has (every object of every object layer; LDtk's entities). */
int jostle_level_object_count(const jostle_level* level);

/* An object of a level (jostle::LevelObject). Its strings belong to the level. */
typedef struct jostle_level_object {
    const char* name;   /* its name in the editor ("" if none) */
    const char* type;   /* Tiled's class; an LDtk entity's identifier */
    const char* layer;  /* the layer it is on */
    int id;             /* Tiled's object id */
    jostle_vec2 centre; /* a point's position */
    jostle_vec2 half;   /* half its width and height ({0, 0} for a point) */
    /* The body made from it in the world jostle_level_create_world made last; the null
     * handle if none, or before that. body_count: how many (a polygon makes one a side,
     * the rest jostle_level_get_body gives). */
    jostle_body_id body;
    int body_count;
} jostle_level_object;

/* Object `i` (from 0, in file order) into *out; false on misuse. */
bool jostle_level_get_object(const jostle_level* level, int i, jostle_level_object* out);

/* The first object named `name`, or -1 (an ordinary answer). */
int jostle_level_find(const jostle_level* level, const char* name);

/* Body `k` (from 0, below body_count) of object `i`, in the last world made; the null
 * handle on misuse. */
jostle_body_id jostle_level_get_body(const jostle_level* level, int i, int k);

/* What a custom property holds. */
typedef enum jostle_property_kind JOSTLE_ENUM_BASE_ {
    JOSTLE_PROPERTY_NONE = 0, /* the object has no property of that name */
    JOSTLE_PROPERTY_BOOL = 1,
    JOSTLE_PROPERTY_NUMBER = 2,
    JOSTLE_PROPERTY_TEXT = 3,
} jostle_property_kind;

/* Object i's custom property `name`: its kind, and its value in the one of *boolean,
 * *number, *text that matches (each may be NULL; the text belongs to the level). */
jostle_property_kind jostle_level_get_property(const jostle_level* level, int i, const char* name, bool* boolean,
                                               double* number, const char** text);

#ifdef __cplusplus
} /* extern "C" */
#endif

#endif /* JOSTLE_LEVEL_H */
