// libFuzzer: any bytes as a Tiled map (jostle::parseTiled), JSON or XML by its first byte,
// with one external tileset at hand ("tiles.tsj", itself a JSON tileset of the corpus);
// and the same bytes as an LDtk project (jostle::parseLdtk), its level "Level_0".
//
// The contract (docs/levels.md): a map either loads, or is refused with a SceneError whose
// message is one line naming the file. A level that loads builds a world without an
// error: its tile maps and bodies are all ones the world accepts. Anything else (another
// exception, a crash, a sanitizer report) is a finding: the fuzzer aborts.
#include "jostle/level.hpp"
#include "jostle/tilemap.hpp"
#include "jostle/world.hpp"

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace {

using namespace jostle;

[[noreturn]] void finding(const std::string& what) {
    std::fprintf(stderr, "fuzz_tiled finding: %s\n", what.c_str());
    std::fflush(stderr);
    std::abort();
}

const char* const kTileset = R"({"name": "tiles", "tilewidth": 16, "tileheight": 16, "tilecount": 4,
  "tiles": [{"id": 0, "properties": [{"name": "collision", "type": "string", "value": "solid"}]},
            {"id": 1, "properties": [{"name": "collision", "type": "string", "value": "/"}]}]})";

/// Loads a level with `load`: a SceneError naming the file, or a level whose world builds
/// and steps without an error.
template <class Load> void buildIfItLoads(Load&& load) {
    Level level;
    try {
        level = load();
    } catch (const SceneError& error) {
        const std::string message = error.what();
        if (!message.starts_with("fuzz.tmj: "))
            finding("a message that does not name the file: " + message);
        if (message.find('\n') != std::string::npos)
            finding("a message of more than one line: " + message);
        return;
    } catch (const std::exception& error) {
        finding(std::string("not a SceneError: ") + error.what());
    }
    try {
        // Within reason: a level too big to build here is the loader's to allow.
        std::size_t tiles = 0;
        for (const TileMapDef& map : level.scene.tileMaps)
            tiles += map.rows.size() * (map.rows.empty() ? 0 : map.rows.front().size());
        if (tiles > 1 << 20 || level.scene.bodies.size() > 10000)
            return;
        World world(level.scene.world);
        addTileMaps(world, level.scene);
        addBodies(world, level.scene);
        world.step(1.0f / 60.0f);
    } catch (const std::exception& error) {
        finding(std::string("a level that loads but does not build: ") + error.what());
    }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    const FileReader tileset = [](const std::string& path) -> std::string {
        if (path == "tiles.tsj")
            return kTileset;
        throw SceneError(path + ": cannot read the file");
    };
    buildIfItLoads([&] { return parseTiled(text, "fuzz.tmj", tileset); });
    buildIfItLoads([&] { return parseLdtk(text, "fuzz.tmj", "Level_0", tileset, {{4, "none"}}); });
    return 0;
}
