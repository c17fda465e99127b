// `jostle synctest` (synctest.hpp): GGPO's sync test over a scene file.
#include "synctest.hpp"

#include "errors.hpp"
#include "load_scene.hpp"

#include "jostle/scene.hpp"

#include <bit>
#include <cinttypes>
#include <cstdio>
#include <cstring>
#include <optional>
#include <vector>

namespace jostle::cli {

namespace {

using Bytes = std::vector<std::byte>;

std::string text(Vec2 v) {
    char out[80];
    std::snprintf(out, sizeof out, "(%.9g, %.9g)", double(v.x), double(v.y));
    return out;
}

bool same(Vec2 a, Vec2 b) {
    return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

/// The first body and field where `resimulated` and `original` differ, in words; or
/// what else differs when every body agrees.
std::string firstDifference(const World& resimulated, const World& original) {
    const auto a = resimulated.bodies(), b = original.bodies();
    if (a.size() != b.size())
        return std::to_string(a.size()) + " bodies against " + std::to_string(b.size());
    for (std::size_t k = 0; k < a.size(); ++k) {
        const std::string body =
            "body " + std::to_string(k) + " (slot " + std::to_string(a[k].index) + "): ";
        if (a[k].index != b[k].index || a[k].generation != b[k].generation)
            return body + "another body in its place (slot " + std::to_string(b[k].index) + ")";
        const struct {
            const char* name;
            Vec2 one, other;
        } fields[] = {
            {"position", resimulated.position(a[k]), original.position(b[k])},
            {"velocity", resimulated.velocity(a[k]), original.velocity(b[k])},
            {"halfExtents", resimulated.halfExtents(a[k]), original.halfExtents(b[k])},
            {"separation", resimulated.separation(a[k]), original.separation(b[k])},
        };
        for (const auto& field : fields)
            if (!same(field.one, field.other))
                return body + field.name + " " + text(field.one) + " against " + text(field.other);
        if (resimulated.isAwake(a[k]) != original.isAwake(b[k]))
            return body + "awake in one world only";
    }
    return "every body agrees; the rest of the state differs (contacts, islands, tile maps)";
}

} // namespace

int syncTest(const SyncTestOptions& options) {
    const Scene scene = loadScene(options.scene, options.solver);
    WorldDef def = scene.world;
    def.tasks.workers = static_cast<int>(options.workers);
    World world(def);
    addTileMaps(world, scene);
    addBodies(world, scene);

    // The snapshots of the last K + 1 states: ring[t % (K + 1)] is the state after t steps.
    const std::size_t slots = static_cast<std::size_t>(options.rollback) + 1;
    std::vector<Bytes> ring(slots);
    auto save = [&](std::int64_t t) {
        Bytes& bytes = ring[static_cast<std::size_t>(t) % slots];
        bytes.resize(world.snapshotSize());
        world.snapshot(bytes);
    };
    save(0);
    for (std::int64_t t = 1; t <= options.steps; ++t) {
        world.step(scene.dt);
        save(t);
        const Bytes& now = ring[static_cast<std::size_t>(t) % slots];
        const std::uint64_t hash = world.stateHash();
        if (t < options.rollback)
            continue;
        world.restore(ring[static_cast<std::size_t>(t - options.rollback) % slots]);
        for (std::int64_t again = t - options.rollback + 1; again <= t; ++again) {
            if (again == options.nudge && world.bodyCount() > 0) {
                const BodyId last = world.bodies().back();
                const Vec2 v = world.velocity(last);
                if (world.type(last) != BodyType::Static)
                    world.setVelocity(last, {std::nextafter(v.x, 1e30f), v.y});
            }
            world.step(scene.dt);
        }
        if (world.stateHash() != hash) {
            World original(def);
            original.restore(now);
            std::fprintf(stderr,
                         "jostle synctest: %s: step %" PRId64 ", stepped again after a rollback "
                         "of %" PRId64 ": %s\n",
                         options.scene.c_str(), t, options.rollback,
                         firstDifference(world, original).c_str());
            return kFailure;
        }
    }
    std::printf(
        "%s: %" PRId64 " steps, each rolled back %" PRId64 " steps and stepped again at %" PRId64
        " worker(s): the same state bit for bit (state hash %016" PRIx64 ")\n",
        options.scene.c_str(), options.steps, options.rollback, options.workers, world.stateHash());
    return 0;
}

} // namespace jostle::cli
