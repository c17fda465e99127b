// `jostle render`, run as a user runs it: the files it writes are read back with libpng
// and giflib, and their pixels checked against positions worked out by hand from the
// camera rule of docs/scene-format.md.
#include "program_test.hpp"

#include <gif_lib.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <png.h>

#include <array>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

namespace {

using ::testing::HasSubstr;

using Result = jostle::testing::ProgramResult;

struct Rgb {
    int r, g, b;
    friend bool operator==(Rgb, Rgb) = default;
};

std::ostream& operator<<(std::ostream& out, Rgb c) {
    return out << "rgb(" << c.r << ", " << c.g << ", " << c.b << ")";
}

// The documented colours (docs/scene-format.md, `jostle render`).
constexpr Rgb kBackground{24, 26, 33};
constexpr Rgb kStatic{150, 150, 150};
constexpr Rgb kStaticOutline{90, 90, 90};
constexpr Rgb kDynamic{240, 150, 60};
constexpr Rgb kDynamicOutline{144, 90, 36};
constexpr Rgb kKinematicSensor{70, 130, 230};
constexpr Rgb kDynamicAsleep{132, 82, 33}; // 55%
constexpr Rgb kLegendLine{60, 64, 76};
constexpr Rgb kLegendText{230, 230, 230};

/// A PNG read back as RGB.
struct Png {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgb;

    Rgb at(int x, int y) const {
        const std::size_t i = (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                               static_cast<std::size_t>(x)) *
                              3;
        return {rgb[i], rgb[i + 1], rgb[i + 2]};
    }
};

Png readPng(const std::string& path) {
    png_image image{};
    image.version = PNG_IMAGE_VERSION;
    Png png;
    if (!png_image_begin_read_from_file(&image, path.c_str())) {
        ADD_FAILURE() << path << ": " << image.message;
        return png;
    }
    image.format = PNG_FORMAT_RGB;
    png.width = static_cast<int>(image.width);
    png.height = static_cast<int>(image.height);
    png.rgb.resize(PNG_IMAGE_SIZE(image));
    if (!png_image_finish_read(&image, nullptr, png.rgb.data(), 0, nullptr))
        ADD_FAILURE() << path << ": " << image.message;
    return png;
}

struct Gif {
    int width = 0;
    int height = 0;
    int frames = 0;
};

Gif readGif(const std::string& path) {
    int error = 0;
    GifFileType* file = DGifOpenFileName(path.c_str(), &error);
    if (!file) {
        ADD_FAILURE() << path << ": " << GifErrorString(error);
        return {};
    }
    if (DGifSlurp(file) == GIF_ERROR)
        ADD_FAILURE() << path << ": " << GifErrorString(file->Error);
    const Gif gif{file->SWidth, file->SHeight, file->ImageCount};
    DGifCloseFile(file, &error);
    return gif;
}

class Render : public jostle::testing::ProgramTest {
protected:
    /// Runs `jostle render ARGS`.
    Result render(const std::string& args) { return run("render " + args); }
};

// One static box 20 × 20, away from the origin. Its bounds, 20 wide, get a margin of
// 20 / 20 = 1 on each side: 22 world units fill the 110 pixels, 5 pixels each, and the
// box's left edge (x = 90) falls on pixel 5, its right edge (x = 110) on pixel 105. So
// columns and rows 5 to 104 are the box, 5 and 104 its outline, and 0-4 and 105-109
// the background.
constexpr const char* kOneBox = R"({"bodies": [
    {"type": "static", "x": 100, "y": -50, "hw": 10, "hh": 10}]})";

