// Sample 5: fast bodies against thin walls. A cannon on the left fires small boxes at
// 3,000 px/s in two lanes; every other one is a `bullet`. The thin static wall of the top
// lane stops them all (every dynamic body is swept against static ones); the thin
// dynamic plank of the bottom lane stops only bullets (only they are swept against
// dynamic bodies): the others tunnel through it.
#include "sample_list.hpp"

#include <deque>

namespace jostle::demo {

namespace {

constexpr float kShotSpeed = 3000.0f;
constexpr float kShotHalf = 4.0f;
constexpr float kSecondsBetweenShots = 0.35f;
/// Older shots are removed, so the sample can run for ever.
constexpr std::size_t kMaxShots = 60;
constexpr float kTopLane = 150.0f;
constexpr float kBottomLane = 420.0f;

class BulletsSample : public Sample {
public:
    const char* name() const override { return "bullets"; }

    void reset() override {
        panes_.clear();
        shots_.clear();
        untilNextShot_ = 0.0f;
        shotCount_ = 0;
        Pane pane = paneWithWorld({.gravity = {0.0f, 800.0f}});
        World& world = *pane.world;
        const auto solid = [&world](float x, float y, float hw, float hh) {
            world.createBody({.type = BodyType::Static, .x = x, .y = y, .hw = hw, .hh = hh});
        };
        solid(500, 590, 520, 10); // floor
        solid(500, 235, 520, 6);  // the shelf between the lanes
        solid(-16, 300, 6, 300);  // walls at both ends
        solid(1016, 300, 6, 300);
        solid(700, kTopLane, 2, 70); // the thin static wall
        const BodyId plank = world.createBody(
            {.x = 700, .y = 510, .hw = 2, .hh = 70, .friction = 0.8f, .mass = 400.0f});
        pane.labels.push_back({plank, "DYNAMIC PLANK"});
        pane.view = {{-30.0f, 60.0f}, {1030.0f, 600.0f}};
        pane.title = "physical: light outline = bullet";
        panes_.push_back(std::move(pane));
    }

    void beforeStep(const Controls& /*controls*/, float dt) override {
        untilNextShot_ -= dt;
        if (untilNextShot_ > 0.0f)
            return;
        untilNextShot_ += kSecondsBetweenShots;
        World& world = *panes_.front().world;
        const bool bullet = shotCount_ % 2 == 0;
        ++shotCount_;
        for (const float lane : {kTopLane, kBottomLane}) {
            // Shots fly level (no gravity), so that each lane tests its own wall.
            shots_.push_back(world.createBody({.x = 40,
                                               .y = lane + 20.0f,
                                               .hw = kShotHalf,
                                               .hh = kShotHalf,
                                               .vx = kShotSpeed,
                                               .bounce = 0.3f,
                                               .gravityScale = 0.0f,
                                               .bullet = bullet}));
        }
        while (shots_.size() > kMaxShots) {
            if (world.isValid(shots_.front()))
                world.destroyBody(shots_.front());
            shots_.pop_front();
        }
    }

private:
    std::deque<BodyId> shots_;
    float untilNextShot_ = 0.0f;
    int shotCount_ = 0;
};

} // namespace

std::unique_ptr<Sample> makeBulletsSample() {
    return std::make_unique<BulletsSample>();
}

} // namespace jostle::demo
