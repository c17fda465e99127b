// Scene files: every field read as written (every property of src/body_properties.hpp
// among them), every default, and every error with its place, as docs/scene-format.md
// promises.
#include "../growth.hpp"
#include "../property_samples.hpp"
#include "jostle/scene.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <string>
#include <unistd.h>
#include <variant>

namespace jostle {
namespace {

using test_support::sampleNeeds;
using test_support::sampleOf;
using test_support::valueOf;
using ::testing::HasSubstr;
using ::testing::Not;
using ::testing::StartsWith;

/// The message of the SceneError that parsing `json` throws ("" if it throws none).
std::string errorOf(const std::string& json) {
    try {
        parseScene(json);
    } catch (const SceneError& error) {
        return error.what();
    }
    return "";
}

/// A scene whose bodies array is `bodies`, everything else left to its default.
std::string withBodies(const std::string& bodies) {
    return R"({"bodies": [)" + bodies + "]}";
}

/// A scene with one top-level field besides an empty bodies array.
std::string withTop(const std::string& field) {
    return R"({"bodies": [], )" + field + "}";
}

constexpr const char* kBox = R"({"hw": 1, "hh": 1})";

// --- Valid scenes ----------------------------------------------------------------------

TEST(SceneParse, EveryFieldIsReadAsWritten) {
    const Scene scene = parseScene(R"({
        "gravity": [1.5, -800], "maxVelocity": 1000, "dt": 0.01, "solver": "classic",
        "classic": {"mass": true, "coulomb": true, "ccd": true}, "sleeping": false,
        "physical": {"velocityIterations": 4, "positionIterations": 0, "slop": 0.125,
                     "correction": 0.5, "restitutionThreshold": 2, "frictionMix": "geometricMean",
                     "maxContactsPerBody": 9},
        "bodies": [
          {"id": "floor", "type": "static", "x": -3, "y": 300, "hw": 400, "hh": 10,
           "bounce": 0, "friction": 0.25},
          {"id": "lift", "type": "kinematic", "x": 1, "y": 2, "hw": 3, "hh": 4, "vx": 5,
           "vy": 6, "density": 3},
          {"id": "crate", "type": "dynamic", "x": 0.1, "y": -2.5, "hw": 10, "hh": 12,
           "vx": 40, "vy": -7, "bounce": 0.3, "friction": 0.75, "mass": 2,
           "gravityScale": -1, "damping": 0.5, "bullet": true}
        ]})");

    EXPECT_EQ(scene.world.gravity, (Vec2{1.5f, -800.0f}));
    EXPECT_EQ(scene.world.maxVelocity, 1000.0f);
    EXPECT_EQ(scene.dt, 0.01f);
    EXPECT_EQ(scene.world.solver, Solver::Classic);
    EXPECT_TRUE(scene.world.classic.mass);
    EXPECT_TRUE(scene.world.classic.coulomb);
    EXPECT_TRUE(scene.world.classic.ccd);
    EXPECT_FALSE(scene.world.sleeping);
    EXPECT_EQ(scene.world.physical.velocityIterations, 4);
    EXPECT_EQ(scene.world.physical.positionIterations, 0);
    EXPECT_EQ(scene.world.physical.slop, 0.125f);
    EXPECT_EQ(scene.world.physical.correction, 0.5f);
    EXPECT_EQ(scene.world.physical.restitutionThreshold, 2.0f);
    EXPECT_EQ(scene.world.physical.frictionMix, FrictionMix::GeometricMean);
    EXPECT_EQ(scene.world.physical.maxContactsPerBody, 9);

    ASSERT_EQ(scene.bodies.size(), 3u);
    const SceneBody& floor = scene.bodies[0];
    EXPECT_EQ(floor.id, "floor");
    EXPECT_EQ(floor.def.type, BodyType::Static);
    EXPECT_EQ(floor.def.x, -3.0f);
    EXPECT_EQ(floor.def.y, 300.0f);
    EXPECT_EQ(floor.def.hw, 400.0f);
    EXPECT_EQ(floor.def.hh, 10.0f);
    EXPECT_EQ(floor.def.bounce, 0.0f);
    EXPECT_EQ(floor.def.friction, 0.25f);

    const SceneBody& lift = scene.bodies[1];
    EXPECT_EQ(lift.id, "lift");
    EXPECT_EQ(lift.def.type, BodyType::Kinematic);
    EXPECT_EQ(lift.def.vx, 5.0f);
    EXPECT_EQ(lift.def.vy, 6.0f);
    EXPECT_EQ(lift.def.density, 3.0f);
    EXPECT_EQ(lift.def.mass, 0.0f); // no "mass": from density

    const SceneBody& crate = scene.bodies[2];
    EXPECT_EQ(crate.id, "crate");
    EXPECT_EQ(crate.def.type, BodyType::Dynamic);
    EXPECT_EQ(crate.def.x, 0.1f); // the float nearest to 0.1, as a C++ literal gives
    EXPECT_EQ(crate.def.y, -2.5f);
    EXPECT_EQ(crate.def.hw, 10.0f);
    EXPECT_EQ(crate.def.hh, 12.0f);
    EXPECT_EQ(crate.def.vx, 40.0f);
    EXPECT_EQ(crate.def.vy, -7.0f);
    EXPECT_EQ(crate.def.bounce, 0.3f);
    EXPECT_EQ(crate.def.friction, 0.75f);
    EXPECT_EQ(crate.def.mass, 2.0f);
    EXPECT_EQ(crate.def.gravityScale, -1.0f);
    EXPECT_EQ(crate.def.damping, 0.5f);
    EXPECT_TRUE(crate.def.bullet);
    EXPECT_FALSE(floor.def.bullet);
    EXPECT_EQ(crate.def.userData, nullptr);
}

TEST(SceneParse, ShapesAreReadAsWritten) {
    const Scene scene = parseScene(R"({"bodies": [
        {"id": "ball", "hw": 2, "hh": 2, "radius": 2},
        {"id": "capsule", "hw": 1, "hh": 3, "radius": 1},
        {"id": "ramp", "type": "static", "hw": 8, "hh": 4, "slope": [-1, -1]},
        {"id": "face", "type": "kinematic", "hw": 8, "hh": 4, "slope": [1, -1], "segment": true},
        {"id": "box", "hw": 1, "hh": 1}]})");
    ASSERT_EQ(scene.bodies.size(), 5u);
    EXPECT_EQ(scene.bodies[0].def.radius, 2.0f);
    EXPECT_EQ(scene.bodies[1].def.radius, 1.0f);
    EXPECT_EQ(scene.bodies[2].def.slope, (Vec2{-1.0f, -1.0f}));
    EXPECT_FALSE(scene.bodies[2].def.segment);
    EXPECT_EQ(scene.bodies[3].def.slope, (Vec2{1.0f, -1.0f}));
    EXPECT_TRUE(scene.bodies[3].def.segment);
    const BodyDef& box = scene.bodies[4].def; // the defaults: a sharp box
    EXPECT_EQ(box.radius, 0.0f);
    EXPECT_EQ(box.slope, Vec2{});
    EXPECT_FALSE(box.segment);
}

TEST(SceneParse, DefaultsAreThoseOfTheFormat) {
    const Scene scene = parseScene(withBodies(R"({"hw": 2, "hh": 3})"));
    EXPECT_EQ(scene.world.gravity, (Vec2{0.0f, 0.0f}));
    EXPECT_EQ(scene.world.maxVelocity, std::numeric_limits<float>::infinity());
    EXPECT_EQ(scene.dt, 1.0f / 60.0f);
    EXPECT_EQ(scene.world.solver, Solver::Physical);
    EXPECT_FALSE(scene.world.classic.mass);
    EXPECT_FALSE(scene.world.classic.coulomb);

    ASSERT_EQ(scene.bodies.size(), 1u);
    const SceneBody& body = scene.bodies[0];
    EXPECT_EQ(body.id, "0");
    EXPECT_EQ(body.def.type, BodyType::Dynamic);
    EXPECT_EQ(body.def.x, 0.0f);
    EXPECT_EQ(body.def.y, 0.0f);
    EXPECT_EQ(body.def.hw, 2.0f);
    EXPECT_EQ(body.def.hh, 3.0f);
    EXPECT_EQ(body.def.vx, 0.0f);
    EXPECT_EQ(body.def.vy, 0.0f);
    EXPECT_EQ(body.def.bounce, 0.0f);
    EXPECT_EQ(body.def.friction, 0.5f);
    EXPECT_EQ(body.def.mass, 0.0f);
    EXPECT_EQ(body.def.density, 1.0f);
    EXPECT_EQ(body.def.gravityScale, 1.0f);
    EXPECT_EQ(body.def.damping, 0.0f);
}

TEST(SceneParse, PartialOptionObjectsKeepTheOtherDefaults) {
    const Scene scene =
        parseScene(withTop(R"("classic": {"coulomb": true}, "physical": {"frictionMix": "min"})"));
    EXPECT_FALSE(scene.world.classic.mass);
    EXPECT_TRUE(scene.world.classic.coulomb);
    EXPECT_EQ(scene.world.physical.velocityIterations, PhysicalOptions{}.velocityIterations);
    EXPECT_EQ(scene.world.physical.frictionMix, FrictionMix::Min);
}