/// A 110 × 110 picture of a lone box, the view its bounds and their margin: the box in
/// `fill` from pixel 5 to 104 each way, its outline at 5 and 104, background around it.
void expectTheBoxFillsTheView(const Png& png, Rgb fill, Rgb outline) {
    ASSERT_EQ(png.width, 110);
    ASSERT_EQ(png.height, 110);
    EXPECT_EQ(png.at(55, 55), fill);
    EXPECT_EQ(png.at(6, 6), fill);
    EXPECT_EQ(png.at(103, 103), fill);
    EXPECT_EQ(png.at(5, 55), outline);
    EXPECT_EQ(png.at(104, 55), outline);
    EXPECT_EQ(png.at(55, 5), outline);
    EXPECT_EQ(png.at(55, 104), outline);
    EXPECT_EQ(png.at(4, 55), kBackground);
    EXPECT_EQ(png.at(105, 55), kBackground);
    EXPECT_EQ(png.at(55, 4), kBackground);
    EXPECT_EQ(png.at(55, 105), kBackground);
    EXPECT_EQ(png.at(0, 0), kBackground);
}

TEST_F(Render, PngOfOneBoxHasTheBoxWhereTheCameraRulePutsIt) {
    const std::string scene = write("box.json", kOneBox);
    const Result result =
        render(scene + " --out " + path("box.png") + " --width 110 --height 110 --steps 3");
    ASSERT_EQ(result.status, 0) << result.err;
    expectTheBoxFillsTheView(readPng(path("box.png")), kStatic, kStaticOutline);
}

// A static box above a dynamic one (no gravity, so nothing moves) and a kinematic sensor
// around the pair. y grows downward, so the box with the smaller y is at the top. The
// bounds are the sensor's: x -15 to 15, y -15 to 55, 70 high, so the margin is 3.5 and
// the view 37 × 77; 2 pixels a unit fit it into 74 × 154, centred on (0, 20):
// image x = 2x + 37, image y = 2(y - 20) + 77.
constexpr const char* kStack = R"({"gravity": [0, 0], "bodies": [
    {"type": "static", "x": 0, "y": 0, "hw": 10, "hh": 10},
    {"type": "dynamic", "x": 0, "y": 40, "hw": 10, "hh": 10},
    {"type": "kinematic", "sensor": true, "x": 0, "y": 20, "hw": 15, "hh": 35}]})";

TEST_F(Render, YGrowsDownwardAndEachTypeHasItsColour) {
    const std::string scene = write("stack.json", kStack);
    const Result result = render(scene + " --out " + path("stack.png") + " --width 74 --steps 0");
    ASSERT_EQ(result.status, 0) << result.err;
    const Png png = readPng(path("stack.png"));
    ASSERT_EQ(png.width, 74);
    ASSERT_EQ(png.height, 154);                 // fitted: 74 × 77 / 37
    EXPECT_EQ(png.at(37, 37), kStatic);         // (0, 0)
    EXPECT_EQ(png.at(37, 117), kDynamic);       // (0, 40)
    EXPECT_EQ(png.at(37, 77), kBackground);     // (0, 20): between them, inside the sensor
    EXPECT_EQ(png.at(7, 77), kKinematicSensor); // the sensor's left edge, x = -15
    EXPECT_EQ(png.at(37, 7), kKinematicSensor); // its top edge, y = -15
    EXPECT_EQ(png.at(6, 77), kBackground);
}

// --debug (docs/scene-format.md): a box 10 x 10 resting on a floor whose top is y = 0,
// gravity down. The bounds, x -20 to 20 and y -10 to 20, 40 wide, get a margin of 2: a
// view 44 x 34, 2 pixels a unit at 88 wide, 68 high, centred on (0, 5): image x = 2x + 44,
// image y = 2y + 24. The contact point (0, 0) is pixel (44, 24): a 3 x 3 dot, and the
// normal up into the box, 8 pixels (the box is 20 pixels tall, half of it 10). The floor's
// side of the box (y = 0, the row 24) is marked red from x -5 to 5. Without --debug,
// none of it: the box's fill over the normal, the floor's outline under the side.
constexpr const char* kResting = R"({"gravity": [0, 100], "bodies": [
    {"type": "static", "x": 0, "y": 10, "hw": 20, "hh": 10},
    {"type": "dynamic", "x": 0, "y": -5, "hw": 5, "hh": 5}]})";

