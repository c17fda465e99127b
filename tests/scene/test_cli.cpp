// The jostle program, run as a user runs it: options, exit status, messages, and traces
// whose numbers are worked out by hand from the tutorial's formulas.
#include "program_test.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

namespace {

using ::testing::HasSubstr;
using ::testing::Not;
using ::testing::StartsWith;

using Result = jostle::testing::ProgramResult;
using jostle::testing::quote;
using jostle::testing::readAll;

/// One trace row, numbers read back as floats (%.9g round-trips exactly).
struct Row {
    std::string step;
    std::string id;
    float x, y, vx, vy;
};

std::vector<std::string> lines(const std::string& text) {
    std::vector<std::string> result;
    std::stringstream in(text);
    for (std::string line; std::getline(in, line);)
        result.push_back(line);
    return result;
}

std::vector<std::string> split(const std::string& line, char separator) {
    std::vector<std::string> fields;
    std::stringstream in(line);
    for (std::string field; std::getline(in, field, separator);)
        fields.push_back(field);
    return fields;
}

/// The rows of a trace, after checking its header.
std::vector<Row> rowsOf(const std::string& csv) {
    const std::vector<std::string> all = lines(csv);
    std::vector<Row> rows;
    if (all.empty()) {
        ADD_FAILURE() << "empty trace";
        return rows;
    }
    EXPECT_EQ(all[0], "step,id,x,y,vx,vy");
    for (std::size_t i = 1; i < all.size(); ++i) {
        const std::vector<std::string> f = split(all[i], ',');
        if (f.size() != 6) {
            ADD_FAILURE() << "not 6 fields: " << all[i];
            continue;
        }
        rows.push_back({f[0], f[1], std::strtof(f[2].c_str(), nullptr),
                        std::strtof(f[3].c_str(), nullptr), std::strtof(f[4].c_str(), nullptr),
                        std::strtof(f[5].c_str(), nullptr)});
    }
    return rows;
}

void expectRow(const Row& row, const std::string& step, const std::string& id, float x, float y,
               float vx, float vy) {
    SCOPED_TRACE("step " + step + ", " + id);
    EXPECT_EQ(row.step, step);
    EXPECT_EQ(row.id, id);
    EXPECT_EQ(row.x, x);
    EXPECT_EQ(row.y, y);
    EXPECT_EQ(row.vx, vx);
    EXPECT_EQ(row.vy, vy);
}

class Cli : public jostle::testing::ProgramTest {};

// A dynamic body in empty space, dt = 1/4: each step moves it by (4, -8) / 4 = (1, -2).
constexpr const char* kFreeScene = R"({"solver": "classic", "dt": 0.25, "bodies": [
    {"id": "ball", "x": 0, "y": 0, "hw": 1, "hh": 1, "vx": 4, "vy": -8}]})";

// A floor, two boxes falling onto it and a kinematic body passing above (dt = 1/4,
// gravity 32: each step adds 8 to vy). Every number below is a binary fraction.
constexpr const char* kFloorScene = R"({"solver": "classic", "gravity": [0, 32], "dt": 0.25,
  "bodies": [
    {"id": "floor", "type": "static", "x": 0, "y": 19.5, "hw": 100, "hh": 4,
     "bounce": 0, "friction": 0.5},
    {"id": "a", "x": 0, "y": 0, "hw": 4, "hh": 4, "vx": 4, "bounce": 0, "friction": 0.5},
    {"id": "b", "x": 50, "y": 0, "hw": 4, "hh": 4, "bounce": 0.5, "friction": 0},
    {"id": "k", "type": "kinematic", "x": 0, "y": -50, "hw": 1, "hh": 1, "vx": 8}]})";

TEST_F(Cli, TraceOfFreeMotionIsExact) {
    const std::string scene = write("free.json", kFreeScene);
    const Result r = run("run " + quote(scene) + " --steps 3 --trace -");
    EXPECT_EQ(r.status, 0);
    EXPECT_EQ(r.err, "");
    // x = n, y = -2n after step n; velocities unchanged (no gravity, nothing to hit).
    EXPECT_EQ(r.out, "step,id,x,y,vx,vy\n"
                     "1,ball,1,-2,4,-8\n"
                     "2,ball,2,-4,4,-8\n"
                     "3,ball,3,-6,4,-8\n");
}

