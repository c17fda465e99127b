// A game writes jostle's definitions with designated initializers, naming only the fields
// it sets (docs' examples do): with -Wall -Wextra that must not warn, so every member of a
// public aggregate has a default member initializer. Compiled with every warning an error.
#include <jostle/debug_draw.hpp>
#include <jostle/query.hpp>
#include <jostle/tasks.hpp>
#include <jostle/tilemap.hpp>
#include <jostle/world.hpp>

namespace {

[[maybe_unused]] void definitionsNamingOneField() {
    [[maybe_unused]] const jostle::WorldDef world{.gravity = {0, 800}};
    [[maybe_unused]] const jostle::BodyDef body{.hw = 1, .hh = 1};
    [[maybe_unused]] const jostle::TileMapDef map{.tile = 16};
    [[maybe_unused]] const jostle::QueryFilter filter{.includeSensors = true};
    [[maybe_unused]] const jostle::ClassicOptions classic{.mass = true};
    [[maybe_unused]] const jostle::PhysicalOptions physical{.velocityIterations = 4};
    [[maybe_unused]] const jostle::DebugDrawOptions draw{.contacts = true};
    [[maybe_unused]] const jostle::TaskSystem tasks{.workers = 2};
}

} // namespace