TEST_F(Render, DebugAddsTheContactsAndTheSidesTouched) {
    constexpr Rgb kContact{250, 250, 120};
    constexpr Rgb kTouching{230, 60, 60};
    const std::string scene = write("resting.json", kResting);
    for (const bool debug : {true, false}) {
        const std::string out = path(debug ? "debug.png" : "plain.png");
        const Result result =
            render(scene + " --out " + out + " --width 88 --steps 30" + (debug ? " --debug" : ""));
        ASSERT_EQ(result.status, 0) << result.err;
        const Png png = readPng(out);
        ASSERT_EQ(png.height, 68);
        const Rgb dot = png.at(44, 24), normal = png.at(44, 20), side = png.at(36, 24);
        if (debug) {
            EXPECT_EQ(dot, kContact);
            EXPECT_EQ(png.at(43, 25), kContact);
            EXPECT_EQ(normal, kContact);
            EXPECT_EQ(side, kTouching);
        } else {
            EXPECT_NE(dot, kContact);
            EXPECT_NE(normal, kContact);
            EXPECT_NE(side, kTouching);
            EXPECT_EQ(side, kStaticOutline);
        }
    }
}

// --legend: the key in a band under the scene (docs/scene-format.md). The lone box at 110
// pixels wide, as above: its one entry, "static", takes 5 + 7 + 3 + 6 × 6 - 1 + 5 = 55
// font pixels with the margins, so it is drawn twice as large, 10 pixels in from the
// left. The band is a line (row 110), a margin of 10, the swatch's 14 rows and a margin
// of 10: 35 rows, so the image is 145 high and the scene above it as without a key.
TEST_F(Render, LegendAddsAKeyUnderTheScene) {
    const std::string scene = write("box.json", kOneBox);
    const Result result = render(scene + " --out " + path("key.png") +
                                 " --width 110 --height 110 --steps 3 --legend");
    ASSERT_EQ(result.status, 0) << result.err;
    const Png png = readPng(path("key.png"));
    ASSERT_EQ(png.width, 110);
    ASSERT_EQ(png.height, 145);
    EXPECT_EQ(png.at(55, 55), kStatic); // the scene, as in PngOfOneBox... above
    EXPECT_EQ(png.at(55, 104), kStaticOutline);
    EXPECT_EQ(png.at(55, 105), kBackground);
    EXPECT_EQ(png.at(0, 110), kLegendLine); // the line across the top of the band
    EXPECT_EQ(png.at(109, 110), kLegendLine);
    EXPECT_EQ(png.at(10, 121), kStaticOutline); // the swatch: columns 10-23, rows 121-134
    EXPECT_EQ(png.at(23, 134), kStaticOutline);
    EXPECT_EQ(png.at(16, 128), kStatic);
    EXPECT_EQ(png.at(9, 128), kBackground);
    // "STATIC" from x 24 + 6: the S's top row is its 4 right pixels, 2 × 2 each.
    EXPECT_EQ(png.at(30, 121), kBackground);
    EXPECT_EQ(png.at(32, 121), kLegendText);
    EXPECT_EQ(png.at(39, 122), kLegendText);
    EXPECT_EQ(png.at(55, 140), kBackground); // the bottom margin
}