TEST(SceneParse, EmptyBodiesIsAScene) {
    EXPECT_TRUE(parseScene(R"({"bodies": []})").bodies.empty());
}

TEST(SceneParse, IdsDefaultToTheIndex) {
    const Scene scene =
        parseScene(withBodies(std::string(kBox) + R"(, {"id": "b", "hw": 1, "hh": 1}, )" + kBox));
    ASSERT_EQ(scene.bodies.size(), 3u);
    EXPECT_EQ(scene.bodies[0].id, "0");
    EXPECT_EQ(scene.bodies[1].id, "b");
    EXPECT_EQ(scene.bodies[2].id, "2");
}

TEST(SceneParse, IntegersAndTheRangeLimitsAreNumbers) {
    // The ends of the range of math.hpp read back exactly; 999999999 is an integer that
    // is not a float: it reads as the nearest one, 1e9.
    const Scene scene = parseScene(
        withBodies(R"({"hw": 1e-9, "hh": 1, "x": 1e9, "y": -1e9, "vx": -7, "vy": 999999999})"));
    EXPECT_EQ(scene.bodies[0].def.hw, 1e-9f);
    EXPECT_EQ(scene.bodies[0].def.x, 1e9f);
    EXPECT_EQ(scene.bodies[0].def.y, -1e9f);
    EXPECT_EQ(scene.bodies[0].def.vx, -7.0f);
    EXPECT_EQ(scene.bodies[0].def.vy, 1e9f);
}

TEST(SceneParse, ByteOrderMarkAndWhitespaceAreFine) {
    EXPECT_EQ(parseScene("\xEF\xBB\xBF \n\t{\"bodies\": []}\n").bodies.size(), 0u);
}

// --- Errors: syntax --------------------------------------------------------------------

TEST(SceneErrors, InvalidJsonNamesLineAndColumn) {
    // Line 2 is `  x}`: the x, in column 3, is not JSON.
    EXPECT_THAT(errorOf("{\"bodies\": [],\n  x}"), StartsWith("invalid JSON at line 2, column 3:"));
    EXPECT_THAT(errorOf(""), StartsWith("invalid JSON at line 1, column 1:"));
    // Trailing text: the x after the closing brace is the 15th character.
    EXPECT_THAT(errorOf(R"({"bodies": []}x)"), StartsWith("invalid JSON at line 1, column 15:"));
    // The end of the input counts as one more character (the empty text ends in column 1).
    EXPECT_THAT(errorOf(R"({"bodies": [)"), StartsWith("invalid JSON at line 1, column 13:"));
}

TEST(SceneErrors, NothingButWhitespaceFollowsTheValue) {
    for (int byte = 0; byte < 256; ++byte) {
        const char c = static_cast<char>(byte);
        if (c == ' ' || c == '\t' || c == '\n' || c == '\r')
            continue;
        SCOPED_TRACE(byte);
        EXPECT_THAT(errorOf(R"({"bodies": []})" + std::string(1, c) + R"({"gravty": 1, garbage)"),
                    StartsWith("invalid JSON at line 1, column 1"));
    }
}

TEST(SceneErrors, NulBytesAreErrorsWhereverTheyAre) {
    // The parser stops at a NUL as at the end of the text; what follows must not be lost.
    using namespace std::string_literals;
    EXPECT_EQ(errorOf("{\"bodies\": []}\0{\"gravty\": 1, garbage"s),
              "invalid JSON at line 1, column 15: unexpected NUL byte (0x00); expected end of "
              "input");
    EXPECT_EQ(
        errorOf("{\"bodies\": []}\n  \0"s),
        "invalid JSON at line 2, column 3: unexpected NUL byte (0x00); expected end of input");
    EXPECT_EQ(errorOf("{\"bodies\":\0[]}"s),
              "invalid JSON at line 1, column 11: unexpected NUL byte (0x00)");
    EXPECT_EQ(errorOf("{\"bodies\": [], \"a\0\": 1}"s),
              "invalid JSON at line 1, column 18: unexpected NUL byte (0x00)");
    EXPECT_EQ(errorOf("{\"bodies\": [1\0]}"s), "bodies[0]: expected an object, got number");
    EXPECT_EQ(errorOf("\0"s), "invalid JSON at line 1, column 1: unexpected NUL byte (0x00)");
}

TEST(SceneErrors, CommentsAreNotJson) {
    // `{"bodies": [] // none`: the first slash is character 15.
    EXPECT_THAT(errorOf("{\"bodies\": [] // none\n}"),
                StartsWith("invalid JSON at line 1, column 15:"));
    EXPECT_THAT(errorOf("/* scene */ {\"bodies\": []}"), StartsWith("invalid JSON at line 1"));
}

TEST(SceneErrors, DuplicateFieldsAreRefused) {
    EXPECT_EQ(errorOf(withBodies(R"({"hw": 1, "hh": 1, "hw": 2})")),
              R"(bodies[0]: duplicate field "hw")");
    EXPECT_EQ(errorOf(R"({"bodies": [], "bodies": []})"), R"(duplicate field "bodies")");
    EXPECT_EQ(errorOf(withTop(R"("classic": {"mass": true, "mass": false})")),
              R"(classic: duplicate field "mass")");
}

TEST(SceneErrors, DeepNestingIsRefusedWithoutACrash) {
    // The top object and "bodies" are two levels; 31 arrays inside reach depth 33.
    std::string nested = R"({"bodies": )" + std::string(32, '[') + std::string(32, ']') + "}";
    std::string place = "bodies";
    for (int i = 0; i < 31; ++i)
        place += "[0]";
    EXPECT_EQ(errorOf(nested), place + ": nested deeper than 32 levels");

    // A million levels: refused long before memory or the stack run out.
    EXPECT_THAT(errorOf(std::string(1'000'000, '[') + std::string(1'000'000, ']')),
                HasSubstr("nested deeper than"));
    EXPECT_THAT(errorOf(std::string(1'000'000, '{')), HasSubstr("invalid JSON"));
}

TEST(SceneErrors, UnknownFieldsAreRefusedAtTheirName) {
    // Nothing after the name is read, neither the value nor the rest of the file: a long
    // value costs nothing before the refusal.
    EXPECT_EQ(errorOf(R"({"bodies": [], "colour": [1, 2, )"), R"(unknown field "colour")");
    EXPECT_EQ(errorOf(R"({"bodies": [{"hw": 1, "colour": {"r": )"),
              R"(bodies[0]: unknown field "colour")");
    EXPECT_EQ(errorOf(R"({"bodies": [], "classic": {"masses": x)"),
              R"(classic: unknown field "masses" (did you mean "mass"?))");
    EXPECT_EQ(errorOf(R"({"bodies": [], "physical": {"iterations": [)"),
              R"(physical: unknown field "iterations")");
    EXPECT_EQ(errorOf(R"({"bodies": [], "tilemaps": [{"tile": 1, "colour": "#)"),
              R"(tilemaps[0]: unknown field "colour")");
}

TEST(SceneErrors, ProblemsAreReportedInFileOrder) {
    // The first problem met reading from the top, invalid JSON after it or not.
    EXPECT_EQ(errorOf(R"({"bodies": [{"hw": 0, "hh": 1}], x)"), "bodies[0].hw: must be > 0");
    EXPECT_EQ(errorOf(R"({"bodies": [], "gravity": {"a": 1}, x)"),
              "gravity: expected an array of 2 numbers, got object");
    // A value's own problems (its type) when it ends: invalid JSON within it comes first.
    EXPECT_THAT(errorOf(R"({"bodies": [], "gravity": {"a": [1, 2}})"),
                StartsWith("invalid JSON at line 1, column 38:"));
    // An object's problems (missing fields, checkBodyDef) when it ends.
    EXPECT_EQ(errorOf(withBodies(R"({"hw": -1, "hh": 1, "colour": 1})")),
              R"(bodies[0]: unknown field "colour")");
    EXPECT_EQ(errorOf(withBodies(R"({"hw": -1, "x": "left", "hh": 1})")),
              "bodies[0].x: expected a number, got string");
    // The file's (a missing "bodies", the model's shapes) at its end.
    EXPECT_THAT(errorOf(R"({"gravity": [0, 1]} x)"), StartsWith("invalid JSON"));
}

TEST(SceneErrors, LongValuesOfTheWrongTypeAreCountedNotKept) {
    std::string numbers = "0";
    for (int i = 1; i < 100'000; ++i)
        numbers += ", " + std::to_string(i);
    EXPECT_EQ(errorOf(withTop(R"("gravity": [)" + numbers + "]")),
              "gravity: expected an array of 2 numbers, got 100000 numbers");
    EXPECT_EQ(errorOf(withBodies(R"({"hw": 1, "hh": 1, "x": [)" + numbers + "]}")),
              "bodies[0].x: expected a number, got array");
}

TEST(SceneErrors, GarbageGivesPrintableMessages) {
    const std::string garbage = "\xff\xfe\x01garbage";
    const std::string message = errorOf(garbage);
    EXPECT_THAT(message, StartsWith("invalid JSON at line 1, column 1:"));
    EXPECT_THAT(message, HasSubstr("<0xFF>")); // the invalid byte, spelt out
    EXPECT_EQ(message.find('\xff'), std::string::npos);

    // A megabyte-long bad string token is quoted, not copied whole.
    const std::string longToken =
        R"({"bodies": [], ")" + std::string(1'000'000, 'a') + R"(\q": 1})";
    EXPECT_LT(errorOf(longToken).size(), 400u);
}

TEST(SceneErrors, MessagesShowInvisibleCharacters) {
    // One byte-order mark is skipped; a second one is named, not quoted invisibly.
    EXPECT_EQ(errorOf("\xEF\xBB\xBF\xEF\xBB\xBF{\"bodies\": []}"),
              "invalid JSON at line 1, column 4: a second byte-order mark (EF BB BF)");
    // In a name, as JSON escapes.
    EXPECT_EQ(errorOf(withTop("\"\xEF\xBB\xBFgravity\": [0, 1]")),
              R"(unknown field "\ufeffgravity")");
    EXPECT_EQ(errorOf(withTop("\"soft\xC2\xADhyphen\": 1, \"x\": 1")),
              R"(unknown field "soft\u00adhyphen")");
    EXPECT_EQ(errorOf(withTop("\"tag\xF3\xA0\x80\x81\": 1")), R"(unknown field "tag\udb40\udc01")");
    // In what the parser read last, as <U+...>.
    const std::string message = errorOf("{\"bodies\": [], \"zero\xE2\x80\x8Bwidth\x01\": 1}");
    EXPECT_THAT(message, StartsWith("invalid JSON at line 1, column 29:"));
    EXPECT_THAT(message, HasSubstr("zero<U+200B>width<U+0001>"));
}

TEST(SceneErrors, RandomMutationsGiveSceneErrorsOrScenes) {
    // Never anything but a Scene or a SceneError, whatever the bytes.
    const std::string valid = R"({"gravity": [0, 800], "dt": 0.02, "solver": "classic",
        "classic": {"mass": true}, "bodies": [{"id": "a", "hw": 1, "hh": 2, "mass": 3},
        {"type": "static", "hw": 5, "hh": 0.5, "y": 10}]})";
    std::mt19937 rng(12345);
    const std::string alphabet = "{}[]\":,.-+e0123456789 truefalsnl\\\xff";
    for (int round = 0; round < 3000; ++round) {
        std::string text = valid;
        const int edits = 1 + static_cast<int>(rng() % 4);
        for (int e = 0; e < edits; ++e) {
            const std::size_t at = rng() % text.size();
            const char c = alphabet[rng() % alphabet.size()];
            switch (rng() % 3) {
            case 0:
                text[at] = c;
                break;
            case 1:
                text.insert(at, 1, c);
                break;
            default:
                text.erase(at, 1);
                break;
            }
        }
        try {
            parseScene(text);
        } catch (const SceneError&) {
        } catch (...) {
            ADD_FAILURE() << "not a SceneError for: " << text;
        }
    }
}