TEST_F(Cli, TraceFollowsTheTutorialFormulas) {
    const std::string scene = write("floor.json", kFloorScene);
    const Result r = run("run " + quote(scene) + " --steps 6 --trace -");
    ASSERT_EQ(r.status, 0) << r.err;
    const std::vector<Row> rows = rowsOf(r.out);
    // One row per non-static body (a, b, k) after each step, in scene order.
    ASSERT_EQ(rows.size(), 6u * 3u);

    // Steps 1-2, free fall (velocity first, then position): vy = 8n, y = n(n + 1).
    // Step 3: y = 12 puts the bottom (16) 0.5 into the floor (top 15.5); y is the short
    // axis, so the box moves up to 11.5 and its approach speed, 24, is taken away:
    //   a: vy = 24 - 24 (1 + max(0, 0)) = 0; tangent 4 keeps 1 - min(0.5, 0.5): vx = 2.
    //   b: vy = 24 - 24 (1 + max(0.5, 0)) = -12; friction min(0, 0.5) = 0.
    // Step 4: a falls 2 (vy 8) back to 13.5, is pushed to 11.5, vy 0; x 3 + 2/4, vx 1.
    //   b rises: vy -4, y 10.5 (bottom 14.5: clear of the floor).
    // Step 5: a: x 3.75, vx 0.5.  b: vy 4, y 11.5: its bottom touches the floor's top,
    //   which is not an overlap (|dy| >= sum of half heights), so nothing changes.
    // Step 6: a: x 3.875, vx 0.25.  b: vy 12, y 14.5, pushed to 11.5, vy 12 - 18 = -6.
    // k, kinematic: x = 2n, no gravity.
    // a: {x, y, vx, vy} after steps 1 to 6; b: {y, vy} (x = 50 and vx = 0 throughout).
    const float a[6][4] = {{1, 2, 4, 8},        {2, 6, 4, 16},           {3, 11.5f, 2, 0},
                           {3.5f, 11.5f, 1, 0}, {3.75f, 11.5f, 0.5f, 0}, {3.875f, 11.5f, 0.25f, 0}};
    const float b[6][2] = {{2, 8}, {6, 16}, {11.5f, -12}, {10.5f, -4}, {11.5f, 4}, {11.5f, -6}};
    for (int n = 1; n <= 6; ++n) {
        const std::size_t i = static_cast<std::size_t>(n - 1);
        const std::string step = std::to_string(n);
        expectRow(rows[3 * i], step, "a", a[i][0], a[i][1], a[i][2], a[i][3]);
        expectRow(rows[3 * i + 1], step, "b", 50, b[i][0], 0, b[i][1]);
        expectRow(rows[3 * i + 2], step, "k", static_cast<float>(2 * n), -50, 8, 0);
    }
}

TEST_F(Cli, EveryKeepsStepsKTwoKAndSoOn) {
    const std::string scene = write("floor.json", kFloorScene);
    const Result r = run("run " + quote(scene) + " --steps 7 --trace - --every 3");
    ASSERT_EQ(r.status, 0) << r.err;
    const std::vector<Row> rows = rowsOf(r.out);
    // Steps 3 and 6 of 7; the values are those of the full trace above.
    ASSERT_EQ(rows.size(), 2u * 3u);
    expectRow(rows[0], "3", "a", 3, 11.5f, 2, 0);
    expectRow(rows[1], "3", "b", 50, 11.5f, 0, -12);
    expectRow(rows[2], "3", "k", 6, -50, 8, 0);
    expectRow(rows[3], "6", "a", 3.875f, 11.5f, 0.25f, 0);
    expectRow(rows[4], "6", "b", 50, 11.5f, 0, -6);
    expectRow(rows[5], "6", "k", 12, -50, 8, 0);
}

TEST_F(Cli, ZeroStepsIsTheHeaderAlone) {
    const std::string scene = write("floor.json", kFloorScene);
    const Result r = run("run " + quote(scene) + " --steps 0 --trace -");
    EXPECT_EQ(r.status, 0);
    EXPECT_EQ(r.out, "step,id,x,y,vx,vy\n");
}

