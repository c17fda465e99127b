// jostle-web-scenes: the shared scenes (shared/scenes.hpp) the web benchmark runs, written
// as scene files (docs/scene-format.md), so that bench/web/bench.mjs builds the very same
// bodies in jostle's npm package, matter-js, Rapier and planck.
//   jostle-web-scenes <directory>   → <directory>/<scene>.json, one a scene
#include "jostle/scene.hpp"
#include "shared/scenes.hpp"

#include <cstdio>
#include <fstream>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace {

/// A scene as a file: its gravity, sleeping off (as the benchmark runs every engine), and
/// its bodies with their ids.
std::string sceneFile(const jostle::Scene& scene) {
    char gravity[80];
    std::snprintf(gravity, sizeof gravity, "[%.9g, %.9g]",
                  static_cast<double>(scene.world.gravity.x),
                  static_cast<double>(scene.world.gravity.y));
    std::string out =
        std::string("{\"gravity\": ") + gravity + ", \"sleeping\": false, \"bodies\": [\n";
    for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
        const std::string body = jostle::bodyToJson(scene.bodies[i].def);
        out += "  {\"id\": \"" + scene.bodies[i].id + "\", " + body.substr(1);
        out += i + 1 < scene.bodies.size() ? ",\n" : "\n";
    }
    return out + "]}\n";
}

} // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: jostle-web-scenes <directory>\n");
        return 2;
    }
    namespace shared = jostle::shared;
    // Sizes a web game has, each a scene of jostle-bench at a size every peer runs in time.
    const std::vector<std::pair<std::string, std::function<jostle::Scene()>>> scenes = {
        {"pyramid_20", [] { return shared::pyramid(20); }},
        {"pyramid_50", [] { return shared::pyramid(50); }},
        {"many_pyramids_10", [] { return shared::manyPyramids(10, 20); }},
        {"rain_2k", [] { return shared::rain(2000); }},
        {"gas_2k", [] { return shared::gas(2000); }},
        {"tilemap_1k", [] { return shared::tilemap(1000); }},
        {"floor_5k", [] { return shared::crowdOnFloor(5000, 1); }},
    };
    for (const auto& [name, make] : scenes) {
        const std::string path = std::string(argv[1]) + "/" + name + ".json";
        std::ofstream file(path);
        file << sceneFile(make());
        if (!file) {
            std::fprintf(stderr, "jostle-web-scenes: %s: cannot write\n", path.c_str());
            return 1;
        }
        std::printf("%s\n", path.c_str());
    }
}
