// Dispatch from an engine's kind to its builder.
#include "engine.hpp"

#ifndef JOSTLE_BENCH_HAS_BOX2D3
#define JOSTLE_BENCH_HAS_BOX2D3 0
#endif

namespace jostle::bench {

std::string_view name(EngineKind kind) {
    switch (kind) {
    case EngineKind::Jostle:
        return "jostle";
    case EngineKind::JostleSleeping:
        return "jostle+sleep";
    case EngineKind::Box2D:
        return "box2d";
    case EngineKind::Chipmunk:
        return "chipmunk";
    case EngineKind::Box2D3:
        return "box2d3";
    }
    return "?";
}

bool takesWorkers(EngineKind kind) {
    return kind == EngineKind::Jostle || kind == EngineKind::JostleSleeping ||
           kind == EngineKind::Box2D3;
}

bool box2d3Built() {
    return JOSTLE_BENCH_HAS_BOX2D3 != 0;
}

std::unique_ptr<Engine> makeEngine(EngineKind kind, const Scene& scene, int workers) {
    switch (kind) {
    case EngineKind::Jostle:
        return makeJostle(scene, false, workers);
    case EngineKind::JostleSleeping:
        return makeJostle(scene, true, workers);
    case EngineKind::Box2D:
        return makeBox2D(scene);
    case EngineKind::Chipmunk:
        return makeChipmunk(scene);
    case EngineKind::Box2D3:
        return makeBox2D3(scene, workers);
    }
    return nullptr;
}

#if !JOSTLE_BENCH_HAS_BOX2D3
// Without Box2D v3 box2d3Built() is false, and the box2d3 engine is never chosen.
std::unique_ptr<Engine> makeBox2D3(const Scene&, int) {
    return nullptr;
}
std::string_view describeBox2D3() {
    return {};
}
#endif

} // namespace jostle::bench