TEST_F(Cli, TraceToAFile) {
    const std::string scene = write("free.json", kFreeScene);
    const std::string trace = path("trace.csv");
    const Result r = run("run " + quote(scene) + " -n 2 --trace " + quote(trace));
    EXPECT_EQ(r.status, 0);
    EXPECT_EQ(r.out, "");
    EXPECT_EQ(readAll(trace), "step,id,x,y,vx,vy\n1,ball,1,-2,4,-8\n2,ball,2,-4,4,-8\n");
}

TEST_F(Cli, FloatsArePrintedToReadBackExactly) {
    // 0.1f is 0.100000001490116...; nine significant digits are 0.100000001.
    const std::string scene = write("p.json", R"({"solver": "classic", "bodies": [
        {"id": "p", "x": 0.1, "y": 0, "hw": 1, "hh": 1}]})");
    const Result r = run("run " + quote(scene) + " --steps 1 --trace -");
    EXPECT_EQ(r.status, 0);
    EXPECT_EQ(r.out, "step,id,x,y,vx,vy\n1,p,0.100000001,0,0,0\n");
}

TEST_F(Cli, IdsAreQuotedForCsvWhenNeeded) {
    const std::string scene = write("ids.json", R"({"solver": "classic", "bodies": [
        {"id": "a,\"b\"", "hw": 1, "hh": 1}]})");
    const Result r = run("run " + quote(scene) + " --steps 1 --trace -");
    EXPECT_EQ(r.status, 0);
    EXPECT_EQ(r.out, "step,id,x,y,vx,vy\n1,\"a,\"\"b\"\"\",0,0,0,0\n");
}

/// The cells of the summary table's row for `id` (empty if there is none).
std::vector<std::string> summaryRow(const std::string& out, const std::string& id) {
    for (const std::string& line : lines(out)) {
        std::stringstream words(line);
        std::vector<std::string> cells;
        for (std::string word; words >> word;)
            cells.push_back(word);
        if (!cells.empty() && cells[0] == id)
            return cells;
    }
    return {};
}

TEST_F(Cli, SummaryWithoutTrace) {
    const std::string scene = write("free.json", kFreeScene);
    const Result r = run("run " + quote(scene) + " --steps 4");
    EXPECT_EQ(r.status, 0);
    EXPECT_EQ(r.err, "");
    EXPECT_THAT(r.out, HasSubstr(scene));
    EXPECT_THAT(r.out, HasSubstr("classic"));
    EXPECT_THAT(r.out, HasSubstr("1 dynamic"));
    EXPECT_THAT(r.out, HasSubstr("1 s simulated")); // 4 steps of 1/4 s
    // The table row of the ball: after 4 steps x = 4, y = -8, velocity unchanged.
    EXPECT_EQ(summaryRow(r.out, "ball"), (std::vector<std::string>{"ball", "4", "-8", "4", "-8"}))
        << r.out;
}

// Bodies piled at one spot beyond the contact budget: the run goes on, its output whole,
// and a warning says how much was left out; a sane scene says nothing.
TEST_F(Cli, APileBeyondTheContactBudgetIsReported) {
    std::string bodies = R"({"type": "static", "x": 0, "y": 1, "hw": 100, "hh": 1})";
    for (int i = 0; i < 20; ++i)
        bodies += R"(, {"x": 0, "y": -0.5, "hw": 0.5, "hh": 0.5})";
    const std::string scene = write(
        "pile.json", R"({"gravity": [0, 10], "physical": {"maxContactsPerBody": 4}, "bodies": [)" +
                         bodies + "]}");
    const Result r = run("run " + quote(scene) + " --steps 2");
    EXPECT_EQ(r.status, 0);
    EXPECT_THAT(r.out, HasSubstr("20 dynamic"));
    // 190 pairs among the boxes, at most 20 * 4 / 2 = 40 of them kept in a step.
    EXPECT_THAT(r.err, StartsWith("jostle: warning: " + scene +
                                  ": bodies piled on each other beyond the contact budget"));
    EXPECT_THAT(r.err, HasSubstr("in 2 steps"));
    EXPECT_EQ(run("run " + quote(write("floor.json", kFloorScene)) + " --steps 60").err, "");
}

