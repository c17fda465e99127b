// The tutorial's testRectRect, case by case. Every expected vector is worked out by hand
// from the tutorial's code: s = (hw_a + hw_b - |dx|, hh_a + hh_b - |dy|), keep the
// smaller component (y on a tie), signs from d = a - b.
#include "collide.hpp"

#include <gtest/gtest.h>

namespace jostle {
namespace {

Box box(float x, float y, float hw, float hh) {
    return {{x, y}, {hw, hh}};
}

TEST(ShortestSeparation, NoOverlapWhenApartOnEitherAxis) {
    EXPECT_FALSE(shortestSeparation(box(0, 0, 1, 1), box(5, 0, 1, 1)));
    EXPECT_FALSE(shortestSeparation(box(0, 0, 1, 1), box(0, -5, 1, 1)));
    // Overlapping on x only is no overlap.
    EXPECT_FALSE(shortestSeparation(box(0, 0, 1, 1), box(0.5f, 3, 1, 1)));
}

TEST(ShortestSeparation, TouchingEdgesAreNotACollision) {
    // |dx| == hw_a + hw_b exactly.
    EXPECT_FALSE(shortestSeparation(box(0, 0, 1, 1), box(2, 0, 1, 1)));
    EXPECT_FALSE(shortestSeparation(box(0, 0, 1, 1), box(0, 2, 1, 1)));
    EXPECT_FALSE(shortestSeparation(box(0, 0, 1, 1), box(2, 2, 1, 1))); // corners
}

TEST(ShortestSeparation, XAxisBothSigns) {
    // d = (-1.5, 0.25): s = (2 - 1.5, 2 - 0.25) = (0.5, 1.75), x is shorter, sign of dx.
    EXPECT_EQ(*shortestSeparation(box(0, 0, 1, 1), box(1.5f, -0.25f, 1, 1)), (Vec2{-0.5f, 0}));
    EXPECT_EQ(*shortestSeparation(box(1.5f, -0.25f, 1, 1), box(0, 0, 1, 1)), (Vec2{0.5f, 0}));
}

TEST(ShortestSeparation, YAxisBothSigns) {
    // d = (0.5, -1.75): s = (1.5, 0.25), y is shorter.
    EXPECT_EQ(*shortestSeparation(box(0, 0, 1, 1), box(-0.5f, 1.75f, 1, 1)), (Vec2{0, -0.25f}));
    EXPECT_EQ(*shortestSeparation(box(-0.5f, 1.75f, 1, 1), box(0, 0, 1, 1)), (Vec2{0, 0.25f}));
}

TEST(ShortestSeparation, TieGoesToY) {
    // d = (1.5, 1.5): s = (0.5, 0.5): sx < sy is false, so x is dropped.
    EXPECT_EQ(*shortestSeparation(box(1.5f, 1.5f, 1, 1), box(0, 0, 1, 1)), (Vec2{0, 0.5f}));
    EXPECT_EQ(*shortestSeparation(box(-1.5f, -1.5f, 1, 1), box(0, 0, 1, 1)), (Vec2{0, -0.5f}));
}

TEST(ShortestSeparation, DifferentSizes) {
    // a: hw 4, hh 1 at (0, 0); b: hw 1, hh 3 at (3, 3): s = (5 - 3, 4 - 3) = (2, 1) -> y, up.
    EXPECT_EQ(*shortestSeparation(box(0, 0, 4, 1), box(3, 3, 1, 3)), (Vec2{0, -1}));
}

TEST(ShortestSeparation, Containment) {
    // A small box deep inside a big one leaves by the nearer side of the sum of extents:
    // d = (3, -1): s = (10 + 1 - 3, 5 + 1 - 1) = (8, 5) -> y, sign of dy (up).
    EXPECT_EQ(*shortestSeparation(box(3, -1, 1, 1), box(0, 0, 10, 5)), (Vec2{0, -5}));
}

TEST(ShortestSeparation, CoincidentCentresPushTowardsPositive) {
    // d = (0, 0): no sign flips. s = (2, 3) -> x.
    EXPECT_EQ(*shortestSeparation(box(7, 7, 1, 1), box(7, 7, 1, 2)), (Vec2{2, 0}));
    // s = (2, 2): tie -> y.
    EXPECT_EQ(*shortestSeparation(box(7, 7, 1, 1), box(7, 7, 1, 1)), (Vec2{0, 2}));
}

TEST(ShortestSeparation, SeparatedBoxesNoLongerOverlap) {
    const Box a = box(0.3f, 0.2f, 1, 2);
    const Box b = box(1.1f, 1.7f, 1.5f, 0.5f);
    const Vec2 s = *shortestSeparation(a, b);
    EXPECT_FALSE(shortestSeparation(box(a.centre.x + s.x, a.centre.y + s.y, 1, 2), b));
}

// contactAxis(gapX, gapY, skinX, skinY), with skins of 0.1.

TEST(ContactAxis, DeepOverlapOnBothAxesTakesTheLeastPenetration) {
    EXPECT_EQ(contactAxis(-1, -3, 0.1f, 0.1f), Axis::X);
    EXPECT_EQ(contactAxis(-3, -1, 0.1f, 0.1f), Axis::Y);
    EXPECT_EQ(contactAxis(-2, -2, 0.1f, 0.1f), Axis::Y); // tie
}

TEST(ContactAxis, SideBySideWhenOnlyOneAxisOverlaps) {
    EXPECT_EQ(contactAxis(0.5f, -3, 0.1f, 0.1f), Axis::X); // a wall ahead
    EXPECT_EQ(contactAxis(-3, 0.5f, 0.1f, 0.1f), Axis::Y); // a floor below
}

TEST(ContactAxis, ARestingOverlapIsTouchingNotPenetration) {
    // A box resting on a floor box (0.05 deep) reaches the next floor box: it is just
    // entering it sideways (0.01), but that is the floor, not a wall.
    EXPECT_EQ(contactAxis(-0.01f, -0.05f, 0.1f, 0.1f), Axis::Y);
    EXPECT_EQ(contactAxis(0.5f, -0.05f, 0.1f, 0.1f), Axis::Y);
    // Falling along a wall of boxes, flush with it, above the next wall box.
    EXPECT_EQ(contactAxis(0, 0.5f, 0.1f, 0.1f), Axis::X);
}

TEST(ContactAxis, ApartOnBothAxesTakesTheLargerGap) {
    EXPECT_EQ(contactAxis(2, 1, 0.1f, 0.1f), Axis::X);
    EXPECT_EQ(contactAxis(1, 2, 0.1f, 0.1f), Axis::Y);
}

} // namespace
} // namespace jostle