// --- Scale ------------------------------------------------------------------------------

std::string sceneOfBodies(int bodies) {
    std::string text = R"({"gravity": [0, 10], "bodies": [)";
    for (int i = 0; i < bodies; ++i)
        text += (i == 0 ? "" : ",\n") + std::string(R"({"x": )") + std::to_string(i % 1000) +
                R"(, "y": )" + std::to_string(i / 1000) + R"(, "hw": 0.5, "hh": 0.5})";
    return text + "]}";
}

// Loading takes time in proportion to the file. Half a million bodies took minutes when
// each body cost as much as all those before it. Ten times the bodies take about ten times
// as long (a hundred, were it quadratic), measured in one process so that a busy machine
// cannot fail it. How long a million bodies take: jostle-bench-load (docs/benchmarks.md).
TEST(SceneScale, LoadingGrowsLinearlyWithTheBodies) {
    const std::string small = sceneOfBodies(20'000), large = sceneOfBodies(200'000);
    const double growth =
        test_support::growthOf([&] { EXPECT_EQ(parseScene(small).bodies.size(), 20'000u); },
                               [&] { EXPECT_EQ(parseScene(large).bodies.size(), 200'000u); });
    EXPECT_LT(growth, test_support::kTenTimesTheWorkAtMost) << "ten times the bodies";
    const Scene scene = parseScene(large);
    EXPECT_EQ(scene.bodies.back().id, "199999");
    EXPECT_EQ(scene.bodies.back().def.x, 999.0f);
    EXPECT_EQ(scene.bodies.back().def.y, 199.0f);
}

// --- Errors: the top level -------------------------------------------------------------

TEST(SceneErrors, TopLevel) {
    EXPECT_EQ(errorOf("[]"), "expected an object at the top level, got array");
    EXPECT_EQ(errorOf("42"), "expected an object at the top level, got number");
    EXPECT_EQ(errorOf("{}"), R"(missing field "bodies")");
    EXPECT_EQ(errorOf(R"({"gravity": [0, 1]})"), R"(missing field "bodies")");
    EXPECT_EQ(errorOf(withTop(R"("gravty": [0, 1])")),
              R"(unknown field "gravty" (did you mean "gravity"?))");
    EXPECT_EQ(errorOf(R"({"bodies": {}})"), "bodies: expected an array, got object");
    EXPECT_EQ(errorOf(R"({"bodies": null})"), "bodies: expected an array, got null");
}

TEST(SceneErrors, Gravity) {
    EXPECT_EQ(errorOf(withTop(R"("gravity": 800)")),
              "gravity: expected an array of 2 numbers, got number");
    EXPECT_EQ(errorOf(withTop(R"("gravity": [0, 800, 0])")),
              "gravity: expected an array of 2 numbers, got 3 numbers");
    EXPECT_EQ(errorOf(withTop(R"("gravity": [1])")),
              "gravity: expected an array of 2 numbers, got 1 number");
    EXPECT_EQ(errorOf(withTop(R"("gravity": [0, "down"])")),
              "gravity[1]: expected a number, got string");
    EXPECT_EQ(errorOf(withTop(R"("gravity": [false, 1])")),
              "gravity[0]: expected a number, got boolean");
    EXPECT_EQ(errorOf(withTop(R"("gravity": [1e39, 0])")), "gravity[0]: must be a finite number");
    EXPECT_EQ(errorOf(withTop(R"("gravity": [0, -1e400])")), "gravity[1]: must be a finite number");
}

TEST(SceneErrors, MaxVelocityAndDt) {
    EXPECT_EQ(errorOf(withTop(R"("maxVelocity": 0)")), "maxVelocity: must be > 0");
    EXPECT_EQ(errorOf(withTop(R"("maxVelocity": -5)")), "maxVelocity: must be > 0");
    EXPECT_EQ(errorOf(withTop(R"("maxVelocity": "fast")")),
              "maxVelocity: expected a number, got string");
    EXPECT_EQ(errorOf(withTop(R"("maxVelocity": 1e400)")), "maxVelocity: must be a finite number");
    EXPECT_EQ(errorOf(withTop(R"("dt": 0)")), "dt: must be > 0");
    EXPECT_EQ(errorOf(withTop(R"("dt": -0.5)")), "dt: must be > 0");
    // 1e-50 is a float 0: a step that never advances.
    EXPECT_EQ(errorOf(withTop(R"("dt": 1e-50)")), "dt: must be > 0");
    EXPECT_EQ(errorOf(withTop(R"("dt": 1e39)")), "dt: must be a finite number");
    EXPECT_EQ(errorOf(withTop(R"("dt": [0.1])")), "dt: expected a number, got array");
}

TEST(SceneErrors, Solver) {
    EXPECT_EQ(errorOf(withTop(R"("solver": "fast")")),
              R"(solver: expected "classic" or "physical")");
    EXPECT_EQ(errorOf(withTop(R"("solver": "Classic")")),
              R"(solver: expected "classic" or "physical")");
    EXPECT_EQ(errorOf(withTop(R"("solver": 1)")), "solver: expected a string, got number");
}

TEST(SceneErrors, ClassicOptions) {
    EXPECT_EQ(errorOf(withTop(R"("classic": true)")), "classic: expected an object, got boolean");
    EXPECT_EQ(errorOf(withTop(R"("classic": {"mass": 1})")),
              "classic.mass: expected true or false, got number");
    EXPECT_EQ(errorOf(withTop(R"("classic": {"coulomb": "yes"})")),
              "classic.coulomb: expected true or false, got string");
    EXPECT_EQ(errorOf(withTop(R"("classic": {"masses": true})")),
              R"(classic: unknown field "masses" (did you mean "mass"?))");
}

TEST(SceneErrors, PhysicalOptions) {
    EXPECT_EQ(errorOf(withTop(R"("physical": [])")), "physical: expected an object, got array");
    EXPECT_EQ(errorOf(withTop(R"("physical": {"iterations": 3})")),
              R"(physical: unknown field "iterations")");
    EXPECT_EQ(errorOf(withTop(R"("physical": {"velocityIterations": 2.5})")),
              "physical.velocityIterations: expected a whole number, got 2.5");
    EXPECT_EQ(errorOf(withTop(R"("physical": {"positionIterations": "3"})")),
              "physical.positionIterations: expected a whole number, got string");
    EXPECT_EQ(errorOf(withTop(R"("physical": {"frictionMix": "max"})")),
              R"(physical.frictionMix: expected "min" or "geometricMean")");
    // The ranges are the world's (checkWorldDef); the loader names the place and the value.
    EXPECT_EQ(errorOf(withTop(R"("physical": {"velocityIterations": 0})")),
              "physical.velocityIterations: must be in [1, 1000], got 0");
    EXPECT_EQ(errorOf(withTop(R"("physical": {"velocityIterations": 1e12})")),
              "physical.velocityIterations: must be in [1, 1000], got 1000000000000");
    EXPECT_THAT(errorOf(withTop(R"("physical": {"slop": -1})")),
                StartsWith("physical.slop: must be"));
}

TEST(SceneErrors, WholeNumbersFollowOneRule) {
    // Every whole-number field, in a scene where it is the only thing that varies.
    struct WholeField {
        std::string place;
        std::string (*scene)(const std::string& value);
        std::string range; // its rule, as the messages give it
    };
    const WholeField fields[] = {
        {"bodies[0].category",
         [](const std::string& v) {
             return withBodies(R"({"hw": 1, "hh": 1, "category": )" + v + "}");
         },
         "[0, 4294967295]"},
        {"bodies[0].mask",
         [](const std::string& v) {
             return withBodies(R"({"hw": 1, "hh": 1, "mask": )" + v + "}");
         },
         "[0, 4294967295]"},
        {"tilemap.category",
         [](const std::string& v) {
             return withTop(R"("tilemap": {"tile": 1, "rows": ["#"], "category": )" + v + "}");
         },
         "[0, 4294967295]"},
        {"tilemap.mask",
         [](const std::string& v) {
             return withTop(R"("tilemap": {"tile": 1, "rows": ["#"], "mask": )" + v + "}");
         },
         "[0, 4294967295]"},
        {"physical.velocityIterations",
         [](const std::string& v) {
             return withTop(R"("physical": {"velocityIterations": )" + v + "}");
         },
         "[1, 1000]"},
        {"physical.positionIterations",
         [](const std::string& v) {
             return withTop(R"("physical": {"positionIterations": )" + v + "}");
         },
         "[0, 1000]"},
    };
    for (const WholeField& f : fields) {
        SCOPED_TRACE(f.place);
        // A number whose value is whole, however it is written.
        for (const char* written : {"3", "3.0", "3e0", "0.3e1", "300e-2"})
            EXPECT_EQ(errorOf(f.scene(written)), "") << written;
        EXPECT_EQ(errorOf(f.scene("3.5")), f.place + ": expected a whole number, got 3.5");
        EXPECT_EQ(errorOf(f.scene("1e-7")), f.place + ": expected a whole number, got 1e-07");
        EXPECT_EQ(errorOf(f.scene(R"("3")")), f.place + ": expected a whole number, got string");
        EXPECT_EQ(errorOf(f.scene("true")), f.place + ": expected a whole number, got boolean");
        // Out of the field's range, whole numbers of any size are named as such.
        for (const auto& [written, shown] : {std::pair{"-1", "-1"},
                                             {"-1.0", "-1"},
                                             {"4294967296", "4294967296"},
                                             {"18446744073709551616", "18446744073709551616"},
                                             {"-9223372036854775809", "-9223372036854775808"},
                                             {"1e300", "1e+300"}})
            EXPECT_EQ(errorOf(f.scene(written)),
                      f.place + ": must be in " + f.range + ", got " + shown)
                << written;
    }
    // The values read, at the ends of the ranges.
    const Scene scene = parseScene(
        R"({"physical": {"velocityIterations": 1000.0, "positionIterations": 0e5},
            "bodies": [{"hw": 1, "hh": 1, "category": 4294967295.0, "mask": 0.0}]})");
    EXPECT_EQ(scene.world.physical.velocityIterations, 1000);
    EXPECT_EQ(scene.world.physical.positionIterations, 0);
    EXPECT_EQ(scene.bodies[0].def.category, 4294967295u);
    EXPECT_EQ(scene.bodies[0].def.mask, 0u);
}

// --- Errors: bodies --------------------------------------------------------------------

TEST(SceneErrors, BodyShape) {
    EXPECT_EQ(errorOf(withBodies(std::string(kBox) + ", 7")),
              "bodies[1]: expected an object, got number");
    EXPECT_EQ(errorOf(withBodies(std::string(kBox) + ", " + kBox +
                                 R"(, {"hw": 1, "hh": 1, "colour": "red"})")),
              R"(bodies[2]: unknown field "colour")");
    // userData belongs to the program, not to the file.
    EXPECT_EQ(errorOf(withBodies(R"({"hw": 1, "hh": 1, "userData": 0})")),
              R"(bodies[0]: unknown field "userData")");
    EXPECT_EQ(errorOf(withBodies(R"({"hh": 1})")), R"(bodies[0]: missing field "hw")");
    EXPECT_EQ(errorOf(withBodies(R"({"hw": 1})")), R"(bodies[0]: missing field "hh")");
}

TEST(SceneErrors, SizesMustBePositive) {
    const std::string three = std::string(kBox) + ", " + kBox + ", " + kBox + ", ";
    EXPECT_EQ(errorOf(withBodies(three + R"({"hw": 0, "hh": 1})")), "bodies[3].hw: must be > 0");
    EXPECT_EQ(errorOf(withBodies(three + R"({"hw": 1, "hh": -2})")), "bodies[3].hh: must be > 0");
}

TEST(SceneErrors, Type) {
    EXPECT_EQ(errorOf(withBodies(std::string(kBox) + R"(, {"type": "rock", "hw": 1, "hh": 1})")),
              R"(bodies[1].type: expected one of "static", "kinematic", "dynamic")");
    EXPECT_EQ(errorOf(withBodies(R"({"type": 2, "hw": 1, "hh": 1})")),
              "bodies[0].type: expected a string, got number");
}

TEST(SceneErrors, EveryNumberFieldWantsANumber) {
    // The names of BodyDef's numbers, all of them (body.hpp).
    for (const char* name : {"x", "y", "hw", "hh", "vx", "vy", "bounce", "friction", "mass",
                             "density", "gravityScale", "damping"}) {
        SCOPED_TRACE(name);
        const std::string field = std::string(R"(")") + name + R"(": )";
        // A body with every required field, then the one under test set wrongly (it may
        // repeat hw or hh, so test those in a body without them).
        const bool required = std::string(name) == "hw" || std::string(name) == "hh";
        const std::string rest = required
                                     ? (std::string(name) == "hw" ? R"("hh": 1, )" : R"("hw": 1, )")
                                     : R"("hw": 1, "hh": 1, )";
        const std::string place = std::string("bodies[0].") + name;
        EXPECT_EQ(errorOf(withBodies("{" + rest + field + R"("3"})")),
                  place + ": expected a number, got string");
        EXPECT_EQ(errorOf(withBodies("{" + rest + field + "true}")),
                  place + ": expected a number, got boolean");
        EXPECT_EQ(errorOf(withBodies("{" + rest + field + "null}")),
                  place + ": expected a number, got null");
        EXPECT_EQ(errorOf(withBodies("{" + rest + field + "1e39}")),
                  place + ": must be a finite number");
        EXPECT_EQ(errorOf(withBodies("{" + rest + field + "-1e400}")),
                  place + ": must be a finite number");
    }
}

TEST(SceneErrors, JustAboveTheLargestFloatIsNotAFloat) {
    // 3.4028236e38 is past the midpoint between FLT_MAX and 2^128: it rounds to infinity.
    EXPECT_EQ(errorOf(withBodies(R"({"hw": 1, "hh": 1, "x": 3.4028236e38})")),
              "bodies[0].x: must be a finite number");
}

TEST(SceneErrors, NumbersBeyondTheRangeAreNamed) {
    // The largest float is a number, but beyond the range jostle works in (math.hpp).
    EXPECT_EQ(errorOf(withBodies(R"({"hw": 1, "hh": 1, "x": 3.4028235e38})")),
              "bodies[0].x: must be of magnitude <= 1e9");
    EXPECT_EQ(errorOf(withBodies(R"({"hw": 1e-10, "hh": 1})")), "bodies[0].hw: must be >= 1e-9");
    EXPECT_EQ(errorOf(R"({"gravity": [0, 2e9], "bodies": []})"),
              "gravity: must be of magnitude <= 1e9");
    EXPECT_EQ(errorOf(R"({"dt": 1e-12, "bodies": []})"), "dt: must be in [1e-9, 1e9]");
}

TEST(SceneErrors, MassAndDensity) {
    EXPECT_EQ(errorOf(withBodies(R"({"hw": 1, "hh": 1, "mass": 0})")),
              "bodies[0].mass: must be > 0");
    EXPECT_EQ(errorOf(withBodies(R"({"hw": 1, "hh": 1, "mass": -2})")),
              "bodies[0].mass: must be > 0");
    EXPECT_EQ(errorOf(withBodies(R"({"hw": 1, "hh": 1, "mass": 2, "density": 3})")),
              R"(bodies[0]: give "mass" or "density", not both)");
    EXPECT_THAT(errorOf(withBodies(R"({"hw": 1, "hh": 1, "density": 0})")),
                StartsWith("bodies[0].density: must be"));
}

TEST(SceneErrors, ValueRulesOfBodiesGetTheirPlace) {
    // The rules are checkBodyDef's; the loader adds the place.
    EXPECT_THAT(errorOf(withBodies(std::string(kBox) + R"(, {"hw": 1, "hh": 1, "bounce": 2})")),
                StartsWith("bodies[1].bounce: must be"));
    EXPECT_THAT(errorOf(withBodies(R"({"hw": 1, "hh": 1, "friction": -0.1})")),
                StartsWith("bodies[0].friction: must be"));
    EXPECT_THAT(errorOf(withBodies(R"({"hw": 1, "hh": 1, "damping": -1})")),
                StartsWith("bodies[0].damping: must be"));
}

// Rounded bodies, ramps and segments: the rules between fields are checkBodyDef's too.
TEST(SceneErrors, ShapesFollowTheRulesOfCheckBodyDef) {
    const std::string three = std::string(kBox) + ", " + kBox + ", " + kBox + ", ";
    EXPECT_EQ(errorOf(withBodies(three + R"({"hw": 1, "hh": 2, "radius": 1.5})")),
              "bodies[3].radius: must be <= hw and hh");
    EXPECT_EQ(errorOf(withBodies(R"({"hw": 1, "hh": 1, "radius": -0.5})")),
              "bodies[0].radius: must be >= 0");
    EXPECT_EQ(errorOf(withBodies(R"({"hw": 1, "hh": 1, "radius": "round"})")),
              "bodies[0].radius: expected a number, got string");
    EXPECT_EQ(errorOf(withBodies(R"({"type": "static", "hw": 2, "hh": 1, "slope": [1, 0]})")),
              "bodies[0].slope: must be [0, 0] or each component -1 or 1");
    EXPECT_EQ(errorOf(withBodies(R"({"type": "static", "hw": 2, "hh": 1, "slope": [-1]})")),
              "bodies[0].slope: expected an array of 2 numbers, got 1 number");
    EXPECT_EQ(errorOf(withBodies(R"({"type": "static", "hw": 2, "hh": 1, "slope": "up"})")),
              "bodies[0].slope: expected an array of 2 numbers, got string");
    EXPECT_EQ(errorOf(withBodies(kBox + std::string(R"(, {"hw": 2, "hh": 1, "slope": [-1, -1]})"))),
              "bodies[1].slope: a ramp or segment must be static or kinematic");
    EXPECT_EQ(errorOf(withBodies(
                  R"({"type": "static", "hw": 2, "hh": 1, "slope": [-1, -1], "radius": 0.5})")),
              "bodies[0].radius: must be 0 for a ramp or segment");
    EXPECT_EQ(errorOf(withBodies(R"({"type": "static", "hw": 2, "hh": 1, "segment": true})")),
              "bodies[0].segment: needs a slope: a segment is a ramp's sloped face");
    EXPECT_EQ(errorOf(withBodies(
                  R"({"type": "static", "hw": 2, "hh": 1, "slope": [-1, -1], "segment": 1})")),
              "bodies[0].segment: expected true or false, got number");
    EXPECT_EQ(errorOf(withBodies(R"({"hw": 1, "hh": 1, "radius": 1, "oneWay": [0, -1]})")),
              "bodies[0].oneWay: must be [0, 0] for a rounded body, ramp or segment");
    EXPECT_EQ(errorOf(withBodies(
                  R"({"type": "static", "hw": 2, "hh": 1, "slope": [1, 1], "oneWay": [0, -1]})")),
              "bodies[0].oneWay: must be [0, 0] for a rounded body, ramp or segment");
}

// The classic model has sharp boxes only: a file that asks for it and holds a rounded
// body, a ramp or a segment is refused at the first such body, wherever "solver" stands.
TEST(SceneErrors, TheClassicModelRefusesShapes) {
    const std::string refused = R"(: the classic model has sharp boxes only (solver "classic"))";
    EXPECT_EQ(errorOf(R"({"solver": "classic", "bodies": [)" + std::string(kBox) +
                      R"(, {"hw": 1, "hh": 1, "radius": 1}]})"),
              "bodies[1].radius" + refused);
    EXPECT_EQ(errorOf(R"({"bodies": [{"type": "static", "hw": 2, "hh": 1, "slope": [-1, -1],
                                      "segment": true}], "solver": "classic"})"),
              "bodies[0].slope" + refused);
    // Boxes alone are the classic model's; shapes are the physical model's.
    EXPECT_EQ(errorOf(R"({"solver": "classic", "bodies": [)" + std::string(kBox) + "]}"), "");
    EXPECT_EQ(errorOf(R"({"solver": "physical", "bodies": [{"hw": 1, "hh": 1, "radius": 1}]})"),
              "");
}

// Ramp tiles are ramps too: a map that holds one is refused in a file that asks for the
// classic model, at its first ramp reading the rows top first, left to right.
TEST(SceneErrors, TheClassicModelRefusesRampTiles) {
    const std::string refused = R"(: the classic model has sharp boxes only (solver "classic"))";
    // Row 0 is all empty, row 1 has '#' only; row 2's first ramp is its sixth byte.
    EXPECT_EQ(errorOf(R"({"solver": "classic", "bodies": [],
                          "tilemap": {"tile": 16, "rows": ["......", "#....#", "#####/"]}})"),
              "tilemap.rows[2][5]" + refused);
    // The solver after the maps; the first map is boxes only.
    EXPECT_EQ(errorOf(R"({"bodies": [], "tilemaps": [{"tile": 1, "rows": ["#"]},
                                                      {"tile": 1, "rows": ["#.", "rR"]}],
                          "solver": "classic"})"),
              "tilemaps[1].rows[1][0]" + refused);
    // A ramp tile and a rounded body: the one the file holds first is reported.
    const std::string map = R"("tilemap": {"tile": 1, "rows": ["7"]})";
    const std::string ball = R"("bodies": [{"hw": 1, "hh": 1, "radius": 1}])";
    EXPECT_EQ(errorOf(R"({"solver": "classic", )" + map + ", " + ball + "}"),
              "tilemap.rows[0][0]" + refused);
    EXPECT_EQ(errorOf(R"({"solver": "classic", )" + ball + ", " + map + "}"),
              "bodies[0].radius" + refused);
    // Boxes alone are the classic model's; ramp tiles are the physical model's.
    EXPECT_EQ(errorOf(R"({"solver": "classic", "bodies": [],
                          "tilemap": {"tile": 1, "rows": ["#.#"]}})"),
              "");
    EXPECT_EQ(errorOf(R"({"bodies": [], "tilemap": {"tile": 1, "rows": ["/\\7FrRLlcCDd"]}})"), "");
}

