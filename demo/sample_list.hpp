// The demo's samples, in the order of the keys 1 to 9; each is defined in its own file.
#pragma once

#include "sample.hpp"

#include <memory>
#include <vector>

namespace jostle::demo {

std::unique_ptr<Sample> makeTutorialSample();   // sample_tutorial.cpp
std::unique_ptr<Sample> makePlatformerSample(); // sample_platformer.cpp
std::unique_ptr<Sample> makePyramidSample();    // sample_pyramid.cpp
std::unique_ptr<Sample> makeRainSample();       // sample_rain.cpp
std::unique_ptr<Sample> makeBulletsSample();    // sample_bullets.cpp
std::unique_ptr<Sample> makeCratesSample();     // sample_crates.cpp
std::unique_ptr<Sample> makeSlopesSample();     // sample_slopes.cpp
std::unique_ptr<Sample> makeRollbackSample();   // sample_rollback.cpp
std::unique_ptr<Sample> makeLevelSample();      // sample_level.cpp

inline std::vector<std::unique_ptr<Sample>> makeSamples() {
    std::vector<std::unique_ptr<Sample>> samples;
    samples.push_back(makeTutorialSample());
    samples.push_back(makePlatformerSample());
    samples.push_back(makePyramidSample());
    samples.push_back(makeRainSample());
    samples.push_back(makeBulletsSample());
    samples.push_back(makeCratesSample());
    samples.push_back(makeSlopesSample());
    samples.push_back(makeRollbackSample());
    samples.push_back(makeLevelSample());
    return samples;
}

} // namespace jostle::demo
