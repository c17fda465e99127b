// The two scenes of one level read from two files: the same tile maps and bodies.
#pragma once

#include "jostle/scene.hpp"

#include <gtest/gtest.h>

namespace jostle {

/// The two scenes hold the same tile maps and bodies (definitions as scene files write them).
inline void expectSameScene(const Scene& a, const Scene& b) {
    ASSERT_EQ(a.tileMaps.size(), b.tileMaps.size());
    for (std::size_t i = 0; i < a.tileMaps.size(); ++i) {
        EXPECT_EQ(a.tileMaps[i].rows, b.tileMaps[i].rows);
        EXPECT_EQ(a.tileMaps[i].oneWay, b.tileMaps[i].oneWay);
        EXPECT_EQ(a.tileMaps[i].x, b.tileMaps[i].x);
        EXPECT_EQ(a.tileMaps[i].y, b.tileMaps[i].y);
    }
    ASSERT_EQ(a.bodies.size(), b.bodies.size());
    for (std::size_t i = 0; i < a.bodies.size(); ++i) {
        EXPECT_EQ(a.bodies[i].id, b.bodies[i].id);
        EXPECT_EQ(bodyToJson(a.bodies[i].def), bodyToJson(b.bodies[i].def));
    }
    EXPECT_EQ(a.world.gravity, b.world.gravity);
}

} // namespace jostle
