// bench/engine.hpp: one scene built in one physics engine, stepped and read back.
//
// The engines (jostle, Box2D 2.4.1, Chipmunk 7, and Box2D v3 where it was built) hide
// behind this small interface so
// that the timing, the memory count and the quality figures are the same code for all of
// them. The virtual call costs once per step, nothing per body.
#pragma once

#include "jostle/scene.hpp"
#include "jostle/world.hpp"

#include <cstddef>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace jostle::bench {

/// A snapshot's size and the medians of its save, restore and state hash.
struct SnapshotFigures {
    std::size_t bytes = 0;
    double saveMicroseconds = 0.0;
    double restoreMicroseconds = 0.0;
    double hashMicroseconds = 0.0;
};

class Engine {
public:
    virtual ~Engine() = default;

    /// Advances the world by dt seconds.
    virtual void step(float dt) = 0;

    /// Writes the centre of every body, in scene order, to `out` (one per scene body).
    virtual void positions(std::span<Vec2> out) const = 0;

    /// Where the last step's time went, stage by stage: jostle's alone (World::profile).
    virtual const StepProfile* profile() const { return nullptr; }

    /// What a snapshot of the world as it is costs (docs/snapshots.md): jostle's alone.
    virtual std::optional<SnapshotFigures> measureSnapshots(int /*runs*/) { return std::nullopt; }
};

enum class EngineKind {
    Jostle,         ///< sleeping off: the timed figures
    JostleSleeping, ///< sleeping on: what a game gets by default
    Box2D,
    Chipmunk,
    Box2D3, ///< Box2D v3, when CMake was given one (-DJOSTLE_BENCH_BOX2D3=<prefix>)
};

/// Whether this build has Box2D v3 (box2d3Built: configured with JOSTLE_BENCH_BOX2D3).
bool box2d3Built();

/// The name printed in tables and CSV files: "jostle", "jostle+sleep", "box2d", "chipmunk",
/// "box2d3".
std::string_view name(EngineKind kind);

/// Whether the engine steps on several threads when asked: jostle, and Box2D v3 with its
/// own scheduler (the Debian builds of Box2D 2.4.1 and Chipmunk step on one).
bool takesWorkers(EngineKind kind);

/// Builds `scene` in the engine, on `workers` threads if it takesWorkers. An engine
/// stores nothing per body beyond its own bodies, so the memory measured around this call
/// is the engine's alone.
std::unique_ptr<Engine> makeEngine(EngineKind kind, const Scene& scene, int workers);

std::unique_ptr<Engine> makeJostle(const Scene& scene, bool sleeping, int workers);
std::unique_ptr<Engine> makeBox2D(const Scene& scene);
std::unique_ptr<Engine> makeChipmunk(const Scene& scene);
std::unique_ptr<Engine> makeBox2D3(const Scene& scene, int workers); ///< null if not built

// What jostle makes of a scene, for the peers to match it.

/// A body's mass in jostle: its explicit mass, or density × its box's area.
inline float massOf(const BodyDef& def) {
    return def.mass > 0.0f ? def.mass : def.density * 4.0f * def.hw * def.hh;
}

/// The restitution threshold jostle uses for the scene's world: the scene's, or 2 |g| dt.
inline float restitutionThresholdOf(const Scene& scene) {
    const float given = scene.world.physical.restitutionThreshold;
    return given > 0.0f ? given : 2.0f * length(scene.world.gravity) * scene.dt;
}

/// A peer's value for a body's type, given its three (its enumerators, say).
template <class T> T byType(BodyType type, T staticBody, T kinematicBody, T dynamicBody) {
    switch (type) {
    case BodyType::Static:
        return staticBody;
    case BodyType::Kinematic:
        return kinematicBody;
    case BodyType::Dynamic:
        break;
    }
    return dynamicBody;
}

/// How each engine is set up, one line each, for the top of the report.
std::string describeJostle();
std::string_view describeBox2D();
std::string_view describeChipmunk();
std::string_view describeBox2D3(); ///< empty if not built

} // namespace jostle::bench
