// Sample 4: a rain of thousands of boxes of mixed sizes into a container
// (jostle::samples::rain): the broadphase and sleeping at work.
#include "sample_list.hpp"

#include "samples/scenes.hpp"

namespace jostle::demo {

namespace {

/// Thousands, yet few enough that a step stays within a 60 Hz frame on a laptop.
constexpr int kBoxes = 3000;

class RainSample : public Sample {
public:
    const char* name() const override { return "rain"; }

    void reset() override {
        panes_.clear();
        panes_.push_back(paneFromScene(samples::rain(kBoxes), "physical", 0.0f));
    }
};

} // namespace

std::unique_ptr<Sample> makeRainSample() {
    return std::make_unique<RainSample>();
}

} // namespace jostle::demo
