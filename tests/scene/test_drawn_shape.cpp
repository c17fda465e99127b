// shared/drawn_shape.hpp: a body's shape as `jostle render` and the demo draw it, read
// back from the world.
#include "shared/drawn_shape.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace jostle::shared {
namespace {

DrawnShape shapeOf(const BodyDef& def) {
    World world;
    return DrawnShape::of(world, world.createBody(def));
}

TEST(DrawnShape, IsReadFromTheWorld) {
    const DrawnShape box = shapeOf({.x = 1, .y = 2, .hw = 3, .hh = 4});
    EXPECT_EQ(box.kind, DrawnKind::Box);
    EXPECT_EQ(box.centre, (Vec2{1, 2}));
    EXPECT_EQ(box.half, (Vec2{3, 4}));
    const DrawnShape circle = shapeOf({.hw = 5, .hh = 5, .radius = 5});
    EXPECT_EQ(circle.kind, DrawnKind::Rounded);
    EXPECT_EQ(circle.radius, 5.0f);
    const DrawnShape ramp = shapeOf({.type = BodyType::Static, .hw = 2, .hh = 1, .slope = {1, -1}});
    EXPECT_EQ(ramp.kind, DrawnKind::Ramp);
    EXPECT_EQ(ramp.slope, (Vec2{1, -1}));
    const DrawnShape segment =
        shapeOf({.type = BodyType::Kinematic, .hw = 2, .hh = 1, .slope = {-1, 1}, .segment = true});
    EXPECT_EQ(segment.kind, DrawnKind::Segment);
    EXPECT_EQ(segment.slope, (Vec2{-1, 1}));
}

TEST(DrawnShape, ContainsWhatIsInside) {
    const DrawnShape circle{DrawnKind::Rounded, {10, 0}, {5, 5}, 5, {}};
    EXPECT_TRUE(circle.contains({10, 0}));
    EXPECT_TRUE(circle.contains({15, 0}));        // the edge
    EXPECT_FALSE(circle.contains({14.5f, 4.5f})); // the corner of its box
    const DrawnShape capsule{DrawnKind::Rounded, {0, 0}, {2, 6}, 2, {}};
    EXPECT_TRUE(capsule.contains({1.9f, 3.9f})); // the straight side
    EXPECT_FALSE(capsule.contains({1.9f, 5.9f}));
    // Cut along the diagonal: the corner {1, -1} is gone, the opposite one kept.
    const DrawnShape ramp{DrawnKind::Ramp, {0, 0}, {2, 1}, 0, {1, -1}};
    EXPECT_FALSE(ramp.contains({1.9f, -0.9f}));
    EXPECT_TRUE(ramp.contains({-1.9f, 0.9f}));
    EXPECT_TRUE(ramp.contains({0, 0})); // on the face
    EXPECT_FALSE(ramp.contains({2.1f, 0.9f}));
    const DrawnShape segment{DrawnKind::Segment, {0, 0}, {2, 1}, 0, {1, -1}};
    EXPECT_FALSE(segment.contains({0, 0})); // a line holds nothing
}

TEST(DrawnShape, TheTriangleIsTheBoxWithoutTheCornerTheSlopeNames) {
    const DrawnShape ramp{DrawnKind::Ramp, {10, 20}, {2, 1}, 0, {1, -1}};
    const auto corners = ramp.triangle();
    EXPECT_EQ(corners[0], (Vec2{12, 21})); // the face's ends
    EXPECT_EQ(corners[1], (Vec2{8, 19}));
    EXPECT_EQ(corners[2], (Vec2{8, 21}));  // the right angle
    const Vec2 normal = ramp.faceNormal(); // towards {1, -1}, across the face
    EXPECT_NEAR(normal.x, 1.0f / std::sqrt(5.0f), 1e-6f);
    EXPECT_NEAR(normal.y, -2.0f / std::sqrt(5.0f), 1e-6f);
    const Vec2 face = corners[1] - corners[0];
    EXPECT_NEAR(normal.x * face.x + normal.y * face.y, 0.0f, 1e-6f);
}

TEST(DrawnShape, ThePerimeterGoesRoundTheShape) {
    const DrawnShape box{DrawnKind::Box, {0, 0}, {3, 2}, 0, {}};
    const auto corners = box.perimeter(8);
    ASSERT_EQ(corners.size(), 4u);
    for (const Vec2 corner : corners) {
        EXPECT_FLOAT_EQ(std::abs(corner.x), 3.0f);
        EXPECT_FLOAT_EQ(std::abs(corner.y), 2.0f);
    }
    // A capsule: four arcs of 3 points, each at the radius from its corner of the core,
    // the straight sides joining them.
    const DrawnShape capsule{DrawnKind::Rounded, {0, 0}, {1, 3}, 1, {}};
    const auto points = capsule.perimeter(3);
    ASSERT_EQ(points.size(), 12u);
    for (const Vec2 p : points) {
        const Vec2 core{0.0f, p.y > 0 ? 2.0f : -2.0f};
        EXPECT_NEAR(length(p - core), 1.0f, 1e-5f);
        EXPECT_TRUE(capsule.contains(p * 0.999f));
    }
    EXPECT_NEAR(points[0].x, 1.0f, 1e-6f); // the first arc starts on the right side
    EXPECT_NEAR(points[2].y, 3.0f, 1e-6f); // and ends at the bottom
    EXPECT_EQ((DrawnShape{DrawnKind::Ramp, {}, {2, 1}, 0, {1, 1}}.perimeter(8).size()), 3u);
    EXPECT_EQ((DrawnShape{DrawnKind::Segment, {}, {2, 1}, 0, {1, 1}}.perimeter(8).size()), 2u);
}

} // namespace
} // namespace jostle::shared