TEST(SceneErrors, Ids) {
    const std::string body = R"({"hw": 1, "hh": 1, "id": )";
    EXPECT_EQ(errorOf(withBodies(body + R"("floor"}, )" + body + R"("crate"}, )" + kBox + ", " +
                                 kBox + ", " + body + R"("crate"})")),
              R"(bodies[4].id: "crate" is already the id of bodies[1])");
    // A body without an id goes by its index, which an explicit id may already hold.
    EXPECT_EQ(errorOf(withBodies(body + R"("1"}, )" + kBox)),
              R"(bodies[1]: its default id "1" is already the id of bodies[0])");
    EXPECT_EQ(errorOf(withBodies(body + "7}")), "bodies[0].id: expected a string, got number");
    EXPECT_EQ(errorOf(withBodies(body + R"(""})")), "bodies[0].id: must not be empty");
}

TEST(SceneErrors, IdsHoldNoControlCharacters) {
    // "a\u0000b" printed as "a" in traces and summaries, beside a body whose id is "a".
    const std::string body = R"({"hw": 1, "hh": 1, "id": )";
    EXPECT_EQ(errorOf(withBodies(body + R"("a"}, )" + kBox + ", " + body + R"("a\u0000b"})")),
              R"(bodies[2].id: must not contain control characters, got "a\u0000b")");
    EXPECT_EQ(errorOf(withBodies(body + R"("tab\there"})")),
              R"(bodies[0].id: must not contain control characters, got "tab\there")");
    // DEL and the C1 controls, escaped or written as they are.
    EXPECT_EQ(errorOf(withBodies(body + R"("a\u007f"})")),
              R"(bodies[0].id: must not contain control characters, got "a\u007f")");
    EXPECT_EQ(errorOf(withBodies(body + "\"a\x7f\"}")),
              R"(bodies[0].id: must not contain control characters, got "a\u007f")");
    EXPECT_EQ(errorOf(withBodies(body + "\"next\xc2\x85line\"}")),
              R"(bodies[0].id: must not contain control characters, got "next\u0085line")");
    // Other characters are names like any other.
    const Scene scene = parseScene(withBodies(body + R"("caf\u00e9 \u00a0 \ud83d\ude00"})"));
    EXPECT_EQ(scene.bodies[0].id, "caf\xc3\xa9 \xc2\xa0 \xf0\x9f\x98\x80");
}