// The summary is for people: its numbers have five significant digits at the scene's
// size (the largest |coordinate| of its boxes), so float noise next to that scale reads
// as 0, never as -1.4013e-45, 1.17e-19 or "-0". The trace keeps every float exact.
TEST_F(Cli, SummaryRoundsFloatNoiseToZero) {
    // The static edge reaches x = ±100: a scene of size 100, printed to 2 decimals. No
    // gravity, nothing touches: each body moves by its velocity, 4 steps of 1/4 s.
    const std::string noisy = write("noisy.json", R"({"solver": "classic", "dt": 0.25,
      "bodies": [
        {"id": "edge", "type": "static", "x": 0, "y": 95, "hw": 100, "hh": 5},
        {"id": "rest", "x": 10, "y": 0, "hw": 1, "hh": 1, "vx": -1.4e-45, "vy": 1.17e-19},
        {"id": "slow", "x": -20, "y": 0, "hw": 1, "hh": 1, "vx": 0.25, "vy": -0.001}]})");
    const Result r = run("run " + quote(noisy) + " --steps 4");
    ASSERT_EQ(r.status, 0) << r.err;
    // rest: x = 10 + 4 × (-1.4e-45 / 4) = 10 in float; y = 1.17e-19; both velocities noise.
    EXPECT_EQ(summaryRow(r.out, "rest"), (std::vector<std::string>{"rest", "10", "0", "0", "0"}))
        << r.out;
    // slow: x = -20 + 0.25 = -19.75; y = -0.001 and vy = -0.001, below 0.005: 0, not -0.
    EXPECT_EQ(summaryRow(r.out, "slow"),
              (std::vector<std::string>{"slow", "-19.75", "0", "0.25", "0"}))
        << r.out;

    // The trace still has the exact floats.
    const Result trace = run("run " + quote(noisy) + " --steps 4 --every 4 --trace -");
    ASSERT_EQ(trace.status, 0) << trace.err;
    const std::vector<Row> rows = rowsOf(trace.out);
    ASSERT_EQ(rows.size(), 2u);
    EXPECT_EQ(rows[0].id, "rest");
    EXPECT_EQ(rows[0].vx, -1.4e-45f);
    EXPECT_EQ(rows[0].vy, 1.17e-19f);
    EXPECT_NE(rows[0].y, 0.0f);
    EXPECT_EQ(rows[1].vy, -0.001f);

    // A scene of size 1 (a body from -1 to 1) is printed to 4 decimals: the same kind of
    // small speed is now of its scale, and shows.
    const std::string small = write("small.json", R"({"solver": "classic", "dt": 0.25,
      "bodies": [{"id": "ball", "x": 0, "y": 0, "hw": 1, "hh": 1, "vx": 0.0012,
                  "vy": -0.00004}]})");
    const Result s = run("run " + quote(small) + " --steps 4");
    ASSERT_EQ(s.status, 0) << s.err;
    // x = 4 × 0.0012 / 4 = 0.0012; y = -0.00004, below 0.00005: 0.
    EXPECT_EQ(summaryRow(s.out, "ball"),
              (std::vector<std::string>{"ball", "0.0012", "0", "0.0012", "0"}))
        << s.out;
}

TEST_F(Cli, TheTutorialExampleRuns) {
    const Result r =
        run(std::string("run ") + quote(JOSTLE_SCENES_DIR "/tutorial.json") + " --steps 120");
    EXPECT_EQ(r.status, 0);
    EXPECT_EQ(r.err, "");
    EXPECT_THAT(r.out, HasSubstr("classic"));
}

// --solver runs a scene in the other model: one file shows both (the README's picture is
// tutorial.json in the physical model).
TEST_F(Cli, SolverChoosesTheModelInsteadOfTheScenes) {
    const std::string scene = quote(write("floor.json", kFloorScene));
    const Result classic = run("run " + scene + " --steps 8 --trace -");
    const Result asClassic = run("run " + scene + " --steps 8 --trace - --solver classic");
    const Result asPhysical = run("run " + scene + " --steps 8 --trace - --solver physical");
    ASSERT_EQ(asPhysical.status, 0) << asPhysical.err;
    EXPECT_EQ(asClassic.out, classic.out); // the scene's own model, named
    EXPECT_NE(asPhysical.out, classic.out);

    const Result summary = run("run " + scene + " --steps 1 --solver physical");
    EXPECT_THAT(summary.out, HasSubstr("solver     physical"));
}

