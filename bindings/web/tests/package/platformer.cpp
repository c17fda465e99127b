// platformer.ts's level played by the C++ API, frame for frame: the package's runners
// check that JavaScript gives what this prints (the same events on the same frames, the
// same state hash), so that the package is jostle with the same bits.
//   jostle-package-platformer → one line of JSON: what platformer.ts's play() returns
#include "jostle/tilemap.hpp"
#include "jostle/world.hpp"

#include <cinttypes>
#include <cstdio>
#include <optional>

using namespace jostle;

int main() {
    constexpr float dt = 1.0f / 60.0f;
    WorldDef def;
    def.gravity = {0, 800};
    World world(def);
    TileMapDef floor;
    floor.y = 160;
    floor.tile = 16;
    floor.rows = {"###################...##########"};
    createTileMap(world, floor);
    const BodyId hero = world.createBody({.x = 32, .y = 150, .hw = 6, .hh = 10, .character = true});
    const BodyId coin = world.createBody(
        {.type = BodyType::Static, .x = 96, .y = 150, .hw = 4, .hh = 4, .sensor = true});
    const BodyId platform = world.createBody(
        {.type = BodyType::Static, .x = 200, .y = 112, .hw = 32, .hh = 4, .oneWay = {0, -1}});
    const BodyId lift =
        world.createBody({.type = BodyType::Kinematic, .x = 328, .y = 166, .hw = 24, .hh = 6});

    int coinFrame = -1, landedOnPlatformFrame = -1, onLiftFrame = -1;
    bool jumped = false;
    for (int frame = 0; frame < 600 && onLiftFrame < 0; ++frame) {
        const std::optional<Ground> ground = world.ground(hero);
        world.setWalkSpeed(hero, 80);
        if (!jumped && ground && world.position(hero).x >= 150) {
            world.setVelocity(hero, {world.velocity(hero).x, -360});
            jumped = true;
        }
        world.step(dt);
        for (const SensorEvent& event : world.sensorBegins())
            if (event.sensor == coin && event.visitor == hero && coinFrame < 0)
                coinFrame = frame;
        const std::optional<Ground> under = world.ground(hero);
        if (under && under->body == platform && landedOnPlatformFrame < 0)
            landedOnPlatformFrame = frame;
        if (under && under->body == lift && world.position(hero).x > 320)
            onLiftFrame = frame;
    }
    world.setWalkSpeed(hero, 0);
    world.step(dt);
    const float before = world.position(hero).y;
    world.setVelocity(lift, {0, -40});
    for (int frame = 0; frame < 60; ++frame)
        world.step(dt);
    const std::optional<Ground> ground = world.ground(hero);
    std::printf("{\"coinFrame\": %d, \"landedOnPlatformFrame\": %d, \"onLiftFrame\": %d, "
                "\"rise\": %.9g, \"liftSpeedUnderFeet\": %.9g, \"stateHash\": \"%016" PRIx64
                "\"}\n",
                coinFrame, landedOnPlatformFrame, onLiftFrame,
                static_cast<double>(before - world.position(hero).y),
                static_cast<double>(ground ? ground->velocity.y : 0.0f), world.stateHash());
}