// What the key lists: each body type the scene has, "asleep" where bodies can fall asleep
// (the physical model with sleeping on), and sensors. In the stack above at 74 pixels
// wide, the font's own size: four entries a row each (static, dynamic, asleep, sensor;
// the only kinematic body is a sensor), 1 + 5 + 4 × 7 + 3 × 4 + 5 = 51 rows; the classic
// model has no "asleep": three rows, 1 + 5 + 3 × 7 + 2 × 4 + 5 = 40.
TEST_F(Render, LegendListsWhatTheSceneHas) {
    const std::string scene = write("stack.json", kStack);
    for (const char* solver : {"physical", "classic"}) {
        SCOPED_TRACE(solver);
        const std::string out = path(std::string(solver) + ".png");
        const Result result = render(scene + " --out " + out + " --width 74 --steps 0 --legend" +
                                     " --solver " + solver);
        ASSERT_EQ(result.status, 0) << result.err;
        const Png png = readPng(out);
        const bool physical = std::string(solver) == "physical";
        ASSERT_EQ(png.height, 154 + (physical ? 51 : 40));
        // The swatches, 7 × 7 from x 5, rows 11 apart from row 154 + 1 + 5 = 160.
        EXPECT_EQ(png.at(8, 163), kStatic);
        EXPECT_EQ(png.at(8, 174), kDynamic);
        if (physical) {
            EXPECT_EQ(png.at(8, 185), kDynamicAsleep);
        }
        const int sensorRow = physical ? 196 : 185;
        EXPECT_EQ(png.at(5, sensorRow), kKinematicSensor); // outlined only
        EXPECT_EQ(png.at(8, sensorRow), kBackground);
    }
}

// A circle, a ramp and a segment, 20 × 20 each, side by side, no gravity. The bounds are
// x -10 to 70 and y -10 to 10; with the margin of 80 / 20 = 4, 88 × 28 units fill 176 ×
// 56 pixels, 2 a unit: image x = 2x + 28, image y = 2y + 28.
constexpr const char* kShapes = R"({"gravity": [0, 0], "bodies": [
    {"type": "static", "x": 0, "y": 0, "hw": 10, "hh": 10, "radius": 10},
    {"type": "static", "x": 30, "y": 0, "hw": 10, "hh": 10, "slope": [1, -1]},
    {"type": "static", "x": 60, "y": 0, "hw": 10, "hh": 10, "slope": [-1, -1],
     "segment": true}]})";

TEST_F(Render, ShapesAreDrawnInTheirShape) {
    const std::string scene = write("shapes.json", kShapes);
    const Result result = render(scene + " --out " + path("shapes.png") + " --width 176");
    ASSERT_EQ(result.status, 0) << result.err;
    const Png png = readPng(path("shapes.png"));
    ASSERT_EQ(png.height, 56);
    // The circle: its centre filled, the corners of its box empty, its edge outlined.
    EXPECT_EQ(png.at(28, 28), kStatic);
    EXPECT_EQ(png.at(9, 9), kBackground);     // (-9.25, -9.25), 13 from the centre
    EXPECT_EQ(png.at(46, 46), kBackground);   // (9.25, 9.25)
    EXPECT_EQ(png.at(8, 28), kStaticOutline); // (-9.75, 0.25): in, its left neighbour out
    EXPECT_EQ(png.at(7, 28), kBackground);
    EXPECT_EQ(png.at(28, 8), kStaticOutline); // the top
    // The ramp [1, -1]: the top right corner of its box cut away, the bottom left kept.
    EXPECT_EQ(png.at(106, 10), kBackground);   // (39.25, -8.75)
    EXPECT_EQ(png.at(100, 20), kBackground);   // (36.25, -3.75)
    EXPECT_EQ(png.at(72, 44), kStatic);        // (22.25, 8.25)
    EXPECT_EQ(png.at(80, 30), kStatic);        // (26.25, 1.25)
    EXPECT_EQ(png.at(68, 30), kStaticOutline); // its left side, x = 20
    // The segment [-1, -1]: the line from (50, 10) to (70, -10), nothing on either side,
    // and a tick from its middle towards the corner it looks at (up and left).
    EXPECT_EQ(png.at(148, 28), kStatic); // (60, 0)
    EXPECT_EQ(png.at(138, 38), kStatic); // (55, 5)
    EXPECT_EQ(png.at(158, 18), kStatic); // (65, -5)
    EXPECT_EQ(png.at(136, 20), kBackground);
    EXPECT_EQ(png.at(160, 40), kBackground);
    EXPECT_EQ(png.at(145, 25), kStatic); // the tick, 3 pixels up and left of the middle
    EXPECT_EQ(png.at(151, 31), kBackground);
}