// Determinism as a user sees it: two processes, the same scene, the same trace, byte for
// byte (every float printed to read back exactly: FloatsArePrintedToReadBackExactly).
TEST_F(Cli, TheTraceIsTheSameRunAfterRun) {
    for (const std::string scene : {"tutorial.json", "pyramid.json"}) {
        const std::string command = "run " + quote(JOSTLE_SCENES_DIR "/" + scene) +
                                    " --steps 600 --trace - --solver physical";
        const Result first = run(command);
        const Result second = run(command);
        ASSERT_EQ(first.status, 0) << first.err;
        EXPECT_GT(first.out.size(), 10000u); // a real trace, not an empty one
        EXPECT_TRUE(first.out == second.out) << scene;
    }
}

TEST_F(Cli, TileMapsAreTakenIntoTheWorld) {
    const std::string scene = write("tiles.json", R"({"gravity": [0, 800],
        "tilemap": {"x": 0, "y": 100, "tile": 16, "rows": ["....", "####"]},
        "bodies": [{"id": "box", "x": 32, "y": 0, "hw": 8, "hh": 8}]})");
    const Result r = run("run " + quote(scene) + " --steps 120 --every 120 --trace -");
    EXPECT_EQ(r.status, 0);
    EXPECT_EQ(r.err, "");
    const std::vector<Row> rows = rowsOf(r.out);
    ASSERT_EQ(rows.size(), 1u);
    // Resting on the map's floor, whose top is at y = 116, within the slop (0.01 × 8).
    EXPECT_EQ(rows[0].id, "box");
    EXPECT_NEAR(rows[0].y, 116.0f - 8.0f, 0.08f);
}

// --- Progress: on a terminal only ------------------------------------------------------

// The tests' standard error is a file: no progress in it, however long the run.
TEST_F(Cli, NoProgressWhenStandardErrorIsNotATerminal) {
    const std::string scene = quote(write("floor.json", kFloorScene));
    const Result summary = run("run " + scene + " --steps 3000");
    EXPECT_EQ(summary.status, 0);
    EXPECT_EQ(summary.err, "");
    const Result trace = run("run " + scene + " --steps 3000 --every 1000 --trace -");
    EXPECT_EQ(trace.status, 0);
    EXPECT_EQ(trace.err, "");
    EXPECT_EQ(rowsOf(trace.out).size(), 3u * 3u);
}

/// True if what the terminal received is progress lines of `label` for `total` steps and
/// their erasing, nothing else.
bool onlyProgress(const std::string& received, const std::string& label, int total) {
    const std::regex line(label + R"(: step \d+ of )" + std::to_string(total) + R"( \(\d+%\)| *)");
    for (const std::string& piece : split(received, '\r'))
        if (!std::regex_match(piece, line))
            return false;
    return true;
}

// With standard error on a terminal: "jostle run: step 0 of 50 (0%)" at once, redrawn in
// place (the line's start, "\r") a few times a second, erased at the end. Standard
// output, a file here, has the summary or the trace as ever.
TEST_F(Cli, ProgressOnATerminal) {
    JOSTLE_SKIP_WITHOUT_A_TERMINAL();
    const std::string scene = quote(write("floor.json", kFloorScene));
    const Result summary = runOnTerminal("run " + scene + " --steps 50");
    EXPECT_EQ(summary.status, 0);
    EXPECT_THAT(summary.err, StartsWith("\rjostle run: step 0 of 50 (0%)"));
    EXPECT_TRUE(onlyProgress(summary.err, "jostle run", 50)) << summary.err;
    EXPECT_EQ(jostle::testing::lastLineShown(summary.err), "");
    EXPECT_THAT(summary.out, HasSubstr("steps      50 of 0.25 s"));
    EXPECT_THAT(summary.out, Not(HasSubstr("jostle run")));

    const Result trace = runOnTerminal("run " + scene + " --steps 50 --trace -");
    EXPECT_EQ(trace.status, 0);
    EXPECT_THAT(trace.err, StartsWith("\rjostle run: step 0 of 50 (0%)"));
    EXPECT_EQ(jostle::testing::lastLineShown(trace.err), "");
    EXPECT_EQ(trace.out, run("run " + scene + " --steps 50 --trace -").out);
}

