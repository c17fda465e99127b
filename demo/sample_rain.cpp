// Sample 4: a rain of boxes of mixed sizes poured into a container, a few a step: the
// broadphase, stacking and sleeping at work. (The benchmark's rain drops its boxes in
// columns already inside the container, to settle fast; a demo wants to see them fall.)
#include "sample_list.hpp"

#include "shared/random.hpp"

namespace jostle::demo {

namespace {

constexpr int kBoxes = 1500;
constexpr int kPerStep = 4;         ///< boxes poured each step, one above the other
constexpr float kSpacing = 2.2f;    ///< between the heights of one step's boxes
constexpr float kPourSpeed = 15.0f; ///< units/s down at the start
constexpr float kHalfWidth = 40.0f; ///< inside of the container
constexpr float kWallHeight = 40.0f;
constexpr float kPourHeight = 55.0f;              ///< above the floor
constexpr float kMinHalf = 0.2f, kMaxHalf = 0.7f; ///< a box fits its lane and its row

class RainSample : public Sample {
public:
    const char* name() const override { return "rain"; }

    void reset() override {
        panes_.clear();
        Pane pane = paneWithWorld({.gravity = {0.0f, 10.0f}});
        World& world = *pane.world;
        // Floor with its top at y = 0, and walls standing on it.
        world.createBody({.type = BodyType::Static, .x = 0, .y = 1, .hw = kHalfWidth + 2, .hh = 1});
        for (const float side : {-1.0f, 1.0f})
            world.createBody({.type = BodyType::Static,
                              .x = side * (kHalfWidth + 1),
                              .y = -kWallHeight / 2,
                              .hw = 1,
                              .hh = kWallHeight / 2});
        pane.view = {{-kHalfWidth - 4, -kPourHeight - 4}, {kHalfWidth + 4, 3}};
        pane.title = "physical";
        panes_.push_back(std::move(pane));
        random_ = shared::Random(0x7a1e5u);
        poured_ = 0;
    }

    void beforeStep(const Controls& /*controls*/, float /*dt*/) override {
        World& world = *panes_.front().world;
        // Each step's boxes at different heights, so they never start inside each other;
        // one may start inside a box of the step before, and is pushed out.
        for (int k = 0; k < kPerStep && poured_ < kBoxes; ++k, ++poured_) {
            const float hw = random_.uniform(kMinHalf, kMaxHalf);
            const float hh = random_.uniform(kMinHalf, kMaxHalf);
            world.createBody({.x = (kHalfWidth - hw) * random_.uniform(-1.0f, 1.0f),
                              .y = -kPourHeight - kSpacing * float(k),
                              .hw = hw,
                              .hh = hh,
                              .vy = kPourSpeed,
                              .friction = 0.5f});
        }
    }

private:
    /// jostle's own mapping of random bits to floats: the same rain with every standard
    /// library, natively and in the browser.
    shared::Random random_{0x7a1e5u};
    int poured_ = 0;
};

} // namespace

std::unique_ptr<Sample> makeRainSample() {
    return std::make_unique<RainSample>();
}

} // namespace jostle::demo
