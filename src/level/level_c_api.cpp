// The C face of levels (include/jostle/level.h) over jostle::loadTiled and loadLdtk, with
// jostle.h's error contract (src/c_api/misuse.hpp): each function runs in a guard that
// records "function: message" instead of letting an exception reach C.
#include "jostle/level.h"

#include "c_api/c_api.hpp"
#include "jostle/level.hpp"

#include <string>
#include <vector>

using namespace jostle;
using namespace jostle::c_api;

struct jostle_level {
    Level level;
    /// The bodies of the world made last, in the order of level.scene.bodies.
    std::vector<BodyId> bodies;
};

namespace {

const LevelObject& objectOf(const jostle_level* level, int i) {
    const jostle_level& l = required(level, "level");
    if (i < 0 || static_cast<std::size_t>(i) >= l.level.objects.size())
        misuse("object " + std::to_string(i) + ": the level has " +
               std::to_string(l.level.objects.size()));
    return l.level.objects[static_cast<std::size_t>(i)];
}

} // namespace

extern "C" {

jostle_level* jostle_level_load_tiled(const char* path) {
    return guard<jostle_level*>(__func__, nullptr, [&] {
        required(path, "path");
        return new jostle_level{loadTiled(path), {}};
    });
}

jostle_level* jostle_level_load_ldtk(const char* path, const char* level,
                                     const jostle_intgrid_kind* kinds, int count) {
    return guard<jostle_level*>(__func__, nullptr, [&] {
        required(path, "path");
        required(level, "level");
        if (count < 0 || (count > 0 && kinds == nullptr))
            misuse("kinds: expected count >= 0 pairs, not NULL when count > 0");
        IntGridKinds table;
        for (int k = 0; k < count; ++k) {
            required(kinds[k].kind, "kinds[].kind");
            table[kinds[k].value] = kinds[k].kind;
        }
        return new jostle_level{loadLdtk(path, level, table), {}};
    });
}

void jostle_level_destroy(jostle_level* level) {
    delete level;
}

jostle_world* jostle_level_create_world(jostle_level* level, const jostle_task_system* tasks) {
    return guard<jostle_world*>(__func__, nullptr, [&] {
        jostle_level& l = required(level, "level");
        jostle_world_def def = toC(l.level.scene.world);
        if (tasks != nullptr)
            def.tasks = *tasks;
        jostle_world* world = jostle_world_create(&def);
        if (world == nullptr)
            throw Error(std::string(jostle_last_error())); // the world's own refusal
        try {
            addTileMaps(world->world, l.level.scene);
            l.bodies = addBodies(world->world, l.level.scene);
        } catch (...) {
            jostle_world_destroy(world);
            throw;
        }
        return world;
    });
}

int jostle_level_object_count(const jostle_level* level) {
    return guard(__func__, 0,
                 [&] { return static_cast<int>(required(level, "level").level.objects.size()); });
}

bool jostle_level_get_object(const jostle_level* level, int i, jostle_level_object* out) {
    return guard(__func__, false, [&] {
        const LevelObject& o = objectOf(level, i);
        jostle_level_object& c = required(out, "out");
        c.name = o.name.c_str();
        c.type = o.type.c_str();
        c.layer = o.layer.c_str();
        c.id = o.id;
        c.centre = {o.x, o.y};
        c.half = {o.hw, o.hh};
        c.body_count = o.bodyCount;
        c.body = o.body >= 0 && static_cast<std::size_t>(o.body) < level->bodies.size()
                     ? toC(level->bodies[static_cast<std::size_t>(o.body)])
                     : jostle_body_id{};
        return true;
    });
}

int jostle_level_find(const jostle_level* level, const char* name) {
    return guard(__func__, -1, [&] {
        const jostle_level& l = required(level, "level");
        required(name, "name");
        for (std::size_t i = 0; i < l.level.objects.size(); ++i)
            if (l.level.objects[i].name == name)
                return static_cast<int>(i);
        return -1;
    });
}

jostle_body_id jostle_level_get_body(const jostle_level* level, int i, int k) {
    return guard(__func__, jostle_body_id{}, [&] {
        const LevelObject& o = objectOf(level, i);
        if (k < 0 || k >= o.bodyCount)
            misuse("body " + std::to_string(k) + ": the object has " + std::to_string(o.bodyCount));
        const auto index = static_cast<std::size_t>(o.body + k);
        return index < level->bodies.size() ? toC(level->bodies[index]) : jostle_body_id{};
    });
}

jostle_property_kind jostle_level_get_property(const jostle_level* level, int i, const char* name,
                                               bool* boolean, double* number, const char** text) {
    return guard(__func__, JOSTLE_PROPERTY_NONE, [&] {
        const LevelObject& o = objectOf(level, i);
        required(name, "name");
        const auto found = o.properties.find(name);
        if (found == o.properties.end())
            return JOSTLE_PROPERTY_NONE;
        if (const bool* b = std::get_if<bool>(&found->second)) {
            if (boolean != nullptr)
                *boolean = *b;
            return JOSTLE_PROPERTY_BOOL;
        }
        if (const double* d = std::get_if<double>(&found->second)) {
            if (number != nullptr)
                *number = *d;
            return JOSTLE_PROPERTY_NUMBER;
        }
        if (text != nullptr)
            *text = std::get<std::string>(found->second).c_str();
        return JOSTLE_PROPERTY_TEXT;
    });
}

} // extern "C"
