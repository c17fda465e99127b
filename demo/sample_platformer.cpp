// Sample 2: a platformer. A character steered by the keys (runner.hpp) on a tile-map
// level (createTileMap), with jump-through platforms (down + jump drops through them:
// World::dropThrough), a lift (a kinematic body going up and down), a conveyor belt
// (BodyDef::surfaceVelocity), two low steps it walks up (stepUp), corners it slips round
// when a jump clips them (cornerCorrection), and crates light enough to push.
#include "runner.hpp"
#include "sample_list.hpp"

#include "jostle/tilemap.hpp"

namespace jostle::demo {

namespace {

constexpr float kTile = 32.0f;
/// Jump 4 tiles high, reaching the top in 0.38 s: gravity and take-off speed follow. The
/// lowest jump-through platform is 117 px above the floor, out of reach of 3.5 tiles (112).
constexpr JumpDef kJump{.height = 4.0f * kTile, .timeToApex = 0.38f};
constexpr float kRunSpeed = 260.0f;

/// The lift's shaft: from the pit in the floor (x 736 to 832) up past the ledge of row 7,
/// between the right ends of the steps and of that ledge (both at x 768) and the pit's
/// right side (832). The lift keeps 4 px clear of both, all the way.
constexpr float kLiftX = 800.0f;
constexpr float kLiftHalfWidth = 28.0f;
constexpr float kLiftBottom = 520.0f;
constexpr float kLiftTop = 230.0f;
constexpr float kLiftSpeed = 90.0f;

TileMapDef levelMap() {
    TileMapDef map;
    map.tile = kTile;
    map.friction = 0.6f;
    map.rows = {
        "################################", "#..............................#",
        "#..............................#", "#..............................#",
        "#..............................#", "#..............................#",
        "#..............................#", "#..................#####.......#",
        "#..............................#", "#..............................#",
        "#..............................#", "#..............................#",
        "#.....................##.......#", "#....................###.......#",
        "#...........##......####.......#", "#..........###.....#####.......#",
        "#########.#############...######", "#########.#############...######",
        "################################",
    };
    return map;
}

class PlatformerSample : public Sample {
public:
    const char* name() const override { return "platformer"; }
    bool usesLetterKeys() const override { return true; }
    BodyId player() const override { return runner_.body(); }

    void reset() override {
        panes_.clear();
        Pane pane = paneWithWorld({.gravity = {0.0f, kJump.gravity()}});
        World& world = *pane.world;
        createTileMap(world, levelMap());

        // Jump-through platforms: thin, and only their top blocks.
        for (const Vec2 at : {Vec2{160, 400}, Vec2{300, 300}, Vec2{160, 200}, Vec2{880, 200}})
            world.createBody({.type = BodyType::Static,
                              .x = at.x,
                              .y = at.y,
                              .hw = 56,
                              .hh = 5,
                              .oneWay = {0.0f, -1.0f}});

        lift_ = world.createBody({.type = BodyType::Kinematic,
                                  .x = kLiftX,
                                  .y = kLiftBottom,
                                  .hw = kLiftHalfWidth,
                                  .hh = 8,
                                  .vy = -kLiftSpeed});

        // On the floor between the two flights of steps (not inside them), light enough
        // to push: the player's feet grip 0.8 × its 2 × g, two crates rub 2 × 0.6 × 1 × g.
        for (int i = 0; i < 3; ++i)
            world.createBody({.x = 520.0f + 32.0f * static_cast<float>(i),
                              .y = 490,
                              .hw = 14,
                              .hh = 14,
                              .friction = 0.6f,
                              .mass = 1.0f});

        // Two low steps (12 px each) in the corner left of the start, walked up without a
        // jump.
        world.createBody({.type = BodyType::Static, .x = 68, .y = 506, .hw = 12, .hh = 6});
        world.createBody({.type = BodyType::Static, .x = 44, .y = 500, .hw = 12, .hh = 12});

        // A conveyor belt in the air, carrying what stands on it to the left.
        const BodyId belt = world.createBody({.type = BodyType::Static,
                                              .x = 460,
                                              .y = 380,
                                              .hw = 60,
                                              .hh = 6,
                                              .friction = 0.8f,
                                              .surfaceVelocity = {-90.0f, 0.0f}});
        pane.labels.push_back({belt, "<< BELT"});

        const BodyId player = world.createBody({.x = 100,
                                                .y = 480,
                                                .hw = 11,
                                                .hh = 20,
                                                .friction = 0.8f,
                                                .mass = 2.0f,
                                                .character = true,
                                                .cornerCorrection = 8.0f,
                                                .stepUp = 14.0f});
        runner_ = Runner(player, kRunSpeed, kJump);
        pane.labels.push_back({player, "YOU"});
        pane.view = boundsOf(world);
        pane.title = "physical";
        panes_.push_back(std::move(pane));
    }

    void beforeStep(const Controls& controls, float /*dt*/) override {
        World& world = *panes_.front().world;
        runner_.steer(world, controls);
        // The lift turns round at either end of its shaft.
        const float y = world.position(lift_).y;
        const float vy = world.velocity(lift_).y;
        if ((y <= kLiftTop && vy < 0.0f) || (y >= kLiftBottom && vy > 0.0f))
            world.setVelocity(lift_, {0.0f, -vy});
    }

private:
    Runner runner_;
    BodyId lift_;
};

} // namespace

std::unique_ptr<Sample> makePlatformerSample() {
    return std::make_unique<PlatformerSample>();
}

} // namespace jostle::demo