// A view is as precise as the bodies in it, wherever they are: a body 2e-9 across at
// x = y = 1e9, where floats are 64 apart, fills the picture as the box of kOneBox does
// (its bounds, 2e-9 wide, get a margin of 1e-10 on each side: 110 pixels of 2e-11).
TEST_F(Render, ATinyBodyFarFromTheOriginFillsTheView) {
    const std::string box = write("box.json", R"({"gravity": [0, 0], "bodies": [
        {"x": 1e9, "y": 1e9, "hw": 1e-9, "hh": 1e-9}]})");
    const Result result =
        render(box + " --out " + path("box.png") + " --width 110 --height 110 --steps 0");
    ASSERT_EQ(result.status, 0) << result.err;
    EXPECT_EQ(result.err, "");
    expectTheBoxFillsTheView(readPng(path("box.png")), kDynamic, kDynamicOutline);

    // Neither size given: 640 wide and, as the view is square, 640 high.
    const Result fitted = render(box + " --out " + path("box.gif") + " --steps 1");
    ASSERT_EQ(fitted.status, 0) << fitted.err;
    const Gif gif = readGif(path("box.gif"));
    EXPECT_EQ(gif.width, 640);
    EXPECT_EQ(gif.height, 640);

    // A circle there: drawn round, 50 pixels in radius, its box's corners empty.
    const std::string circle = write("circle.json", R"({"gravity": [0, 0], "bodies": [
        {"x": 1e9, "y": -1e9, "hw": 1e-9, "hh": 1e-9, "radius": 1e-9}]})");
    const Result round = render(circle + " --out " + path("circle.png") + " --width 110 --steps 0");
    ASSERT_EQ(round.status, 0) << round.err;
    const Png disc = readPng(path("circle.png"));
    ASSERT_EQ(disc.height, 110);
    EXPECT_EQ(disc.at(55, 55), kDynamic);
    EXPECT_EQ(disc.at(5, 55), kDynamicOutline); // (5.5, 55.5): 49.5 from the centre
    EXPECT_EQ(disc.at(4, 55), kBackground);
    EXPECT_EQ(disc.at(8, 8), kBackground); // 66 from the centre
}

