// The tutorial's testRectRect, case by case. Every expected vector is worked out by hand
// from the tutorial's code: s = (hw_a + hw_b - |dx|, hh_a + hh_b - |dy|), keep the
// smaller component (y on a tie), signs from d = a - b.
#include "geometry.hpp"

#include <gtest/gtest.h>

namespace jostle {
namespace {

/// A box as the tutorial gives it: centre and half extents.
struct Rect {
    Vec2 centre;
    Vec2 half;
};

Rect box(float x, float y, float hw, float hh) {
    return {{x, y}, {hw, hh}};
}

/// testRectRect(a, b): geometry.hpp takes the offset of the centres and the sum of the
/// half extents, the tutorial's dx, dy and shw, shh.
std::optional<Vec2> separation(const Rect& a, const Rect& b) {
    return shortestSeparation(a.centre - b.centre, a.half + b.half);
}

TEST(ShortestSeparation, NoOverlapWhenApartOnEitherAxis) {
    EXPECT_FALSE(separation(box(0, 0, 1, 1), box(5, 0, 1, 1)));
    EXPECT_FALSE(separation(box(0, 0, 1, 1), box(0, -5, 1, 1)));
    // Overlapping on x only is no overlap.
    EXPECT_FALSE(separation(box(0, 0, 1, 1), box(0.5f, 3, 1, 1)));
}

TEST(ShortestSeparation, TouchingEdgesAreNotACollision) {
    // |dx| == hw_a + hw_b exactly.
    EXPECT_FALSE(separation(box(0, 0, 1, 1), box(2, 0, 1, 1)));
    EXPECT_FALSE(separation(box(0, 0, 1, 1), box(0, 2, 1, 1)));
    EXPECT_FALSE(separation(box(0, 0, 1, 1), box(2, 2, 1, 1))); // corners
}

TEST(ShortestSeparation, XAxisBothSigns) {
    // d = (-1.5, 0.25): s = (2 - 1.5, 2 - 0.25) = (0.5, 1.75), x is shorter, sign of dx.
    EXPECT_EQ(*separation(box(0, 0, 1, 1), box(1.5f, -0.25f, 1, 1)), (Vec2{-0.5f, 0}));
    EXPECT_EQ(*separation(box(1.5f, -0.25f, 1, 1), box(0, 0, 1, 1)), (Vec2{0.5f, 0}));
}

TEST(ShortestSeparation, YAxisBothSigns) {
    // d = (0.5, -1.75): s = (1.5, 0.25), y is shorter.
    EXPECT_EQ(*separation(box(0, 0, 1, 1), box(-0.5f, 1.75f, 1, 1)), (Vec2{0, -0.25f}));
    EXPECT_EQ(*separation(box(-0.5f, 1.75f, 1, 1), box(0, 0, 1, 1)), (Vec2{0, 0.25f}));
}

TEST(ShortestSeparation, TieGoesToY) {
    // d = (1.5, 1.5): s = (0.5, 0.5): sx < sy is false, so x is dropped.
    EXPECT_EQ(*separation(box(1.5f, 1.5f, 1, 1), box(0, 0, 1, 1)), (Vec2{0, 0.5f}));
    EXPECT_EQ(*separation(box(-1.5f, -1.5f, 1, 1), box(0, 0, 1, 1)), (Vec2{0, -0.5f}));
}

TEST(ShortestSeparation, DifferentSizes) {
    // a: hw 4, hh 1 at (0, 0); b: hw 1, hh 3 at (3, 3): s = (5 - 3, 4 - 3) = (2, 1) -> y, up.
    EXPECT_EQ(*separation(box(0, 0, 4, 1), box(3, 3, 1, 3)), (Vec2{0, -1}));
}

TEST(ShortestSeparation, Containment) {
    // A small box deep inside a big one leaves by the nearer side of the sum of extents:
    // d = (3, -1): s = (10 + 1 - 3, 5 + 1 - 1) = (8, 5) -> y, sign of dy (up).
    EXPECT_EQ(*separation(box(3, -1, 1, 1), box(0, 0, 10, 5)), (Vec2{0, -5}));
}

TEST(ShortestSeparation, CoincidentCentresPushTowardsPositive) {
    // d = (0, 0): no sign flips. s = (2, 3) -> x.
    EXPECT_EQ(*separation(box(7, 7, 1, 1), box(7, 7, 1, 2)), (Vec2{2, 0}));
    // s = (2, 2): tie -> y.
    EXPECT_EQ(*separation(box(7, 7, 1, 1), box(7, 7, 1, 1)), (Vec2{0, 2}));
}

TEST(ShortestSeparation, SeparatedBoxesNoLongerOverlap) {
    const Rect a = box(0.3f, 0.2f, 1, 2);
    const Rect b = box(1.1f, 1.7f, 1.5f, 0.5f);
    const Vec2 s = *separation(a, b);
    EXPECT_FALSE(separation(box(a.centre.x + s.x, a.centre.y + s.y, 1, 2), b));
}

// contactAxis(gapX, gapY, skinX, skinY), with skins of 0.1.

TEST(ContactAxis, DeepOverlapOnBothAxesTakesTheLeastPenetration) {
    EXPECT_EQ(contactAxis(-1, -3, 0.1f, 0.1f), kAlongX);
    EXPECT_EQ(contactAxis(-3, -1, 0.1f, 0.1f), kAlongY);
    EXPECT_EQ(contactAxis(-2, -2, 0.1f, 0.1f), kAlongY); // tie
}

TEST(ContactAxis, SideBySideWhenOnlyOneAxisOverlaps) {
    EXPECT_EQ(contactAxis(0.5f, -3, 0.1f, 0.1f), kAlongX); // a wall ahead
    EXPECT_EQ(contactAxis(-3, 0.5f, 0.1f, 0.1f), kAlongY); // a floor below
}

TEST(ContactAxis, ARestingOverlapIsTouchingNotPenetration) {
    // A box resting on a floor box (0.05 deep) reaches the next floor box: it is just
    // entering it sideways (0.01), but that is the floor, not a wall.
    EXPECT_EQ(contactAxis(-0.01f, -0.05f, 0.1f, 0.1f), kAlongY);
    EXPECT_EQ(contactAxis(0.5f, -0.05f, 0.1f, 0.1f), kAlongY);
    // Falling along a wall of boxes, flush with it, above the next wall box.
    EXPECT_EQ(contactAxis(0, 0.5f, 0.1f, 0.1f), kAlongX);
}

TEST(ContactAxis, ApartOnBothAxesTakesTheLargerGap) {
    EXPECT_EQ(contactAxis(2, 1, 0.1f, 0.1f), kAlongX);
    EXPECT_EQ(contactAxis(1, 2, 0.1f, 0.1f), kAlongY);
}

// --- Moving through a box ----------------------------------------------------------------
//
// Two boxes of half extents (1, 1), the still one at the origin: the mover's centre
// crosses the Minkowski box [-2, 2] x [-2, 2] (shrunk by the skin where it penetrates).
// Times are worked out by hand as (face - start) / motion along the axis.

constexpr Vec2 kUnit{1, 1};
constexpr Vec2 kReach{2, 2};

TEST(SweepBox, StopsWhereTheMoverFirstGoesDeeperThanTheSkin) {
    // From x = -5 along +10: the face x = -2 at 3/10; shrunk by 0.1, x = -1.9 at 3.1/10.
    const std::optional<Hit> hit = sweepBox({-5, 0}, kReach, {10, 0}, {});
    ASSERT_TRUE(hit);
    EXPECT_FLOAT_EQ(hit->time, 0.3f);
    EXPECT_EQ(hit->normal, (Vec2{-1, 0}));
    EXPECT_EQ(hit->axis, kAlongX);
    const std::optional<Hit> skinned = sweepBox({-5, 0}, kReach, {10, 0}, {0.1f, 0.1f});
    ASSERT_TRUE(skinned);
    EXPECT_FLOAT_EQ(skinned->time, 0.31f);
}

TEST(SweepBox, SlidingAlongAFaceWithinTheSkinIsNoHit) {
    // Resting 0.05 deep on the box below (skin 0.1), sliding across its top.
    EXPECT_FALSE(sweepBox({-3, -1.95f}, kReach, {10, 0}, {0.1f, 0.1f}));
}

TEST(SweepBox, InsideOrOutOfReachIsNoHit) {
    EXPECT_FALSE(sweepBox({0.5f, 0}, kReach, {10, 0}, {})); // deep inside: contacts' business
    EXPECT_FALSE(sweepBox({-5, 0}, kReach, {2, 0}, {}));    // would arrive at 1.5 of the motion
    EXPECT_FALSE(sweepBox({-5, 0}, kReach, {-10, 0}, {}));  // moving away
}

TEST(SweepBox, ExactlyIntoACornerMeetsTheXFace) {
    // Both slabs entered at 3/10.
    const std::optional<Hit> hit = sweepBox({-5, -5}, kReach, {10, 10}, {});
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->normal, (Vec2{-1, 0}));
}

TEST(CastBox, HitsWhereTheBoxesFirstTouch) {
    // Touching at x = -2 (3/10); it goes on deeper than the skin, so it runs into it.
    const std::optional<Hit> hit = castBox({-5, 0}, kReach, {10, 0}, {0.1f, 0.1f});
    ASSERT_TRUE(hit);
    EXPECT_FLOAT_EQ(hit->time, 0.3f);
    EXPECT_EQ(hit->normal, (Vec2{-1, 0}));
    EXPECT_EQ(hit->axis, kAlongX);
}

TEST(CastBox, TouchingAtTheStartAndMovingInStopsAtOnce) {
    const std::optional<Hit> hit = castBox({-2, 0}, kReach, {1, 0}, {0.1f, 0.1f});
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->time, 0.0f);
    EXPECT_EQ(hit->normal, (Vec2{-1, 0}));
    EXPECT_EQ(hit->axis, kFromInside);
}