// A trace to the terminal the progress would be drawn on: no progress, to keep its lines.
TEST_F(Cli, NoProgressOverATraceOnTheSameTerminal) {
    JOSTLE_SKIP_WITHOUT_A_TERMINAL();
    const std::string scene = quote(write("free.json", kFreeScene));
    const Result r = runOnTerminal("run " + scene + " --steps 2 --trace -", true);
    EXPECT_EQ(r.status, 0);
    EXPECT_EQ(r.err, "step,id,x,y,vx,vy\r\n1,ball,1,-2,4,-8\r\n2,ball,2,-4,4,-8\r\n");
}

// --- Bad input: exit status 2 and a message naming the place -----------------------

TEST_F(Cli, BadSceneNamesFileAndPlace) {
    const std::string scene = write("bad.json", R"({"bodies": [{"hw": 1, "hh": 1},
        {"hw": 0, "hh": 1}]})");
    const Result r = run("run " + quote(scene) + " --steps 1 --trace -");
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(r.err, "jostle: error: " + scene + ": bodies[1].hw: must be > 0\n");
    EXPECT_EQ(r.out, ""); // not even the header
}

// The classic model has sharp boxes only: a file that asks for it with a rounded body, a
// ramp or a segment, or such a file run with --solver classic, is bad input.
TEST_F(Cli, TheClassicModelRefusesShapes) {
    const std::string refused = R"(the classic model has sharp boxes only (solver "classic"))";
    const std::string classic = write("classic.json", R"({"solver": "classic", "bodies": [
        {"hw": 1, "hh": 1}, {"type": "static", "hw": 4, "hh": 2, "slope": [-1, -1]}]})");
    const Result r = run("run " + quote(classic) + " --steps 1 --trace -");
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(r.err, "jostle: error: " + classic + ": bodies[1].slope: " + refused + "\n");
    EXPECT_EQ(r.out, "");

    const std::string physical = write("physical.json", R"({"bodies": [
        {"id": "ball", "hw": 1, "hh": 1, "radius": 1}]})");
    EXPECT_EQ(run("run " + quote(physical) + " --steps 1").status, 0);
    const Result asClassic = run("run " + quote(physical) + " --steps 1 --solver classic");
    EXPECT_EQ(asClassic.status, 2);
    EXPECT_EQ(asClassic.err,
              "jostle: error: " + physical + ": addBodies: bodies[0].radius: " + refused + "\n");
    const Result render = run("render " + quote(physical) + " --out " + quote(path("ball.png")) +
                              " --solver classic");
    EXPECT_EQ(render.status, 2);
    EXPECT_THAT(render.err, HasSubstr(refused));
}

// Ramp tiles too: a classic file with one, or a file with one run with --solver classic.
TEST_F(Cli, TheClassicModelRefusesRampTiles) {
    const std::string refused = R"(the classic model has sharp boxes only (solver "classic"))";
    const std::string classic = write("classic.json", R"({"solver": "classic", "bodies": [],
        "tilemap": {"tile": 16, "rows": ["....", "..F.", "####"]}})");
    const Result r = run("run " + quote(classic) + " --steps 1 --trace -");
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(r.err, "jostle: error: " + classic + ": tilemap.rows[1][2]: " + refused + "\n");
    EXPECT_EQ(r.out, "");

    const std::string physical = write("physical.json", R"({"bodies": [],
        "tilemaps": [{"tile": 16, "rows": ["##"]}, {"tile": 16, "rows": ["..", "\\#"]}]})");
    EXPECT_EQ(run("run " + quote(physical) + " --steps 1").status, 0);
    const Result asClassic = run("run " + quote(physical) + " --steps 1 --solver classic");
    EXPECT_EQ(asClassic.status, 2);
    EXPECT_EQ(asClassic.err, "jostle: error: " + physical +
                                 ": addTileMaps: tileMaps[1].rows[1][0]: " + refused + "\n");
    EXPECT_EQ(asClassic.out, "");
    const Result render = run("render " + quote(physical) + " --out " + quote(path("ramp.png")) +
                              " --solver classic");
    EXPECT_EQ(render.status, 2);
    EXPECT_THAT(render.err, HasSubstr("tileMaps[1].rows[1][0]: " + refused));
}