// Scenes at the edges of the world's range (magnitudes 1e-9 to 1e9) give a picture, with
// neither an error nor undefined behaviour (the sanitizer build checks the second).
TEST_F(Render, ScenesAtTheEdgesOfTheRangeRender) {
    const std::vector<std::string> scenes = {
        // Tiny bodies far apart: a pixel each.
        R"([{"x": -1e9, "y": 1e9, "hw": 1e-9, "hh": 1e-9},
            {"x": 1e9, "y": -1e9, "hw": 1e-9, "hh": 1e-9}])",
        // The largest bodies, side by side, and a tiny one between them.
        R"([{"type": "static", "x": -1e9, "y": 0, "hw": 1e9, "hh": 1e9},
            {"type": "static", "x": 1e9, "y": 0, "hw": 1e9, "hh": 1e9},
            {"x": 0, "y": 0, "hw": 1e-9, "hh": 1e-9, "radius": 1e-9}])",
        // A thin line of a scene, 2e9 by 2e-9, and shapes as small as can be.
        R"([{"type": "static", "x": 0, "y": 1e9, "hw": 1e9, "hh": 1e-9},
            {"type": "static", "x": 1e9, "y": 1e9, "hw": 1e-9, "hh": 1e-9,
             "slope": [1, -1]},
            {"type": "kinematic", "x": -1e9, "y": 1e9, "hw": 1e-9, "hh": 1e-9,
             "slope": [-1, -1], "segment": true, "vx": 1e9}])",
        // Every shape tiny, at one spot far away.
        R"([{"type": "static", "x": 1e9, "y": 1e9, "hw": 1e-9, "hh": 1e-9,
             "slope": [1, 1], "segment": true},
            {"type": "static", "x": 1e9, "y": 1e9, "hw": 1e-9, "hh": 1e-9,
             "slope": [-1, 1]},
            {"x": 1e9, "y": 1e9, "hw": 1e-9, "hh": 1e-9, "radius": 1e-9, "sensor": true}])",
    };
    for (std::size_t i = 0; i < scenes.size(); ++i) {
        const std::string scene =
            write("edge" + std::to_string(i) + ".json", R"({"bodies": )" + scenes[i] + "}");
        for (const std::string out : {"edge.png", "edge.gif"}) {
            SCOPED_TRACE(scenes[i] + " " + out);
            const Result result = render(scene + " --out " + path(out) + " --steps 4");
            EXPECT_EQ(result.status, 0);
            EXPECT_EQ(result.err, "");
        }
        for (const std::string size : {"--width 1", "--height 1", "--width 1 --height 4096"}) {
            SCOPED_TRACE(scenes[i] + " " + size);
            const Result result =
                render(scene + " --out " + path("edge.png") + " --steps 1 " + size);
            EXPECT_EQ(result.status, 0);
            EXPECT_EQ(result.err, "");
        }
    }
}

TEST_F(Render, GifHasAFrameForStepZeroAndEveryKthStep) {
    const std::string scene = write("box.json", kOneBox);
    const Result result = render(scene + " --out " + path("anim.gif") +
                                 " --width 64 --height 48 --steps 10 --every 3");
    ASSERT_EQ(result.status, 0) << result.err;
    const Gif gif = readGif(path("anim.gif"));
    EXPECT_EQ(gif.width, 64);
    EXPECT_EQ(gif.height, 48);
    EXPECT_EQ(gif.frames, 4); // steps 0, 3, 6, 9: floor(10 / 3) + 1
}

// Each frame after the first holds only the rectangle that changed (drawn over the frame
// before): the tutorial's boxes falling change a part of the picture, a static scene
// nothing, which is one pixel.
TEST_F(Render, GifFramesHoldWhatChanged) {
    const std::string still = write("box.json", kOneBox);
    const std::string falling = std::string(JOSTLE_SCENES_DIR) + "/tutorial.json";
    for (const std::string& scene : {still, falling}) {
        SCOPED_TRACE(scene);
        ASSERT_EQ(render(scene + " --out " + path("delta.gif") + " --steps 4 --every 2").status, 0);
        int error = 0;
        GifFileType* file = DGifOpenFileName(path("delta.gif").c_str(), &error);
        ASSERT_NE(file, nullptr) << GifErrorString(error);
        ASSERT_NE(DGifSlurp(file), GIF_ERROR);
        ASSERT_EQ(file->ImageCount, 3);
        const GifImageDesc& first = file->SavedImages[0].ImageDesc;
        EXPECT_EQ(first.Width, file->SWidth);
        EXPECT_EQ(first.Height, file->SHeight);
        for (int i = 1; i < 3; ++i) {
            const GifImageDesc& desc = file->SavedImages[i].ImageDesc;
            if (scene == still) {
                EXPECT_EQ(desc.Width, 1);
                EXPECT_EQ(desc.Height, 1);
            } else {
                EXPECT_GT(desc.Width * desc.Height, 1);
                EXPECT_LT(desc.Width * desc.Height, file->SWidth * file->SHeight);
            }
        }
        DGifCloseFile(file, &error);
    }
}

