// Reads a Tiled map (JSON, and XML through pugixml) through the installed level library,
// in C++ and through its C API (whose worlds are the C API's), and makes its world; exits
// 0 if each gives the map's one floor and its spawn point.
#include <jostle/level.h>
#include <jostle/level.hpp>
#include <jostle/world.hpp>

#include <cstdio>
#include <string>

namespace {

// 2 x 1 tiles of 16 px, both solid (the tile property collision = solid), and a point.
constexpr const char* kJson = R"({"orientation": "orthogonal", "width": 2, "height": 1,
  "tilewidth": 16, "tileheight": 16, "infinite": false,
  "tilesets": [{"firstgid": 1, "tilecount": 1, "columns": 1, "tilewidth": 16, "tileheight": 16,
    "tiles": [{"id": 0, "properties": [{"name": "collision", "type": "string", "value": "solid"}]}]}],
  "layers": [{"type": "tilelayer", "name": "ground", "width": 2, "height": 1, "data": [1, 1]},
    {"type": "objectgroup", "name": "things", "objects": [{"id": 1, "name": "spawn", "point": true,
      "x": 8, "y": -4, "width": 0, "height": 0}]}]})";

constexpr const char* kXml = R"(<?xml version="1.0" encoding="UTF-8"?>
<map version="1.8" orientation="orthogonal" renderorder="right-down" width="2" height="1"
     tilewidth="16" tileheight="16" infinite="0">
 <tileset firstgid="1" name="t" tilewidth="16" tileheight="16" tilecount="1" columns="1">
  <tile id="0"><properties><property name="collision" value="solid"/></properties></tile>
 </tileset>
 <layer id="1" name="ground" width="2" height="1"><data encoding="csv">1,1</data></layer>
 <objectgroup id="2" name="things"><object id="1" name="spawn" x="8" y="-4"><point/></object></objectgroup>
</map>)";

bool check(const jostle::Level& level, const char* format) {
    jostle::World world(level.scene.world);
    jostle::addTileMaps(world, level.scene);
    jostle::addBodies(world, level.scene);
    const jostle::LevelObject* spawn = level.find("spawn");
    // The two tiles merge into one box, 32 x 16, centred at (16, 8).
    const bool ok = world.bodyCount() == 1 && world.position(world.bodies()[0]).x == 16.0f &&
                    spawn != nullptr && spawn->x == 8.0f && spawn->y == -4.0f;
    std::printf("%s: %zu body, spawn %s\n", format, world.bodyCount(), spawn ? "found" : "missing");
    return ok;
}

} // namespace

/// The C API: the map written to a file, loaded, its world made by the level.
bool checkC() {
    const char* path = "level_consumer_map.tmj";
    std::FILE* file = std::fopen(path, "w");
    if (file == nullptr || std::fputs(kJson, file) < 0 || std::fclose(file) != 0)
        return false;
    jostle_level* level = jostle_level_load_tiled(path);
    if (level == nullptr) {
        std::printf("C: %s\n", jostle_last_error());
        return false;
    }
    jostle_world* world = jostle_level_create_world(level, nullptr);
    const int spawn = jostle_level_find(level, "spawn");
    const bool ok = world != nullptr && jostle_world_body_count(world) == 1 && spawn >= 0;
    std::printf("C: %d body, spawn %s\n", world ? jostle_world_body_count(world) : 0,
                spawn >= 0 ? "found" : "missing");
    jostle_world_destroy(world);
    jostle_level_destroy(level);
    std::remove(path);
    return ok;
}

int main() {
    const auto noFiles = [](const std::string& path) -> std::string {
        throw jostle::Error("no file " + path);
    };
    const bool json = check(jostle::parseTiled(kJson, "map.tmj", noFiles), "tmj");
    const bool xml = check(jostle::parseTiled(kXml, "map.tmx", noFiles), "tmx");
    const bool c = checkC();
    return json && xml && c ? 0 : 1;
}