TEST_F(Cli, BadTileMapNamesFileAndPlace) {
    const std::string scene = write("bad.json", R"({"bodies": [],
        "tilemap": {"tile": 16, "rows": ["....", "####", "##.#.x"]}})");
    const Result r = run("run " + quote(scene) + " --steps 1");
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(r.err, "jostle: error: " + scene +
                         ": tilemap.rows[2][5]: expected '#', '.' or a ramp, got 'x'\n");
    EXPECT_EQ(r.out, "");
}

TEST_F(Cli, InvalidJsonNamesFileAndLine) {
    const std::string scene = write("bad.json", "{\"bodies\": [\n}");
    const Result r = run("run " + quote(scene) + " --steps 1");
    EXPECT_EQ(r.status, 2);
    EXPECT_THAT(r.err, StartsWith("jostle: error: " + scene + ": invalid JSON at line 2"));
}

TEST_F(Cli, MissingFile) {
    const std::string scene = path("missing.json");
    const Result r = run("run " + quote(scene) + " --steps 1");
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(r.err, "jostle: error: " + scene + ": cannot read: No such file or directory\n");
}

TEST_F(Cli, ASceneCanComeThroughAPipe) {
    const Result r = runPiped(std::string("printf '%s' '") + kFreeScene + "'",
                              "run /dev/stdin --steps 3 --trace -");
    EXPECT_EQ(r.status, 0);
    EXPECT_EQ(r.out, "step,id,x,y,vx,vy\n1,ball,1,-2,4,-8\n2,ball,2,-4,4,-8\n3,ball,3,-6,4,-8\n");
}

TEST_F(Cli, AnUnknownFieldIsRefusedBeforeItsValueIsRead) {
    // 60 MB of value: the refusal comes at the field's name, and the rest is never read.
    const Result r =
        runPiped(R"(printf '{"bodies": [], "colour": ['; yes '[],' | head -c 60000000)",
                 "run /dev/stdin --steps 1");
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(r.err, "jostle: error: /dev/stdin: unknown field \"colour\"\n");
}

TEST_F(Cli, EndlessDevicesAreRefusedAtTheirFirstBytes) {
    const Result zero = run("run /dev/zero --steps 1");
    EXPECT_EQ(zero.status, 2);
    EXPECT_EQ(zero.err, "jostle: error: /dev/zero: invalid JSON at line 1, column 1: unexpected "
                        "NUL byte (0x00)\n");
    const Result random = run("run /dev/urandom --steps 1");
    EXPECT_EQ(random.status, 2);
    EXPECT_THAT(random.err, StartsWith("jostle: error: /dev/urandom: "));
    EXPECT_EQ(random.err.find('\n'), random.err.size() - 1); // one line
}

TEST_F(Cli, TraceFileThatCannotBeCreated) {
    const std::string scene = write("free.json", kFreeScene);
    const std::string trace = path("no/such/dir/trace.csv");
    const Result r = run("run " + quote(scene) + " --steps 1 --trace " + quote(trace));
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(r.err, "jostle: error: " + trace + ": cannot write: No such file or directory\n");
}

// --- Output that cannot be written: exit status 1 and a message saying why -------------

