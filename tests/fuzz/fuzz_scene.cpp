// libFuzzer: any bytes as a scene file (jostle::parseScene).
//
// The contract (docs/scene-format.md): a file either loads, or is refused with a
// jostle::SceneError whose message is one readable line. A scene that loads holds only
// values the world accepts, so building a world from it never throws, and stepping that
// world keeps every invariant of tests/fuzz/invariants.hpp. Anything else (another
// exception, a crash, a sanitizer report, a NaN) is a finding: the fuzzer aborts.
#include "invariants.hpp"

#include "jostle/scene.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <set>
#include <string>
#include <string_view>

namespace {

using namespace jostle;

[[noreturn]] void finding(const std::string& what) {
    std::fprintf(stderr, "fuzz_scene finding: %s\n", what.c_str());
    std::fflush(stderr);
    std::abort();
}

/// True for well-formed UTF-8 (the error messages promise to show other bytes as <0xFF>).
bool isUtf8(std::string_view text) {
    std::size_t i = 0;
    while (i < text.size()) {
        const auto byte = static_cast<unsigned char>(text[i]);
        const std::size_t length = byte < 0x80           ? 1
                                   : (byte >> 5) == 0x6  ? 2
                                   : (byte >> 4) == 0xE  ? 3
                                   : (byte >> 3) == 0x1E ? 4
                                                         : 0;
        if (length == 0 || i + length > text.size())
            return false;
        for (std::size_t k = 1; k < length; ++k)
            if ((static_cast<unsigned char>(text[i + k]) & 0xC0) != 0x80)
                return false;
        i += length;
    }
    return true;
}

void checkMessage(const SceneError& error) {
    const std::string_view message = error.what();
    if (message.empty())
        finding("SceneError with an empty message");
    if (message.find_first_of("\r\n") != std::string_view::npos)
        finding("SceneError message is not one line: " + std::string(message));
    if (!isUtf8(message))
        finding("SceneError message is not UTF-8: " + std::string(message));
}

/// What parseScene promises of a scene it returns.
void checkScene(const Scene& scene) {
    if (auto problem = checkWorldDef(scene.world))
        finding("loaded a world that checkWorldDef refuses: " + problem->field + ": " +
                problem->problem);
    if (!(scene.dt > 0.0f) || !std::isfinite(scene.dt))
        finding("loaded dt " + std::to_string(scene.dt));
    std::set<std::string> ids;
    for (const SceneBody& body : scene.bodies) {
        if (body.id.empty() || !ids.insert(body.id).second)
            finding("loaded an empty or duplicate id \"" + body.id + "\"");
        // No control character: C0, DEL, and C1 (U+0080 to U+009F, C2 80 to C2 9F).
        for (std::size_t i = 0; i < body.id.size(); ++i) {
            const auto byte = static_cast<unsigned char>(body.id[i]);
            const auto next =
                i + 1 < body.id.size() ? static_cast<unsigned char>(body.id[i + 1]) : 0u;
            if (byte < 0x20 || byte == 0x7F || (byte == 0xC2 && next >= 0x80 && next <= 0x9F))
                finding("loaded an id with a control character");
        }
        if (auto problem = checkBodyDef(body.def))
            finding("loaded body \"" + body.id + "\" that checkBodyDef refuses: " + problem->field +
                    ": " + problem->problem);
    }
    for (const TileMapDef& map : scene.tileMaps)
        if (auto problem = checkTileMapDef(map))
            finding("loaded a tile map that checkTileMapDef refuses: " + problem->field + ": " +
                    problem->problem);
}

/// Builds the world as `jostle run` does (maps first) and steps it a little.
void runScene(const Scene& scene) {
    try {
        World world(scene.world);
        addTileMaps(world, scene);
        addBodies(world, scene);
        // A map's boxes are at most one a solid tile, and its ramps at most two a ramp tile
        // (a lone high half of a 2:1 ramp is a ramp and the box under it).
        std::size_t tiles = 0;
        for (const TileMapDef& map : scene.tileMaps)
            for (const std::string& row : map.rows)
                for (char tile : row)
                    tiles += tile == '#' ? 1 : tile == '.' ? 0 : 2;
        if (world.bodyCount() > scene.bodies.size() + tiles)
            finding("more bodies than the scene's bodies, solid tiles and ramps");
        // A few steps exercise every path of the step; big scenes get fewer, so that one
        // input never takes long.
        const int steps = world.bodyCount() > 500 ? 2 : 8;
        for (int i = 0; i < steps; ++i) {
            world.step(scene.dt);
            if (auto problem = check::finiteState(world))
                finding("after step " + std::to_string(i + 1) + ": " + *problem);
        }
    } catch (const Error& error) {
        finding(std::string("a scene that loads was refused by the world: ") + error.what());
    }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    Scene scene;
    try {
        scene = parseScene(text);
    } catch (const SceneError& error) {
        checkMessage(error);
        return 0; // refused, as bad input should be
    }
    // Any other exception escapes, and libFuzzer reports it as a crash.
    checkScene(scene);
    runScene(scene);
    return 0;
}