TEST(CastBox, SlidingAlongAFaceOrMovingAwayIsNoHit) {
    EXPECT_FALSE(castBox({-3, -1.95f}, kReach, {10, 0}, {0.1f, 0.1f}));
    EXPECT_FALSE(castBox({-2, 0}, kReach, {-1, 0}, {0.1f, 0.1f}));
    EXPECT_FALSE(castBox({-5, 0}, kReach, {0, 0}, {0.1f, 0.1f}));
}

TEST(CastBox, ExactlyIntoACornerMeetsTheYFace) {
    const std::optional<Hit> hit = castBox({-5, -5}, kReach, {10, 10}, {0.1f, 0.1f});
    ASSERT_TRUE(hit);
    EXPECT_FLOAT_EQ(hit->time, 0.3f);
    EXPECT_EQ(hit->normal, (Vec2{0, -1}));
    EXPECT_EQ(hit->axis, kAlongY);
}

TEST(CastRay, MeetsTheFaceItEntersThrough) {
    // The box [-1, 1]^2 from x = -5 along +10: the face x = -1 at 4/10.
    const Box box{-kUnit, kUnit};
    const std::optional<Hit> hit = castRay({-5, 0}, {10, 0}, box);
    ASSERT_TRUE(hit);
    EXPECT_FLOAT_EQ(hit->time, 0.4f);
    EXPECT_EQ(hit->normal, (Vec2{-1, 0}));
    EXPECT_EQ(hit->axis, kAlongX);
}

TEST(CastRay, TouchingCountsButLeavingFromTheStartDoesNot) {
    const Box box{-kUnit, kUnit};
    EXPECT_TRUE(castRay({-5, 1}, {10, 0}, box)); // along the top face
    EXPECT_FALSE(castRay({1, 0}, {5, 0}, box));  // from the right face, heading away
    EXPECT_FALSE(castRay({-5, 0}, {3, 0}, box)); // stops short
}

TEST(CastRay, StartingInsideHitsAtOnceTheFaceItHeadsFor) {
    const Box box{-kUnit, kUnit};
    const std::optional<Hit> hit = castRay({0, 0}, {1, 5}, box);
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->time, 0.0f);
    EXPECT_EQ(hit->normal, (Vec2{0, -1}));
    EXPECT_EQ(hit->axis, kFromInside);
}

TEST(CastRay, ExactlyIntoACornerMeetsTheYFace) {
    const Box box{-kUnit, kUnit};
    const std::optional<Hit> hit = castRay({-3, -3}, {4, 4}, box);
    ASSERT_TRUE(hit);
    EXPECT_FLOAT_EQ(hit->time, 0.5f);
    EXPECT_EQ(hit->normal, (Vec2{0, -1}));
}

} // namespace
} // namespace jostle