TEST_F(Render, ExampleSceneMakesAGifOfTheDefaultWidth) {
    const Result result = render(std::string(JOSTLE_SCENES_DIR) + "/tutorial.json --out " +
                                 path("tutorial.GIF") + " --steps 8");
    ASSERT_EQ(result.status, 0) << result.err;
    const Gif gif = readGif(path("tutorial.GIF"));
    EXPECT_EQ(gif.width, 640);
    EXPECT_GT(gif.height, 0);
    EXPECT_EQ(gif.frames, 5); // the default --every is 2
}

// A full disk (a name for /dev/full, which refuses every write with ENOSPC) gives the same
// message for either image, whether the first write that fails is early (a big picture)
// or the last (a small one, written when the file is closed); exit status 1.
TEST_F(Render, AnImageThatCannotBeWrittenSaysWhy) {
    const std::string scene = write("box.json", kOneBox);
    for (const std::string name : {"full.gif", "full.png"}) {
        const std::string image = path(name);
        std::filesystem::create_symlink("/dev/full", image);
        for (const std::string size : {"--width 8 --height 8 --steps 0", "--width 640"}) {
            SCOPED_TRACE(name);
            SCOPED_TRACE(size);
            const Result result = render(scene + " --out " + image + " " + size);
            EXPECT_EQ(result.status, 1);
            EXPECT_EQ(result.err,
                      "jostle: error: " + image + ": write failed: No space left on device\n");
        }
    }
}

// Progress on standard error when it is a terminal, erased at the end; none otherwise.
TEST_F(Render, ProgressOnATerminalOnly) {
    JOSTLE_SKIP_WITHOUT_A_TERMINAL();
    const std::string scene = write("box.json", kOneBox);
    for (const std::string name : {"anim.gif", "last.png"}) {
        SCOPED_TRACE(name);
        const std::string args = scene + " --out " + path(name) + " --width 32 --steps 300";
        const Result quiet = render(args);
        EXPECT_EQ(quiet.status, 0);
        EXPECT_EQ(quiet.err, "");

        const Result shown = runOnTerminal("render " + args);
        EXPECT_EQ(shown.status, 0);
        EXPECT_THAT(shown.err, ::testing::StartsWith("\rjostle render: step 0 of 300 (0%)"));
        EXPECT_EQ(jostle::testing::lastLineShown(shown.err), "");
        EXPECT_EQ(shown.out, "");
    }
    EXPECT_EQ(readGif(path("anim.gif")).frames, 151); // the GIF is whole
}

TEST_F(Render, BadInputExitsWith2AndNamesTheProblem) {
    const std::string scene = write("box.json", kOneBox);
    const std::string out = " --out " + path("x.png");
    struct Case {
        std::string args;
        std::string message;
    };
    const std::vector<Case> cases = {
        {path("missing.json") + out, "missing.json"},
        {scene, "--out"},
        {scene + out + " --steps many", "--steps"},
        {scene + out + " --steps -1", "--steps: must be >= 0"},
        {scene + out + " --width 0", "--width: must be >= 1, got 0"},
        {scene + out + " --height -5", "--height: must be >= 1"},
        {scene + out + " --width 100000", "--width: must be <= 4096, got 100000"},
        {scene + out + " --every 0", "--every: must be >= 1, got 0"},
        {scene + out + " --solver newton", "--solver: newton not in {classic,physical}"},
        {scene + " --out " + path("x.bmp"), "unknown image type"},
        {scene + " --out " + path("no/such/dir/x.png"), "cannot write"},
        {scene + " --out " + path("no/such/dir/x.gif"), "cannot write"},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.args);
        const Result result = render(c.args);
        EXPECT_EQ(result.status, 2);
        EXPECT_THAT(result.err, HasSubstr("jostle: error: "));
        EXPECT_THAT(result.err, HasSubstr(c.message));
    }
    EXPECT_FALSE(std::filesystem::exists(path("x.png"))); // nothing written on bad input
}

} // namespace
