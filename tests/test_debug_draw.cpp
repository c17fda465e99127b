// Debug drawing (World::debugDraw): what each body, contact and mark becomes as calls of
// the game's renderer, and the line drawings a renderer gets when it draws lines only.
#include "jostle/tilemap.hpp"
#include "jostle/world.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace jostle {
namespace {

constexpr float kDt = 1.0f / 60.0f;

/// Every call, as it came.
struct Recorder : DebugDraw {
    struct Call {
        enum Kind { Line, Box, Rounded, Triangle, Point } kind;
        std::vector<Vec2> points; ///< line: its ends; box, rounded: centre, half; triangle:
                                  ///< its corners; point: where
        float radius = 0.0f;      ///< rounded: the radius; point: the size
        Colour fill;              ///< line, point: their colour
        Colour outline;
    };
    std::vector<Call> calls;

    void line(Vec2 from, Vec2 to, Colour colour) override {
        calls.push_back({Call::Line, {from, to}, 0.0f, colour, colour});
    }
    void box(Vec2 centre, Vec2 half, Colour fill, Colour outline) override {
        calls.push_back({Call::Box, {centre, half}, 0.0f, fill, outline});
    }
    void roundedBox(Vec2 centre, Vec2 half, float radius, Colour fill, Colour outline) override {
        calls.push_back({Call::Rounded, {centre, half}, radius, fill, outline});
    }
    void triangle(Vec2 a, Vec2 b, Vec2 c, Colour fill, Colour outline) override {
        calls.push_back({Call::Triangle, {a, b, c}, 0.0f, fill, outline});
    }
    void point(Vec2 at, float size, Colour colour) override {
        calls.push_back({Call::Point, {at}, size, colour, colour});
    }
    std::vector<Call> of(Call::Kind kind) const {
        std::vector<Call> found;
        std::copy_if(calls.begin(), calls.end(), std::back_inserter(found),
                     [kind](const Call& call) { return call.kind == kind; });
        return found;
    }
};

/// Draws lines only: the base class draws the other shapes with them.
struct Lines : DebugDraw {
    std::vector<std::pair<Vec2, Vec2>> lines;
    void line(Vec2 from, Vec2 to, Colour) override { lines.emplace_back(from, to); }
};

/// The palette's defaults as docs/debug-draw.md lists them.
struct DocumentedPalette {
    Colour staticBody{150, 150, 150}, kinematicBody{70, 130, 230}, dynamicBody{240, 150, 60};
    Colour bulletOutline{255, 255, 255}, oneWayFace{230, 230, 230};
    Colour contact{250, 250, 120}, velocity{90, 220, 120}, touching{230, 60, 60};
    Colour gridCell{50, 110, 140}, gridBox{110, 220, 250};
};
const DocumentedPalette kPalette;

TEST(DebugDraw, EachBodyTypeIsFilledInItsColourAndOutlinedDarker) {
    World world(WorldDef{.sleeping = false});
    world.createBody({.type = BodyType::Static, .x = 1, .y = 2, .hw = 3, .hh = 0.5f});
    world.createBody({.type = BodyType::Kinematic, .x = -4, .y = 0, .hw = 1, .hh = 1});
    world.createBody({.x = 0, .y = -5, .hw = 0.5f, .hh = 0.25f});
    Recorder draw;
    world.debugDraw(draw);
    ASSERT_EQ(draw.calls.size(), 3u);
    const Colour fills[] = {kPalette.staticBody, kPalette.kinematicBody, kPalette.dynamicBody};
    const Vec2 centres[] = {{1, 2}, {-4, 0}, {0, -5}};
    const Vec2 halves[] = {{3, 0.5f}, {1, 1}, {0.5f, 0.25f}};
    for (std::size_t i = 0; i < 3; ++i) {
        const Recorder::Call& call = draw.calls[i];
        EXPECT_EQ(call.kind, Recorder::Call::Box);
        EXPECT_EQ(call.points[0], centres[i]);
        EXPECT_EQ(call.points[1], halves[i]);
        EXPECT_EQ(call.fill, fills[i]);
    }
    // Outlines are 60 % of the fill, rounded down: 240 150 60 -> 144 90 36.
    EXPECT_EQ(draw.calls[2].outline, (Colour{144, 90, 36}));
    EXPECT_EQ(draw.calls[0].outline, (Colour{90, 90, 90}));
}

TEST(DebugDraw, ASleepingBodyIsDimmedAndAnAwakeOneIsNot) {
    World world(WorldDef{.gravity = {0, 10}});
    world.createBody({.type = BodyType::Static, .x = 0, .y = 1, .hw = 10, .hh = 1});
    const BodyId box = world.createBody({.x = 0, .y = -0.5f, .hw = 0.5f, .hh = 0.5f});
    for (int i = 0; i < 600 && world.isAwake(box); ++i)
        world.step(kDt);
    ASSERT_FALSE(world.isAwake(box));
    Recorder draw;
    world.debugDraw(draw);
    ASSERT_EQ(draw.calls.size(), 2u);
    // 55 % of 240 150 60 rounded down, then 60 % of that for the outline.
    EXPECT_EQ(draw.calls[1].fill, (Colour{132, 82, 33}));
    EXPECT_EQ(draw.calls[1].outline, (Colour{79, 49, 19}));
    // A static body never sleeps: its colour stays.
    EXPECT_EQ(draw.calls[0].fill, kPalette.staticBody);
}

TEST(DebugDraw, SensorsAreOutlinedOnlyAndDrawnAfterEverythingElse) {
    World world;
    world.createBody({.type = BodyType::Static, .x = 0, .y = 0, .hw = 1, .hh = 1, .sensor = true});
    world.createBody({.type = BodyType::Static, .x = 0, .y = 0, .hw = 2, .hh = 2});
    Recorder draw;
    world.debugDraw(draw);
    ASSERT_EQ(draw.calls.size(), 2u);
    EXPECT_EQ(draw.calls[0].points[1], (Vec2{2, 2})); // the solid body first
    EXPECT_EQ(draw.calls[1].points[1], (Vec2{1, 1}));
    EXPECT_EQ(draw.calls[1].fill.a, 0); // not filled
    EXPECT_EQ(draw.calls[1].outline, kPalette.staticBody);
}

TEST(DebugDraw, BulletsGetTheirOwnOutline) {
    World world;
    world.createBody({.x = 0, .y = 0, .hw = 0.1f, .hh = 0.1f, .bullet = true});
    Recorder draw;
    world.debugDraw(draw);
    ASSERT_EQ(draw.calls.size(), 1u);
    EXPECT_EQ(draw.calls[0].outline, kPalette.bulletOutline);
}

TEST(DebugDraw, RoundShapesAreRoundedBoxesWithTheirRadius) {
    World world;
    world.createBody({.x = 3, .y = 4, .hw = 0.5f, .hh = 0.5f, .radius = 0.5f});   // a circle
    world.createBody({.x = 0, .y = 0, .hw = 0.25f, .hh = 1.0f, .radius = 0.25f}); // a capsule
    Recorder draw;
    world.debugDraw(draw);
    const auto rounded = draw.of(Recorder::Call::Rounded);
    ASSERT_EQ(rounded.size(), 2u);
    EXPECT_EQ(rounded[0].points[0], (Vec2{3, 4}));
    EXPECT_EQ(rounded[0].points[1], (Vec2{0.5f, 0.5f}));
    EXPECT_EQ(rounded[0].radius, 0.5f);
    EXPECT_EQ(rounded[1].points[1], (Vec2{0.25f, 1.0f}));
    EXPECT_EQ(rounded[1].radius, 0.25f);
}

// A ramp whose slope names the corner (+x, -y) is the box without the half towards that
// corner: the sloped face runs between the other diagonal's corners, (+x, +y) and (-x, -y),
// and the right angle is at the corner opposite the one named, (-x, +y).
TEST(DebugDraw, ARampIsTheTriangleItsSlopeLeaves) {
    World world;
    world.createBody(
        {.type = BodyType::Static, .x = 10, .y = 20, .hw = 2, .hh = 1, .slope = {1, -1}});
    Recorder draw;
    world.debugDraw(draw);
    ASSERT_EQ(draw.calls.size(), 1u);
    const Recorder::Call& call = draw.calls[0];
    ASSERT_EQ(call.kind, Recorder::Call::Triangle);
    EXPECT_EQ(call.points[0], (Vec2{12, 21}));
    EXPECT_EQ(call.points[1], (Vec2{8, 19}));
    EXPECT_EQ(call.points[2], (Vec2{8, 21}));
    EXPECT_EQ(call.fill, kPalette.staticBody);
}

// A segment is the sloped face alone, with a tick from its middle towards the side it
// blocks (the corner its slope names): a sixth of its length, at most markLength.
TEST(DebugDraw, ASegmentIsALineWithATickOnItsBlockingSide) {
    World world;
    world.createBody({.type = BodyType::Static,
                      .x = 0,
                      .y = 0,
                      .hw = 3,
                      .hh = 3,
                      .slope = {-1, -1},
                      .segment = true});
    Recorder draw;
    world.debugDraw(draw, {.markLength = 0.5f});
    const auto lines = draw.of(Recorder::Call::Line);
    ASSERT_EQ(lines.size(), 2u);
    EXPECT_EQ(lines[0].points[0], (Vec2{-3, 3}));
    EXPECT_EQ(lines[0].points[1], (Vec2{3, -3}));
    const Vec2 tick = lines[1].points[1] - lines[1].points[0];
    EXPECT_EQ(lines[1].points[0], (Vec2{0, 0}));
    // Length 6 sqrt 2, a sixth of it 1.41: the mark's 0.5 is shorter. Towards (-1, -1).
    EXPECT_NEAR(length(tick), 0.5f, 1e-6f);
    EXPECT_NEAR(tick.x, -0.5f / std::sqrt(2.0f), 1e-6f);
    EXPECT_NEAR(tick.y, -0.5f / std::sqrt(2.0f), 1e-6f);
}

TEST(DebugDraw, AOneWayBodyMarksTheFaceItBlocksFrom) {
    World world;
    world.createBody(
        {.type = BodyType::Static, .x = 0, .y = 10, .hw = 4, .hh = 0.5f, .oneWay = {0, -1}});
    Recorder draw;
    world.debugDraw(draw);
    const auto lines = draw.of(Recorder::Call::Line);
    ASSERT_EQ(lines.size(), 1u);
    EXPECT_EQ(lines[0].fill, kPalette.oneWayFace);
    EXPECT_EQ(lines[0].points[0], (Vec2{-4, 9.5f})); // the top face, y = 10 - 0.5
    EXPECT_EQ(lines[0].points[1], (Vec2{4, 9.5f}));
}

// A tile map's solid tiles are merged into runs: a row of five tiles is one box.
TEST(DebugDraw, ATileMapIsDrawnAsItsMergedBoxes) {
    World world;
    createTileMap(world, {.x = 0, .y = 0, .tile = 1, .rows = {".....", "#####"}});
    Recorder draw;
    world.debugDraw(draw);
    ASSERT_EQ(draw.calls.size(), 1u);
    EXPECT_EQ(draw.calls[0].points[0], (Vec2{2.5f, 1.5f}));
    EXPECT_EQ(draw.calls[0].points[1], (Vec2{2.5f, 0.5f}));
}

// A box resting on a floor whose top is y = 0: one contact, at y = 0 under the box, its
// normal pointing into the box (up, y-down world), markLength long (half the box is more).
TEST(DebugDraw, AContactIsItsPointAndItsNormalIntoTheBodyItPushes) {
    World world(WorldDef{.gravity = {0, 10}, .sleeping = false});
    world.createBody({.type = BodyType::Static, .x = 0, .y = 1, .hw = 10, .hh = 1});
    world.createBody({.x = 2, .y = -0.5f, .hw = 0.5f, .hh = 0.5f});
    for (int i = 0; i < 60; ++i)
        world.step(kDt);
    Recorder draw;
    world.debugDraw(draw, {.shapes = false, .contacts = true, .markLength = 0.25f});
    const auto points = draw.of(Recorder::Call::Point);
    const auto lines = draw.of(Recorder::Call::Line);
    ASSERT_EQ(points.size(), 1u);
    ASSERT_EQ(lines.size(), 1u);
    EXPECT_NEAR(points[0].points[0].x, 2.0f, 1e-3f);
    EXPECT_NEAR(points[0].points[0].y, 0.0f, 1e-2f);
    EXPECT_EQ(points[0].fill, kPalette.contact);
    const Vec2 normal = lines[0].points[1] - lines[0].points[0];
    EXPECT_NEAR(normal.x, 0.0f, 1e-6f);
    EXPECT_NEAR(normal.y, -0.25f, 1e-6f);
}

// Falling with gravity (0, 10) for 0.5 s: 5 units/s down, drawn as 0.1 s of motion.
TEST(DebugDraw, VelocityIsATenthOfASecondOfMotion) {
    World world(WorldDef{.gravity = {0, 10}, .sleeping = false});
    const BodyId box = world.createBody({.x = 0, .y = 0, .hw = 0.5f, .hh = 0.5f});
    for (int i = 0; i < 30; ++i)
        world.step(kDt);
    Recorder draw;
    world.debugDraw(draw, {.shapes = false, .velocities = true});
    const auto lines = draw.of(Recorder::Call::Line);
    ASSERT_EQ(lines.size(), 1u);
    EXPECT_EQ(lines[0].points[0], world.position(box));
    EXPECT_NEAR(lines[0].points[1].y - lines[0].points[0].y, 0.5f, 1e-4f);
    EXPECT_EQ(lines[0].fill, kPalette.velocity);
}

// A newcomer's count of lines found one for each crate at rest, from its centre to itself.
TEST(DebugDraw, ABodyAtRestHasNoVelocityLine) {
    World world(WorldDef{.gravity = {0, 0}, .sleeping = false});
    world.createBody({.x = 0, .y = 0, .hw = 0.5f, .hh = 0.5f});
    world.createBody({.x = 5, .y = 0, .hw = 0.5f, .hh = 0.5f, .vx = 1});
    world.step(kDt);
    Recorder draw;
    world.debugDraw(draw, {.shapes = false, .velocities = true});
    EXPECT_EQ(draw.of(Recorder::Call::Line).size(), 1u); // the moving one's alone
}

// Touched sides are relative to gravity: with gravity pointing to +x, the floor is the
// box's +x face.
TEST(DebugDraw, TheTouchedFloorIsTheFaceGravityPullsTowards) {
    World world(WorldDef{.gravity = {10, 0}, .sleeping = false});
    world.createBody({.type = BodyType::Static, .x = 1, .y = 0, .hw = 1, .hh = 10});
    world.createBody({.x = -0.5f, .y = 0, .hw = 0.5f, .hh = 0.5f});
    for (int i = 0; i < 30; ++i)
        world.step(kDt);
    Recorder draw;
    world.debugDraw(draw, {.shapes = false, .touching = true});
    const auto lines = draw.of(Recorder::Call::Line);
    ASSERT_EQ(lines.size(), 1u);
    EXPECT_EQ(lines[0].fill, kPalette.touching);
    EXPECT_NEAR(lines[0].points[0].x, 0.0f, 1e-2f); // the face at x = 0
    EXPECT_NEAR(lines[0].points[1].x, 0.0f, 1e-2f);
    EXPECT_NEAR(std::abs(lines[0].points[1].y - lines[0].points[0].y), 1.0f, 1e-4f);
}

// Gravity pulling to -y: "down" is -y, and the body's right, looking along gravity, is
// (down.y, -down.x) = (-1, 0). A wall at the box's -x side is on its right.
TEST(DebugDraw, TheWallsAreLeftAndRightLookingAlongGravity) {
    World world(WorldDef{.gravity = {0, -10}, .sleeping = false});
    world.createBody({.type = BodyType::Static, .x = 0, .y = -1, .hw = 10, .hh = 1}); // floor
    world.createBody({.type = BodyType::Static, .x = -1, .y = 5, .hw = 1, .hh = 5});  // wall
    const BodyId box = world.createBody({.x = 0.5f, .y = 0.5f, .hw = 0.5f, .hh = 0.5f});
    for (int i = 0; i < 30; ++i) { // pressed against the wall
        world.applyForce(box, {-20, 0});
        world.step(kDt);
    }
    ASSERT_TRUE(world.touching(box).wallRight);
    Recorder draw;
    world.debugDraw(draw, {.shapes = false, .touching = true});
    const auto lines = draw.of(Recorder::Call::Line);
    // The floor (the -y face) and the wall on the -x face.
    ASSERT_EQ(lines.size(), 2u);
    const Vec2 centre = world.position(box);
    EXPECT_NEAR(lines[0].points[0].y, centre.y - 0.5f, 1e-5f);
    EXPECT_NEAR(lines[0].points[1].y, centre.y - 0.5f, 1e-5f);
    EXPECT_NEAR(lines[1].points[0].x, centre.x - 0.5f, 1e-5f);
    EXPECT_NEAR(lines[1].points[1].x, centre.x - 0.5f, 1e-5f);
}

// A renderer that changes the world while it is walked is refused, and the walk ends.
TEST(DebugDraw, ARendererThatChangesTheWorldIsRefused) {
    World world;
    world.createBody({.type = BodyType::Static, .x = 0, .y = 0, .hw = 1, .hh = 1});
    struct Changer : DebugDraw {
        World* world = nullptr;
        void line(Vec2, Vec2, Colour) override {}
        void box(Vec2, Vec2, Colour, Colour) override {
            world->createBody({.x = 5, .y = 5, .hw = 1, .hh = 1});
        }
    } draw;
    draw.world = &world;
    try {
        world.debugDraw(draw);
        ADD_FAILURE() << "a body created from a DebugDraw function was accepted";
    } catch (const Error& error) {
        EXPECT_STREQ(error.what(), "createBody: called from a DebugDraw function (the world "
                                   "cannot change until debugDraw is done)");
    }
    EXPECT_EQ(world.bodyCount(), 1u);
    world.createBody({.x = 5, .y = 5, .hw = 1, .hh = 1}); // and after it, as ever
    EXPECT_EQ(world.bodyCount(), 2u);
}

TEST(DebugDraw, OnlyWhatTouchesTheViewIsDrawn) {
    World world;
    world.createBody({.type = BodyType::Static, .x = 0, .y = 0, .hw = 1, .hh = 1});
    world.createBody({.type = BodyType::Static, .x = 100, .y = 0, .hw = 1, .hh = 1});
    Recorder draw;
    world.debugDraw(draw, {.viewMin = {-10, -10}, .viewMax = {10, 10}});
    ASSERT_EQ(draw.calls.size(), 1u);
    EXPECT_EQ(draw.calls[0].points[0], (Vec2{0, 0}));
}

// A row of 100 tiles with gaps ("#.#.#..."): 50 boxes of one tile each. A view from x 0 to
// 5 overlaps the tiles from 0 to 1, 2 to 3 and 4 to 5 only, and only they are drawn, with
// a sensor in view; nothing beyond.
TEST(DebugDraw, AViewOfAWideMapDrawsWhatItOverlaps) {
    World world;
    std::string row;
    for (int i = 0; i < 50; ++i)
        row += "#.";
    createTileMap(world, {.x = 0, .y = 0, .tile = 1, .rows = {row}});
    world.createBody(
        {.type = BodyType::Static, .x = 1.5f, .y = 3, .hw = 1, .hh = 1, .sensor = true});
    world.createBody({.type = BodyType::Static, .x = 60, .y = 3, .hw = 1, .hh = 1, .sensor = true});
    Recorder draw;
    world.debugDraw(draw, {.viewMin = {0, 0}, .viewMax = {5, 5}});
    const auto boxes = draw.of(Recorder::Call::Box);
    ASSERT_EQ(boxes.size(), 4u);
    for (std::size_t i = 0; i < 3; ++i)
        EXPECT_EQ(boxes[i].points[0], (Vec2{0.5f + 2.0f * float(i), 0.5f}));
    EXPECT_EQ(boxes[3].points[0], (Vec2{1.5f, 3})); // the sensor in view, last
}

// The broadphase files a box in the cell of its level that holds its min corner
// (docs/broadphase.md): some drawn cell holds it, and the moving box covers the body.
TEST(DebugDraw, TheGridShowsACellHoldingEachMovingBox) {
    World world(WorldDef{.gravity = {0, 10}, .sleeping = false});
    const BodyId box = world.createBody({.x = 3.3f, .y = -7.1f, .hw = 0.5f, .hh = 0.5f});
    world.step(kDt);
    Recorder draw;
    world.debugDraw(draw, {.shapes = false, .grid = true});
    const Vec2 low = world.position(box) - world.halfExtents(box);
    const Vec2 high = world.position(box) + world.halfExtents(box);
    bool cell = false, grown = false;
    for (const auto& call : draw.of(Recorder::Call::Box)) {
        const Vec2 min = call.points[0] - call.points[1], max = call.points[0] + call.points[1];
        EXPECT_EQ(call.fill.a, 0);
        // A cell of the level a lone 1 x 1 box goes to: square, at least as large as the box
        // (a level's cells hold its boxes), at most 2.5 times (1.25 times the smallest box,
        // doubled at most once: docs/broadphase.md).
        const Vec2 size = max - min;
        if (call.outline == kPalette.gridCell && min.x <= low.x && low.x < max.x &&
            min.y <= low.y && low.y < max.y)
            cell = cell || (std::abs(size.x - size.y) < 1e-5f && size.x >= 1.0f && size.x <= 2.5f);
        if (call.outline == kPalette.gridBox)
            grown =
                grown || (min.x <= low.x && min.y <= low.y && max.x >= high.x && max.y >= high.y);
    }
    EXPECT_TRUE(cell);
    EXPECT_TRUE(grown);
}

// --- A renderer of lines alone ------------------------------------------------------------

/// The lines as unordered pairs of ends, sorted: comparable whatever their order.
std::vector<std::pair<Vec2, Vec2>> sortedLines(std::vector<std::pair<Vec2, Vec2>> lines) {
    const auto less = [](Vec2 a, Vec2 b) { return a.x != b.x ? a.x < b.x : a.y < b.y; };
    for (auto& [a, b] : lines)
        if (less(b, a))
            std::swap(a, b);
    std::sort(lines.begin(), lines.end(), [&](const auto& p, const auto& q) {
        return p.first != q.first ? less(p.first, q.first) : less(p.second, q.second);
    });
    return lines;
}

TEST(DebugDraw, WithLinesOnlyABoxIsItsFourSides) {
    World world;
    world.createBody({.type = BodyType::Static, .x = 0, .y = 0, .hw = 2, .hh = 1});
    Lines draw;
    world.debugDraw(draw);
    const std::vector<std::pair<Vec2, Vec2>> sides{
        {{-2, -1}, {2, -1}}, {{2, -1}, {2, 1}}, {{-2, 1}, {2, 1}}, {{-2, -1}, {-2, 1}}};
    EXPECT_EQ(sortedLines(draw.lines), sortedLines(sides));
}

TEST(DebugDraw, WithLinesOnlyACircleIsAClosedRingOnItsEdge) {
    World world;
    world.createBody({.x = 1, .y = 1, .hw = 2, .hh = 2, .radius = 2});
    Lines draw;
    world.debugDraw(draw);
    ASSERT_GE(draw.lines.size(), 12u);
    for (const auto& [from, to] : draw.lines)
        EXPECT_NEAR(length(from - Vec2{1, 1}), 2.0f, 1e-5f);
    for (std::size_t i = 0; i < draw.lines.size(); ++i) // each line starts where one ends
        EXPECT_EQ(draw.lines[i].first,
                  draw.lines[(i + draw.lines.size() - 1) % draw.lines.size()].second);
}

// The ramp whose slope names the corner (+x, +y): its face from (+x, -y) to (-x, +y), its
// right angle at (-x, -y).
TEST(DebugDraw, WithLinesOnlyARampIsItsThreeSides) {
    World world;
    world.createBody({.type = BodyType::Static, .x = 0, .y = 0, .hw = 1, .hh = 1, .slope = {1, 1}});
    Lines draw;
    world.debugDraw(draw);
    const std::vector<std::pair<Vec2, Vec2>> sides{
        {{1, -1}, {-1, 1}}, {{-1, 1}, {-1, -1}}, {{-1, -1}, {1, -1}}};
    EXPECT_EQ(sortedLines(draw.lines), sortedLines(sides));
}

// A list replays the calls in their order with their values: the same calls as drawing
// straight away.
TEST(DebugDraw, AListReplaysTheSameCalls) {
    World world(WorldDef{.gravity = {0, 10}, .sleeping = false});
    world.createBody({.type = BodyType::Static, .x = 0, .y = 1, .hw = 10, .hh = 1});
    world.createBody({.x = 0, .y = -0.5f, .hw = 0.5f, .hh = 0.5f, .radius = 0.5f});
    world.createBody(
        {.type = BodyType::Static, .x = 4, .y = -1, .hw = 1, .hh = 1, .slope = {1, -1}});
    for (int i = 0; i < 30; ++i)
        world.step(kDt);
    const DebugDrawOptions options{.contacts = true, .velocities = true};
    Recorder direct, replayed;
    DebugDrawList list;
    world.debugDraw(direct, options);
    world.debugDraw(list, options);
    list.replay(replayed);
    ASSERT_EQ(list.commands().size(), direct.calls.size());
    ASSERT_EQ(replayed.calls.size(), direct.calls.size());
    for (std::size_t i = 0; i < direct.calls.size(); ++i) {
        EXPECT_EQ(replayed.calls[i].kind, direct.calls[i].kind);
        EXPECT_EQ(replayed.calls[i].points, direct.calls[i].points);
        EXPECT_EQ(replayed.calls[i].radius, direct.calls[i].radius);
        EXPECT_EQ(replayed.calls[i].fill, direct.calls[i].fill);
        EXPECT_EQ(replayed.calls[i].outline, direct.calls[i].outline);
    }
    list.clear();
    EXPECT_TRUE(list.commands().empty());
}

TEST(DebugDraw, BadOptionsAreRefusedByName) {
    World world;
    Lines draw;
    EXPECT_THROW(
        {
            try {
                world.debugDraw(draw, {.markLength = -1});
            } catch (const Error& error) {
                EXPECT_STREQ(error.what(),
                             "debugDraw: options.markLength must be a finite number >= 0");
                throw;
            }
        },
        Error);
    const auto message = [&](const DebugDrawOptions& options) {
        try {
            world.debugDraw(draw, options);
        } catch (const Error& error) {
            return std::string(error.what());
        }
        return std::string("accepted");
    };
    EXPECT_EQ(message({.markLength = NAN}),
              "debugDraw: options.markLength must be a finite number >= 0");
    EXPECT_EQ(message({.viewMin = {INFINITY, 0}}), "debugDraw: options.viewMin must be finite");
    DebugDrawOptions options;
    options.palette.sleepingPercent = 101;
    EXPECT_EQ(message(options), "debugDraw: options.palette.sleepingPercent must be in [0, 100]");
    options = {};
    options.palette.outlinePercent = -1;
    EXPECT_EQ(message(options), "debugDraw: options.palette.outlinePercent must be in [0, 100]");
    // A view and a mark as large as floats go are drawing, not misuse.
    EXPECT_EQ(
        message({.markLength = 1e30f, .viewMin = {-1e30f, -1e30f}, .viewMax = {1e30f, 1e30f}}),
        "accepted");
}

} // namespace
} // namespace jostle