TEST(SceneErrors, OddNamesAreQuotedAsJson) {
    EXPECT_EQ(errorOf(withTop(R"("a\"b\n": 1)")), R"(unknown field "a\"b\n")");
}

// --- Tile maps -------------------------------------------------------------------------

TEST(SceneTileMaps, EveryFieldIsReadAsWritten) {
    const Scene scene = parseScene(withTop(R"("tilemap": {
        "x": -8, "y": 4.5, "tile": 16, "rows": ["#..#", "####"], "friction": 0.25,
        "bounce": 0.5, "category": 2, "mask": 6, "oneWay": [0, -1], "sensor": true})"));
    ASSERT_EQ(scene.tileMaps.size(), 1u);
    const TileMapDef& map = scene.tileMaps[0];
    EXPECT_EQ(map.x, -8.0f);
    EXPECT_EQ(map.y, 4.5f);
    EXPECT_EQ(map.tile, 16.0f);
    EXPECT_EQ(map.rows, (std::vector<std::string>{"#..#", "####"}));
    EXPECT_EQ(map.friction, 0.25f);
    EXPECT_EQ(map.bounce, 0.5f);
    EXPECT_EQ(map.category, 2u);
    EXPECT_EQ(map.mask, 6u);
    EXPECT_EQ(map.oneWay, (Vec2{0.0f, -1.0f}));
    EXPECT_TRUE(map.sensor);
}

TEST(SceneTileMaps, DefaultsAreThoseOfTileMapDef) {
    const Scene scene = parseScene(withTop(R"("tilemap": {"tile": 8, "rows": ["#"]})"));
    ASSERT_EQ(scene.tileMaps.size(), 1u);
    const TileMapDef& map = scene.tileMaps[0];
    const TileMapDef defaults;
    EXPECT_EQ(map.x, 0.0f);
    EXPECT_EQ(map.y, 0.0f);
    EXPECT_EQ(map.friction, defaults.friction);
    EXPECT_EQ(map.bounce, defaults.bounce);
    EXPECT_EQ(map.category, defaults.category);
    EXPECT_EQ(map.mask, defaults.mask);
    EXPECT_EQ(map.oneWay, defaults.oneWay);
    EXPECT_FALSE(map.sensor);
    EXPECT_TRUE(parseScene(withTop(R"("gravity": [0, 1])")).tileMaps.empty());
}

TEST(SceneTileMaps, SeveralMapsInFileOrder) {
    const Scene scene = parseScene(withTop(R"("tilemaps": [
        {"tile": 8, "rows": ["#"]}, {"tile": 4, "rows": [".#"], "y": 100}])"));
    ASSERT_EQ(scene.tileMaps.size(), 2u);
    EXPECT_EQ(scene.tileMaps[0].tile, 8.0f);
    EXPECT_EQ(scene.tileMaps[1].tile, 4.0f);
    EXPECT_EQ(scene.tileMaps[1].rows, (std::vector<std::string>{".#"}));
    EXPECT_TRUE(parseScene(withTop(R"("tilemaps": [])")).tileMaps.empty());
}

// --- Every property of src/body_properties.hpp that a file can hold ---------------------

/// `value` as JSON; null for a pointer, which a file cannot hold.
std::string jsonOf(const properties::Value& value) {
    return test_support::literalOf(value, Notation::Json);
}

TEST(SceneProperties, EveryBodyPropertyAFileCanHoldIsRead) {
    for (const auto& field : properties::kBodyFields) {
        const std::string name = field.property->name;
        const properties::Value sample = sampleOf(*field.property);
        std::string body = "{\"" + name + "\": " + jsonOf(sample);
        // What the sample needs besides (a ramp's type), as test_properties.cpp gives it.
        for (const auto& [property, value] : sampleNeeds(*field.property))
            body += std::string(", \"") + property->name + "\": " + jsonOf(value);
        // hw and hh are required: the sample replaces one of them.
        for (const char* size : {"hw", "hh"})
            if (name != size)
                body += std::string(", \"") + size + "\": 1";
        const std::string scene = withBodies(body + "}");
        if (std::holds_alternative<void*>(sample)) {
            EXPECT_EQ(errorOf(scene), "bodies[0]: unknown field \"" + name + "\"");
            continue;
        }
        const Scene parsed = parseScene(scene);
        EXPECT_TRUE(valueOf(parsed.bodies.at(0).def, field) == sample) << name;
    }
}

TEST(SceneProperties, BodyToJsonWritesEveryPropertyAFileCanHoldAndReadsBackTheSame) {
    for (const auto& field : properties::kBodyFields) {
        const properties::Value sample = sampleOf(*field.property);
        if (std::holds_alternative<void*>(sample))
            continue;
        BodyDef def{.hw = 1, .hh = 1};
        test_support::setValue(def, field, sample);
        for (const auto& [property, value] : sampleNeeds(*field.property))
            test_support::setValue(def, *properties::find(properties::kBodyFields, *property),
                                   value);
        const std::string json = bodyToJson(def);
        const Scene parsed = parseScene(withBodies(json));
        for (const auto& each : properties::kBodyFields) {
            if (std::holds_alternative<void*>(sampleOf(*each.property)))
                continue;
            EXPECT_TRUE(valueOf(parsed.bodies.at(0).def, each) == valueOf(def, each))
                << field.property->name << ": " << each.property->name << " in " << json;
        }
    }
    // A dense body has density and no mass; a body of a given mass, mass and no density.
    EXPECT_THAT(bodyToJson({.hw = 1, .hh = 1, .density = 2}), HasSubstr("\"density\":2"));
    EXPECT_THAT(bodyToJson({.hw = 1, .hh = 1, .density = 2}), Not(HasSubstr("mass")));
    EXPECT_THAT(bodyToJson({.hw = 1, .hh = 1, .mass = 3}), Not(HasSubstr("density")));
}

TEST(SceneProperties, EveryTileMapPropertyAFileCanHoldIsRead) {
    for (const auto& field : properties::kTileMapFields) {
        const std::string name = field.property->name;
        const properties::Value sample = sampleOf(*field.property);
        std::string map = "{\"" + name + "\": " + jsonOf(sample) + R"(, "rows": ["#"])";
        if (name != "tile")
            map += R"(, "tile": 1)";
        const std::string scene = withTop(R"("tilemap": )" + map + "}");
        if (std::holds_alternative<void*>(sample)) {
            EXPECT_EQ(errorOf(scene), "tilemap: unknown field \"" + name + "\"");
            continue;
        }
        const Scene parsed = parseScene(scene);
        EXPECT_TRUE(valueOf(parsed.tileMaps.at(0), field) == sample) << name;
    }
}

// WorldDef's own fields at the top level, its options in "classic" and "physical"; its task
// system is the game's to choose when it makes the world, not the scene's.
TEST(SceneProperties, EveryWorldOptionAFileCanHoldIsRead) {
    test_support::forEachWorldTable([](const std::string& table, const auto& fields) {
        for (const auto& field : fields) {
            const std::string name = field.property->name;
            const properties::Value sample = sampleOf(*field.property);
            const std::string value = "\"" + name + "\": " + jsonOf(sample);
            const bool top = table == "world" || table == "tasks";
            const std::string scene = withTop(top ? value : "\"" + table + "\": {" + value + "}");
            if (table == "tasks") {
                EXPECT_THAT(errorOf(scene), StartsWith("unknown field \"" + name + "\""));
                continue;
            }
            WorldDef world = parseScene(scene).world;
            EXPECT_TRUE(valueOf(test_support::partOf(world, field), field) == sample)
                << table << "." << name;
        }
    });
}

TEST(SceneErrors, TileMaps) {
    const auto map = [](const std::string& fields) {
        return errorOf(withTop(R"("tilemap": {)" + fields + "}"));
    };
    EXPECT_EQ(map(R"("tile": 16, "rows": ["#.", "..", "#.#..."])"),
              "tilemap.rows[2]: has 6 columns, rows[0] has 2");
    EXPECT_EQ(map(R"("tile": 16, "rows": ["....", "####", "##.#.x"])"),
              "tilemap.rows[2][5]: expected '#', '.' or a ramp, got 'x'");
    EXPECT_EQ(map(R"("tile": 16, "rows": ["# "])"),
              "tilemap.rows[0][1]: expected '#', '.' or a ramp, got ' '");
    EXPECT_EQ(map(R"("tile": 16, "rows": [])"), "tilemap.rows: must have at least one row");
    EXPECT_EQ(map(R"("tile": 16, "rows": [""])"), "tilemap.rows[0]: must have at least one column");
    EXPECT_EQ(map(R"("tile": 16, "rows": "##")"), "tilemap.rows: expected an array, got string");
    EXPECT_EQ(map(R"("tile": 16, "rows": ["#", 1])"),
              "tilemap.rows[1]: expected a string, got number");
    EXPECT_EQ(map(R"("rows": ["#"])"), R"(tilemap: missing field "tile")");
    EXPECT_EQ(map(R"("tile": 16)"), R"(tilemap: missing field "rows")");
    EXPECT_EQ(map(R"("tile": 0, "rows": ["#"])"), "tilemap.tile: must be > 0");
    EXPECT_EQ(map(R"("tile": "big", "rows": ["#"])"),
              "tilemap.tile: expected a number, got string");
    EXPECT_EQ(map(R"("tile": 1e30, "rows": ["##########"])"),
              "tilemap.tile: must be of magnitude <= 1e9");
    EXPECT_EQ(map(R"("tile": 2e8, "rows": ["##########"])"),
              "tilemap.tile: puts the map's far corner beyond 1e9 (math.hpp)");
    EXPECT_EQ(map(R"("tile": 16, "x": 1e39, "rows": ["#"])"), "tilemap.x: must be a finite number");
    EXPECT_EQ(map(R"("tile": 16, "rows": ["#"], "friction": 2)"),
              "tilemap.friction: must be in [0, 1]");
    EXPECT_EQ(map(R"("tile": 16, "rows": ["#"], "bounce": -1)"),
              "tilemap.bounce: must be in [0, 1]");
    EXPECT_EQ(map(R"("tile": 16, "rows": ["#"], "oneWay": [1, 1])"),
              "tilemap.oneWay: must be [0, 0] or one of [1, 0], [-1, 0], [0, 1], [0, -1]");
    EXPECT_EQ(map(R"("tile": 16, "rows": ["#"], "mask": -1)"),
              "tilemap.mask: must be in [0, 4294967295], got -1");
    EXPECT_EQ(map(R"("tile": 16, "rows": ["#"], "sensor": 1)"),
              "tilemap.sensor: expected true or false, got number");
    EXPECT_EQ(map(R"("tile": 16, "rows": ["#"], "colour": "red")"),
              R"(tilemap: unknown field "colour")");
    EXPECT_EQ(map(R"("tile": 16, "tile": 8, "rows": ["#"])"), R"(tilemap: duplicate field "tile")");

    EXPECT_EQ(errorOf(withTop(R"("tilemap": [])")), "tilemap: expected an object, got array");
    EXPECT_EQ(errorOf(withTop(R"("tilemaps": {})")), "tilemaps: expected an array, got object");
    EXPECT_EQ(errorOf(withTop(R"("tilemaps": [{"tile": 1, "rows": ["#"]},
                                              {"tile": 1, "rows": ["#", "?"]}])")),
              "tilemaps[1].rows[1][0]: expected '#', '.' or a ramp, got '?'");
    EXPECT_EQ(errorOf(withTop(R"("tilemap": {"tile": 1, "rows": ["#"]},
                                 "tilemaps": [])")),
              R"(give "tilemap" or "tilemaps", not both)");
}

// --- Files -----------------------------------------------------------------------------

class SceneFiles : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = std::filesystem::temp_directory_path() /
               ("jostle_scene_test_" + std::to_string(::getpid()));
        std::filesystem::create_directories(dir_);
    }
    void TearDown() override { std::filesystem::remove_all(dir_); }

    std::string write(const std::string& name, const std::string& text) {
        const std::string path = (dir_ / name).string();
        std::ofstream(path, std::ios::binary) << text;
        return path;
    }

    std::filesystem::path dir_;
};

TEST_F(SceneFiles, LoadsAFile) {
    const std::string path = write("ok.json", withBodies(R"({"id": "a", "hw": 1, "hh": 2})"));
    const Scene scene = loadScene(path);
    ASSERT_EQ(scene.bodies.size(), 1u);
    EXPECT_EQ(scene.bodies[0].id, "a");
    EXPECT_EQ(scene.bodies[0].def.hh, 2.0f);
}

TEST_F(SceneFiles, ErrorsStartWithTheFile) {
    const std::string path = write("bad.json", withBodies(R"({"hw": -1, "hh": 2})"));
    try {
        loadScene(path);
        FAIL() << "no SceneError";
    } catch (const SceneError& error) {
        EXPECT_EQ(std::string(error.what()), path + ": bodies[0].hw: must be > 0");
    }
}

TEST_F(SceneFiles, MissingFilesAndDirectoriesCannotBeRead) {
    const std::string missing = (dir_ / "missing.json").string();
    try {
        loadScene(missing);
        FAIL() << "no SceneError";
    } catch (const SceneError& error) {
        EXPECT_EQ(std::string(error.what()), missing + ": cannot read: No such file or directory");
    }
    try {
        loadScene(dir_.string());
        FAIL() << "no SceneError";
    } catch (const SceneError& error) {
        EXPECT_EQ(std::string(error.what()), dir_.string() + ": cannot read: Is a directory");
    }
}

TEST_F(SceneFiles, FilesBeyondTheLimitAreRefusedBeforeReading) {
    // A sparse file: a gigabyte of holes takes no room on the disk.
    const std::string path = (dir_ / "huge.json").string();
    { std::ofstream(path, std::ios::binary) << "{"; }
    std::filesystem::resize_file(path, kMaxSceneBytes + 1);
    try {
        loadScene(path);
        FAIL() << "no SceneError";
    } catch (const SceneError& error) {
        EXPECT_EQ(std::string(error.what()),
                  path + ": too large: a scene file holds at most 1073741824 bytes (1 GiB)");
    }
}

// --- addBodies -------------------------------------------------------------------------

TEST(AddBodies, CreatesTheBodiesInFileOrder) {
    const Scene scene = parseScene(R"({"solver": "classic", "bodies": [
        {"type": "static", "x": 1, "y": 2, "hw": 3, "hh": 4},
        {"x": 5, "y": 6, "hw": 1, "hh": 1, "vx": 7, "bounce": 0.5, "mass": 9}]})");
    World world(scene.world);
    const std::vector<BodyId> ids = addBodies(world, scene);
    ASSERT_EQ(ids.size(), 2u);
    ASSERT_EQ(world.bodyCount(), 2u);
    EXPECT_EQ(world.bodies()[0], ids[0]);
    EXPECT_EQ(world.bodies()[1], ids[1]);
    EXPECT_EQ(world.type(ids[0]), BodyType::Static);
    EXPECT_EQ(world.position(ids[0]), (Vec2{1.0f, 2.0f}));
    EXPECT_EQ(world.halfExtents(ids[0]), (Vec2{3.0f, 4.0f}));
    EXPECT_EQ(world.position(ids[1]), (Vec2{5.0f, 6.0f}));
    EXPECT_EQ(world.velocity(ids[1]), (Vec2{7.0f, 0.0f}));
    EXPECT_EQ(world.bounce(ids[1]), 0.5f);
    EXPECT_EQ(world.mass(ids[1]), 9.0f);
}

TEST(AddBodies, ABadBodyLeavesTheWorldUntouched) {
    // A Scene built in code skips the loader's checks; addBodies still checks them all
    // before creating any.
    Scene scene;
    scene.world.solver = Solver::Classic;
    scene.bodies.push_back({"good", BodyDef{.hw = 1, .hh = 1}});
    scene.bodies.push_back({"bad", BodyDef{.hw = 1, .hh = 0}});
    World world(scene.world);
    try {
        addBodies(world, scene);
        FAIL() << "no jostle::Error";
    } catch (const Error& error) {
        EXPECT_THAT(std::string(error.what()), HasSubstr("bodies[1].hh: must be > 0"));
    }
    EXPECT_EQ(world.bodyCount(), 0u);
}

TEST(AddBodies, TheClassicModelRefusesShapesBeforeCreatingAny) {
    // A Scene built in code, or a file's scene run in the classic model by
    // `jostle run --solver classic`: the world's model decides.
    Scene scene;
    scene.bodies.push_back({"box", BodyDef{.hw = 1, .hh = 1}});
    scene.bodies.push_back({"ball", BodyDef{.hw = 1, .hh = 1, .radius = 1}});
    World classic(WorldDef{.solver = Solver::Classic});
    try {
        addBodies(classic, scene);
        FAIL() << "no jostle::Error";
    } catch (const Error& error) {
        EXPECT_EQ(
            std::string(error.what()),
            R"(addBodies: bodies[1].radius: the classic model has sharp boxes only (solver "classic"))");
    }
    EXPECT_EQ(classic.bodyCount(), 0u);

    World physical;
    const std::vector<BodyId> ids = addBodies(physical, scene);
    ASSERT_EQ(ids.size(), 2u);
    EXPECT_EQ(physical.bodyDef(ids[1]).radius, 1.0f);
}

// --- addTileMaps ------------------------------------------------------------------------

TEST(AddTileMaps, CreatesTheMapsInFileOrder) {
    const Scene scene = parseScene(R"({"bodies": [], "tilemaps": [
        {"tile": 10, "rows": ["##", ".#"], "friction": 0.25},
        {"x": 100, "tile": 2, "rows": ["#.#"]}]})");
    World world(scene.world);
    const std::vector<TileMapId> maps = addTileMaps(world, scene);
    ASSERT_EQ(maps.size(), 2u);
    EXPECT_EQ(tileMapDef(world, maps[0]).rows, scene.tileMaps[0].rows);
    EXPECT_EQ(tileMapDef(world, maps[1]).rows, scene.tileMaps[1].rows);
    // "##" over ".#": the run of row 0, then the single tile of row 1; then two tiles.
    ASSERT_EQ(world.bodyCount(), 4u);
    EXPECT_EQ(tileMapOf(world, world.bodies()[0]), maps[0]);
    EXPECT_EQ(world.position(world.bodies()[0]), (Vec2{10.0f, 5.0f}));
    EXPECT_EQ(world.halfExtents(world.bodies()[0]), (Vec2{10.0f, 5.0f}));
    EXPECT_EQ(world.friction(world.bodies()[0]), 0.25f);
    EXPECT_EQ(tileMapOf(world, world.bodies()[3]), maps[1]);
    EXPECT_EQ(world.position(world.bodies()[3]), (Vec2{105.0f, 1.0f}));
}

TEST(AddTileMaps, ABadMapLeavesTheWorldUntouched) {
    Scene scene;
    TileMapDef good;
    good.tile = 1;
    good.rows = {"#"};
    TileMapDef bad = good;
    bad.rows = {"#", "x"};
    scene.tileMaps = {good, bad};
    World world(scene.world);
    try {
        addTileMaps(world, scene);
        FAIL() << "no jostle::Error";
    } catch (const Error& error) {
        EXPECT_EQ(std::string(error.what()),
                  "addTileMaps: tileMaps[1].rows[1][0]: expected '#', '.' or a ramp, got 'x'");
    }
    EXPECT_EQ(world.bodyCount(), 0u);
}

TEST(AddTileMaps, TheClassicModelRefusesRampsBeforeCreatingAny) {
    // A Scene built in code, or a file's scene run in the classic model by
    // `jostle run --solver classic`: the world's model decides. The first map, boxes
    // only, would be accepted alone; it is not created either.
    Scene scene;
    TileMapDef boxes;
    boxes.tile = 1;
    boxes.rows = {"##"};
    TileMapDef ramps = boxes;
    ramps.rows = {"#/", "##"};
    scene.tileMaps = {boxes, ramps};
    World classic(WorldDef{.solver = Solver::Classic});
    try {
        addTileMaps(classic, scene);
        FAIL() << "no jostle::Error";
    } catch (const Error& error) {
        EXPECT_EQ(
            std::string(error.what()),
            R"(addTileMaps: tileMaps[1].rows[0][1]: the classic model has sharp boxes only (solver "classic"))");
    }
    EXPECT_EQ(classic.bodyCount(), 0u);

    // The physical model takes them: "##" is one box; "#/" over "##" is the box of row 0's
    // '#', the box of row 1, and the ramp.
    World physical;
    const std::vector<TileMapId> maps = addTileMaps(physical, scene);
    ASSERT_EQ(maps.size(), 2u);
    EXPECT_EQ(physical.bodyCount(), 4u);
    EXPECT_EQ(tileOf(physical, maps[1], 1, 0), '/');
}

TEST(AddTileMaps, ABoxLandsOnATileFloor) {
    const Scene scene = parseScene(R"({"gravity": [0, 800],
        "tilemap": {"x": 0, "y": 100, "tile": 16, "rows": ["....", "####"]},
        "bodies": [{"x": 32, "y": 0, "hw": 8, "hh": 8}]})");
    World world(scene.world);
    addTileMaps(world, scene);
    const std::vector<BodyId> ids = addBodies(world, scene);
    for (int i = 0; i < 120; ++i)
        world.step(scene.dt);
    // The floor's top is row 1's: y = 100 + 16. Within the slop, 0.01 × 8.
    EXPECT_NEAR(world.position(ids[0]).y, 116.0f - 8.0f, 0.08f);
}

// --- The example scenes ----------------------------------------------------------------

TEST(ExampleScenes, TutorialIsTheClassicDemo) {
    const Scene scene = loadScene(JOSTLE_SCENES_DIR "/tutorial.json");
    EXPECT_EQ(scene.world.solver, Solver::Classic);
    EXPECT_GT(scene.world.gravity.y, 0.0f); // y grows downward
    EXPECT_EQ(scene.world.maxVelocity, 1000.0f);

    int statics = 0;
    int dynamics = 0;
    float floorTop = -std::numeric_limits<float>::infinity();
    for (const SceneBody& body : scene.bodies) {
        if (body.def.type == BodyType::Static) {
            ++statics;
            floorTop = std::max(floorTop, body.def.y - body.def.hh); // the lowest top
        } else if (body.def.type == BodyType::Dynamic) {
            ++dynamics;
            EXPECT_LE(body.def.bounce, 0.8f);
        }
    }
    EXPECT_GE(statics, 3); // a floor and platforms
    EXPECT_GE(dynamics, 8);

    // Ten seconds of falling and bouncing: no box falls through the floor. (The classic
    // model lets a box pushed by a later one overlap the floor until the next step, so
    // the test is on the centre, not on the bottom edge.)
    World world(scene.world);
    const std::vector<BodyId> ids = addBodies(world, scene);
    for (int i = 0; i < 600; ++i)
        world.step(scene.dt);
    for (std::size_t i = 0; i < ids.size(); ++i) {
        if (scene.bodies[i].def.type != BodyType::Dynamic)
            continue;
        SCOPED_TRACE(scene.bodies[i].id);
        const Vec2 p = world.position(ids[i]);
        EXPECT_TRUE(isFinite(p));
        EXPECT_LT(p.y, floorTop);
    }
}

/// The body of `scene` whose id is `id` (the test fails without one).
const BodyDef& bodyNamed(const Scene& scene, const std::string& id) {
    const auto found = std::find_if(scene.bodies.begin(), scene.bodies.end(),
                                    [&](const SceneBody& body) { return body.id == id; });
    EXPECT_NE(found, scene.bodies.end()) << id;
    static const BodyDef none;
    return found == scene.bodies.end() ? none : found->def;
}

TEST(ExampleScenes, SlopesHasRampsASegmentAndRoundBodies) {
    const Scene scene = loadScene(JOSTLE_SCENES_DIR "/slopes.json");
    EXPECT_EQ(scene.world.solver, Solver::Physical);
    EXPECT_GT(scene.world.gravity.y, 0.0f); // y grows downward
    // A 2:1 ramp falling to the right, a hill (a ramp up, a flat top, a ramp down, side
    // by side) and a 2:1 ramp rising to the right, all static.
    const BodyDef& slide = bodyNamed(scene, "slide");
    EXPECT_EQ(slide.slope, (Vec2{1, -1}));
    EXPECT_EQ(slide.hw, 2.0f * slide.hh);
    const BodyDef& up = bodyNamed(scene, "hillUp");
    const BodyDef& top = bodyNamed(scene, "hillTop");
    const BodyDef& down = bodyNamed(scene, "hillDown");
    EXPECT_EQ(up.slope, (Vec2{-1, -1}));
    EXPECT_EQ(top.slope, Vec2{});
    EXPECT_EQ(down.slope, (Vec2{1, -1}));
    EXPECT_EQ(up.x + up.hw, top.x - top.hw);
    EXPECT_EQ(top.x + top.hw, down.x - down.hw);
    EXPECT_EQ(up.y - up.hh, top.y - top.hh); // the ramps reach the flat top's height
    const BodyDef& bank = bodyNamed(scene, "bank");
    EXPECT_EQ(bank.slope, (Vec2{-1, -1}));
    EXPECT_EQ(bank.hw, 2.0f * bank.hh);
    const BodyDef& chute = bodyNamed(scene, "chute");
    EXPECT_TRUE(chute.segment);
    for (const BodyDef* ramp : {&slide, &up, &down, &bank, &chute})
        EXPECT_EQ(ramp->type, BodyType::Static);
    // A ball, a capsule, and crates whose friction with the bank (0.8) holds them.
    const BodyDef& ball = bodyNamed(scene, "ball");
    EXPECT_EQ(ball.type, BodyType::Dynamic);
    EXPECT_TRUE(ball.hw == ball.radius && ball.hh == ball.radius);
    const BodyDef& capsule = bodyNamed(scene, "capsule");
    EXPECT_TRUE(capsule.hw == capsule.radius && capsule.hh > capsule.radius);
    EXPECT_EQ(bank.friction, 0.8f);
    for (const char* crate : {"crate1", "crate2", "crate3"})
        EXPECT_EQ(bodyNamed(scene, crate).friction, 0.8f) << crate;

    World world(scene.world);
    const std::vector<BodyId> ids = addBodies(world, scene);
    EXPECT_EQ(ids.size(), scene.bodies.size());
    for (int i = 0; i < 60; ++i)
        world.step(scene.dt);
    for (BodyId id : ids)
        EXPECT_TRUE(isFinite(world.position(id)));
}

// Ten seconds of the slopes scene: the round bodies end on the floor or the ramps, none
// through them, and friction holds the crates on the bank where they were put.
TEST(ExampleScenes, SlopesKeepsEveryBodyInTheLevel) {
    const Scene scene = loadScene(JOSTLE_SCENES_DIR "/slopes.json");
    World world(scene.world);
    const std::vector<BodyId> ids = addBodies(world, scene);
    for (int i = 0; i < 600; ++i)
        world.step(scene.dt);
    const BodyDef& floor = bodyNamed(scene, "floor");
    for (std::size_t i = 0; i < ids.size(); ++i) {
        const BodyDef& def = scene.bodies[i].def;
        if (def.type != BodyType::Dynamic)
            continue;
        SCOPED_TRACE(scene.bodies[i].id);
        const Vec2 p = world.position(ids[i]);
        EXPECT_LE(p.y + def.hh, floor.y - floor.hh + 0.5f); // on the floor or above it
        EXPECT_GT(p.x, bodyNamed(scene, "leftWall").x);
        EXPECT_LT(p.x, bodyNamed(scene, "rightWall").x);
        if (scene.bodies[i].id.starts_with("crate")) { // friction holds them where they are
            EXPECT_LT(length(p - Vec2{def.x, def.y}), 5.0f);
        }
    }
}

} // namespace
} // namespace jostle
