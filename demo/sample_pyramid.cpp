// Sample 3: a pyramid of 210 unit boxes (jostle::shared::pyramid), which the physical
// model keeps standing; shown in pixels through the pane's view.
#include "sample_list.hpp"

#include "shared/scenes.hpp"

namespace jostle::demo {

namespace {

constexpr int kRows = 20;

class PyramidSample : public Sample {
public:
    const char* name() const override { return "pyramid"; }

    void reset() override {
        panes_.clear();
        panes_.push_back(paneFromScene(shared::pyramid(kRows), "physical", 0.6f));
    }
};

} // namespace

std::unique_ptr<Sample> makePyramidSample() {
    return std::make_unique<PyramidSample>();
}

} // namespace jostle::demo