// /dev/full refuses every write with ENOSPC; a closed descriptor with EBADF. A summary
// is written at the end; a trace of 2,000 steps fills stdio's buffer many times, and the
// run ends at the first write that fails; one of 3 steps is written when it is flushed.
TEST_F(Cli, OutputThatCannotBeWritten) {
    const std::string scene = quote(write("floor.json", kFloorScene));
    struct Case {
        std::string args;
        std::string redirection;
        std::string message;
    };
    const std::string summary = "cannot write the summary to standard output: ";
    const std::string trace = "cannot write the trace to standard output: ";
    const std::vector<Case> cases = {
        {"--steps 1", ">/dev/full", summary + "No space left on device"},
        {"--steps 1", ">&-", summary + "Bad file descriptor"},
        {"--steps 2000 --trace -", ">/dev/full", trace + "No space left on device"},
        {"--steps 3 --trace -", ">/dev/full", trace + "No space left on device"},
        {"--steps 3 --trace -", ">&-", trace + "Bad file descriptor"},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.args + " " + c.redirection);
        const Result r = run("run " + scene + " " + c.args, c.redirection);
        EXPECT_EQ(r.status, 1);
        EXPECT_EQ(r.err, "jostle: error: " + c.message + "\n");
    }

    // A trace file on a full disk: a name for /dev/full.
    const std::string traceFile = path("trace.csv");
    std::filesystem::create_symlink("/dev/full", traceFile);
    const Result file = run("run " + scene + " --steps 3 --trace " + quote(traceFile));
    EXPECT_EQ(file.status, 1);
    EXPECT_EQ(file.err,
              "jostle: error: " + traceFile + ": write failed: No space left on device\n");
    EXPECT_EQ(file.out, "");
}

// A closed standard output is not taken by the files the program opens.
TEST_F(Cli, TraceFileWithStandardOutputClosed) {
    const std::string scene = write("free.json", kFreeScene);
    const std::string trace = path("trace.csv");
    const Result r = run("run " + quote(scene) + " -n 2 --trace " + quote(trace), ">&-");
    EXPECT_EQ(r.status, 0);
    EXPECT_EQ(r.err, "");
    EXPECT_EQ(readAll(trace), "step,id,x,y,vx,vy\n1,ball,1,-2,4,-8\n2,ball,2,-4,4,-8\n");
}

TEST_F(Cli, BadOptions) {
    const std::string scene = quote(write("free.json", kFreeScene));
    for (const std::string& args : {
             "run " + scene + " --steps -1",                    // steps >= 0
             "run " + scene + " --steps 2.5",                   // a whole number
             "run " + scene + " --steps 1 --trace - --every 0", // every >= 1
             "run " + scene + " --steps 1 --every 2",           // every needs a trace
             "run " + scene,                                    // steps is required
             std::string("run --steps 1"),                      // so is the scene
             "run " + scene + " --steps 1 --colour",            // no such option
             "run " + scene + " --steps 1 --solver newton",     // no such model
             std::string(""),                                   // no command
             std::string("fly"),                                // no such command
         }) {
        SCOPED_TRACE(args);
        const Result r = run(args);
        EXPECT_EQ(r.status, 2);
        EXPECT_THAT(r.err, StartsWith("jostle: error: "));
        EXPECT_EQ(r.out, "");
    }
}

// Without a command CLI11 would say "A subcommand is required" whatever was typed: the
// program names what it did not know, and the commands it has.
TEST_F(Cli, AnUnknownCommandIsNamed) {
    const std::string usage = "Run 'jostle --help' for usage.\n";
    const Result walk = run("walk --steps 1");
    EXPECT_EQ(walk.status, 2);
    EXPECT_EQ(walk.err, "jostle: error: unknown command 'walk' (commands: run, render, synctest)\n" + usage);
    const Result option = run("--colour run");
    EXPECT_EQ(option.status, 2);
    EXPECT_EQ(option.err,
              "jostle: error: unknown option '--colour' (commands: run, render, synctest)\n" + usage);
    const Result none = run("");
    EXPECT_EQ(none.status, 2);
    EXPECT_EQ(none.err, "jostle: error: a command is required (commands: run, render, synctest)\n" + usage);
    EXPECT_EQ(none.out, "");
}

TEST_F(Cli, Help) {
    const Result top = run("--help");
    EXPECT_EQ(top.status, 0);
    EXPECT_THAT(top.out, HasSubstr("run"));

    const Result sub = run("run --help");
    EXPECT_EQ(sub.status, 0);
    EXPECT_THAT(sub.out, HasSubstr("--steps"));
    EXPECT_THAT(sub.out, HasSubstr("--trace"));
    EXPECT_THAT(sub.out, HasSubstr("--every"));
    EXPECT_THAT(sub.out, HasSubstr("--solver"));
}

} // namespace
