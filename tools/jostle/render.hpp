// `jostle render`: steps a scene headless and draws it, as an animated GIF of every K-th
// step or a PNG of the last one (docs/scene-format.md, `jostle render`).
#pragma once

#include <cstdint>
#include <string>

namespace jostle::cli {

/// The largest width or height `jostle render` draws: beyond it a typo (an extra 0)
/// would take minutes and gigabytes rather than give a picture.
constexpr std::int64_t kMaxImageSide = 4096;
/// The width when neither --width nor --height is given.
constexpr int kDefaultImageWidth = 640;

struct RenderOptions {
    std::string scene;
    std::string out; ///< ends in .gif or .png (any case)
    std::int64_t steps = 120;
    std::int64_t width = 0; ///< 0: from the height and the scene's shape
    std::int64_t height = 0;
    std::int64_t every = 2; ///< GIF only: a frame every K steps
    std::string solver;     ///< --solver: "classic" or "physical"; empty: the scene's own
    /// --legend: a key to the colours in a band under the scene (legend.hpp), which makes
    /// the image taller by the band's height
    bool legend = false;
    /// --debug: the debug marks of World::debugDraw too, as the demo's Tab shows them:
    /// contacts, velocities, the sides touched, the broadphase's cells
    bool debug = false;
};

/// Runs the command; returns the exit status (errors.hpp), having printed any error.
/// Throws what loadScene and World throw, for main to report as bad input.
int render(const RenderOptions& options);

} // namespace jostle::cli
