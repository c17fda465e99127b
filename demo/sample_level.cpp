// Sample 9: the example level drawn in Tiled (examples/levels/level.tmj, docs/levels.md),
// read with jostle::parseTiled and played. The level says where everything is: the
// character starts on its "spawn" point, the lift rides between where it is drawn and its
// "top" property, the coins are its sensors, collected on touch. Its gravity is the map's.
#include "runner.hpp"
#include "sample_list.hpp"

#include "example_scenes.hpp"

#include "jostle/level.hpp"

#include <cmath>
#include <cstdio>
#include <variant>

namespace jostle::demo {

namespace {

constexpr float kRunSpeed = 120.0f;
/// Jump three and a half tiles (16 px) high under the map's gravity.
constexpr float kJumpHeight = 56.0f;
constexpr float kLiftSpeed = 40.0f;
/// The character: 10 × 14 px, its feet where the spawn point is.
constexpr float kHalfWidth = 5.0f;
constexpr float kHalfHeight = 7.0f;

Level exampleLevel() {
    return parseTiled(kExampleLevelJson, "level.tmj", [](const std::string& path) -> std::string {
        throw Error("level.tmj: names a file (" + path + "), but its tilesets are embedded");
    });
}

float numberOf(const LevelObject& object, const char* property) {
    const auto found = object.properties.find(property);
    if (found == object.properties.end() || !std::holds_alternative<double>(found->second))
        throw Error("level.tmj: object \"" + object.name + "\": no number \"" + property + "\"");
    return static_cast<float>(std::get<double>(found->second));
}

class LevelSample : public Sample {
public:
    const char* name() const override { return "level"; }
    bool usesLetterKeys() const override { return true; }
    BodyId player() const override { return runner_.body(); }

    void reset() override {
        panes_.clear();
        const Level level = exampleLevel();
        Pane pane = paneWithWorld(level.scene.world);
        World& world = *pane.world;
        addTileMaps(world, level.scene);
        const std::vector<BodyId> bodies = addBodies(world, level.scene);
        coins_.clear();
        collected_ = 0;
        lift_ = {};
        for (const LevelObject& object : level.objects) {
            if (object.body < 0)
                continue; // a point, or an object made into no body
            if (object.type == "coin")
                coins_.push_back(bodies[static_cast<std::size_t>(object.body)]);
            if (object.type == "lift") {
                lift_ = bodies[static_cast<std::size_t>(object.body)];
                liftBottom_ = object.y;
                liftTop_ = numberOf(object, "top");
                world.setVelocity(lift_, {0.0f, -kLiftSpeed});
            }
        }
        const LevelObject* spawn = level.find("spawn");
        if (spawn == nullptr)
            throw Error("level.tmj: no object named \"spawn\"");
        const BodyId player = world.createBody({.x = spawn->x,
                                                .y = spawn->y - kHalfHeight,
                                                .hw = kHalfWidth,
                                                .hh = kHalfHeight,
                                                .friction = 0.8f,
                                                .character = true,
                                                .cornerCorrection = 4.0f,
                                                .stepUp = 5.0f});
        const float gravity = world.gravity().y;
        runner_ =
            Runner(player, kRunSpeed,
                   {.height = kJumpHeight, .timeToApex = std::sqrt(2.0f * kJumpHeight / gravity)});
        pane.labels.push_back({player, "YOU"});
        pane.view = boundsOf(world);
        pane.title = "level.tmj (tiled)";
        panes_.push_back(std::move(pane));
    }

    void beforeStep(const Controls& controls, float /*dt*/) override {
        World& world = *panes_.front().world;
        // The last step's touches: a coin the character met is collected.
        for (const SensorEvent& event : world.sensorBegins())
            if (event.visitor == runner_.body() && world.isValid(event.sensor) &&
                std::erase(coins_, event.sensor) == 1) {
                world.destroyBody(event.sensor);
                ++collected_;
            }
        runner_.steer(world, controls);
        if (!world.isValid(lift_))
            return;
        // The lift turns round at either end of its ride.
        const float y = world.position(lift_).y;
        const float vy = world.velocity(lift_).y;
        if ((y <= liftTop_ && vy < 0.0f) || (y >= liftBottom_ && vy > 0.0f))
            world.setVelocity(lift_, {0.0f, -vy});
    }

    void report() const override { std::printf("coins %d\n", collected_); }

private:
    Runner runner_;
    BodyId lift_;
    float liftTop_ = 0.0f;
    float liftBottom_ = 0.0f;
    std::vector<BodyId> coins_;
    int collected_ = 0;
};

} // namespace

std::unique_ptr<Sample> makeLevelSample() {
    return std::make_unique<LevelSample>();
}

} // namespace jostle::demo
