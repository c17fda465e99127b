// Dispatch from an engine's kind to its builder.
#include "engine.hpp"

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
    }
    return "?";
}

bool takesWorkers(EngineKind kind) {
    return kind == EngineKind::Jostle || kind == EngineKind::JostleSleeping;
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
    }
    return nullptr;
}

} // namespace jostle::bench
