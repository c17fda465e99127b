// Helpers shared by the samples: see sample.hpp.
#include "sample.hpp"

#include <algorithm>

namespace jostle::demo {

WorldBox boundsOf(const World& world) {
    const auto bodies = world.bodies();
    if (bodies.empty())
        return {{-1.0f, -1.0f}, {1.0f, 1.0f}};
    WorldBox bounds{world.position(bodies.front()), world.position(bodies.front())};
    for (BodyId body : bodies) {
        const Vec2 centre = world.position(body);
        const Vec2 half = world.halfExtents(body);
        bounds.min = {std::min(bounds.min.x, centre.x - half.x),
                      std::min(bounds.min.y, centre.y - half.y)};
        bounds.max = {std::max(bounds.max.x, centre.x + half.x),
                      std::max(bounds.max.y, centre.y + half.y)};
    }
    return bounds;
}

WorldBox withHeadroom(WorldBox box, float fraction) {
    box.min.y -= (box.max.y - box.min.y) * fraction;
    return box;
}

Pane paneWithWorld(const WorldDef& def) {
    Pane pane;
    pane.world = std::make_unique<World>(def);
    return pane;
}

Pane paneFromScene(const Scene& scene, std::string title, float headroom) {
    Pane pane = paneWithWorld(scene.world);
    addTileMaps(*pane.world, scene);
    addBodies(*pane.world, scene);
    pane.view = withHeadroom(boundsOf(*pane.world), headroom);
    pane.title = std::move(title);
    return pane;
}

DebugDrawOptions paneDrawOptions(bool debug, float markLength, WorldBox view) {
    DebugDrawOptions options{.contacts = debug,
                             .velocities = debug,
                             .touching = debug,
                             .grid = debug,
                             .markLength = markLength,
                             .viewMin = view.min,
                             .viewMax = view.max};
    if (!debug)
        options.palette.sleepingPercent = 100;
    return options;
}

} // namespace jostle::demo
