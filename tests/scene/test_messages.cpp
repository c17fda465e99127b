// Messages that say one rule in each language's own words (docs/reliability.md, "Misuse of
// the APIs"): an unknown field with the known one it was probably meant to be
// (src/suggest.hpp), values in each language's notation and places in its counting
// (src/notation.hpp, src/tile_rows.hpp). C++'s and scene files' messages here; the same
// cases for C, Lua and JavaScript are in tests/c/test_c_api.c, bindings/lua/tests/
// test_errors.lua and bindings/web/tests/js_api.js.
#include "jostle/scene.hpp"
#include "jostle/tilemap.hpp"
#include "jostle/world.hpp"
#include "notation.hpp"
#include "suggest.hpp"

#include <gtest/gtest.h>

#include <functional>
#include <initializer_list>
#include <string>
#include <string_view>

namespace jostle {
namespace {

/// The message of the jostle::Error that `call` throws ("" if it throws none).
std::string errorOf(const std::function<void()>& call) {
    try {
        call();
    } catch (const Error& error) {
        return error.what();
    }
    return "";
}

/// The message of the SceneError that parsing `json` throws ("" if it throws none).
std::string sceneErrorOf(const std::string& json) {
    try {
        parseScene(json);
    } catch (const SceneError& error) {
        return error.what();
    }
    return "";
}

/// The suggestion for `name` among `known`, or "".
std::string suggestion(std::string_view name, std::initializer_list<std::string_view> known) {
    NearestName nearest(name);
    for (std::string_view k : known)
        nearest.consider(k);
    return std::string(nearest.name());
}

// --- The rules, once -----------------------------------------------------------------

TEST(Messages, EditsCountInsertsDeletesReplacementsAndSwapsWithoutCase) {
    EXPECT_EQ(nameEdits("snapdown", "snapDown", true), 0u);
    EXPECT_EQ(nameEdits("snapdown", "snapDown", false), 1u);
    EXPECT_EQ(nameEdits("frcition", "friction", true), 1u); // a swap is one edit
    EXPECT_EQ(nameEdits("gravty", "gravity", true), 1u);
    EXPECT_EQ(nameEdits("masses", "mass", true), 2u);
    EXPECT_EQ(nameEdits("mas", "mask", true), 1u);
    // Beyond two edits, all are the same: not near.
    EXPECT_EQ(nameEdits("colour", "bounce", true), kMaxSuggestionEdits + 1);
    EXPECT_EQ(nameEdits("tileWidth", "tile", true), kMaxSuggestionEdits + 1);
}

TEST(Messages, TheNearestKnownNameWithinTwoEditsIsSuggested) {
    EXPECT_EQ(suggestion("snapdown", {"snapDown", "slope"}), "snapDown");
    EXPECT_EQ(suggestion("SNAPDOWN", {"snapDown"}), "snapDown");
    EXPECT_EQ(suggestion("foo", {"x", "y", "hw", "hh", "bounce"}), "");
    // Fewer edits than the shorter name has characters: "z" is no typo of "x".
    EXPECT_EQ(suggestion("z", {"x", "y"}), "");
    EXPECT_EQ(suggestion("id", {"x"}), "");
    // The fewest edits; then the fewest counting case; then the first offered.
    EXPECT_EQ(suggestion("frictoin", {"fraction", "friction"}), "friction");
    EXPECT_EQ(suggestion("masq", {"mass", "mask"}), "mass");
    EXPECT_EQ(suggestion("mas", {"mass", "mask"}), "mass");
    EXPECT_EQ(suggestion("Gravty", {"gravity", "Gravity"}), "Gravity");
    EXPECT_EQ(didYouMean("snapDown"), R"( (did you mean "snapDown"?))");
    EXPECT_EQ(didYouMean(""), "");
}

TEST(Messages, EachLanguageWritesARuleInItsOwnNotation) {
    const std::string rule = "must be {0, 0} or one of {1, 0}, {-1, 0}, {0, 1}, {0, -1}";
    EXPECT_EQ(inNotation(rule, Notation::Cpp), rule);
    EXPECT_EQ(inNotation(rule, Notation::Lua), rule);
    EXPECT_EQ(inNotation(rule, Notation::Json),
              "must be [0, 0] or one of [1, 0], [-1, 0], [0, 1], [0, -1]");
    EXPECT_EQ(inNotation(rule, Notation::JavaScript), inNotation(rule, Notation::Json));
    const std::string character = "a dynamic body with BodyDef::character = true";
    EXPECT_EQ(inNotation(character, Notation::Cpp), character);
    EXPECT_EQ(inNotation(character, Notation::Lua), "a dynamic body with character = true");
    EXPECT_EQ(inNotation(character, Notation::Json), R"(a dynamic body with "character": true)");
    EXPECT_EQ(inNotation(character, Notation::JavaScript), "a dynamic body with character: true");
    // An interval is no vector; what is quoted is the caller's and kept.
    EXPECT_EQ(inNotation("must be in [0, 1]", Notation::Json), "must be in [0, 1]");
    EXPECT_EQ(inNotation("expected '#', '.' or a ramp, got '{'", Notation::Json),
              "expected '#', '.' or a ramp, got '{'");
    EXPECT_EQ(inNotation(R"(unknown field "{\"}" near {0, 0})", Notation::Json),
              R"(unknown field "{\"}" near [0, 0])");
    char cut[12];
    copyInNotation(rule, Notation::Json, cut, sizeof cut);
    EXPECT_EQ(std::string(cut), "must be [0,");
}

// --- C++: {0, 0}, rows counted from 0 ------------------------------------------------

TEST(Messages, CppNamesTheRuleInItsNotationAndCounting) {
    World world;
    EXPECT_EQ(errorOf([&] {
                  world.createBody({.hw = 1, .hh = 1, .oneWay = {1, 1}});
              }),
              "createBody: BodyDef.oneWay: must be {0, 0} or one of {1, 0}, {-1, 0}, {0, 1}, "
              "{0, -1}");
    const BodyId crate = world.createBody({.hw = 1, .hh = 1});
    EXPECT_EQ(errorOf([&] {
                  world.setOneWay(crate, {1, 1});
              }),
              "setOneWay: normal must be {0, 0} or one of {1, 0}, {-1, 0}, {0, 1}, {0, -1}");
    EXPECT_EQ(errorOf([&] {
                  world.createBody({.hw = 1, .hh = 1, .slope = {1, 0}});
              }),
              "createBody: BodyDef.slope: must be {0, 0} or each component -1 or 1");
    TileMapDef ragged;
    ragged.tile = 16;
    ragged.rows = {"#..#", "###"};
    EXPECT_EQ(errorOf([&] { createTileMap(world, ragged); }),
              "createTileMap: TileMapDef.rows[1]: has 3 columns, rows[0] has 4");
    EXPECT_EQ(errorOf([&] { world.setWalkSpeed(crate, 50); }),
              "setWalkSpeed: the body is not a character (a dynamic body with "
              "BodyDef::character = true)");
    EXPECT_EQ(world.bodyCount(), 1u);
}

// --- Scene files: JSON's [0, 0], rows counted from 0, did you mean -------------------

TEST(Messages, SceneFilesNameTheRuleInJson) {
    EXPECT_EQ(sceneErrorOf(R"({"bodies": [{"hw": 1, "hh": 1, "snapdown": 4}]})"),
              R"(bodies[0]: unknown field "snapdown" (did you mean "snapDown"?))");
    EXPECT_EQ(sceneErrorOf(R"({"bodies": [{"hw": 1, "hh": 1, "foo": 4}]})"),
              R"(bodies[0]: unknown field "foo")");
    EXPECT_EQ(sceneErrorOf(R"({"bodies": [{"hw": 1, "hh": 1, "oneWay": [1, 1]}]})"),
              "bodies[0].oneWay: must be [0, 0] or one of [1, 0], [-1, 0], [0, 1], [0, -1]");
    EXPECT_EQ(sceneErrorOf(R"({"bodies": [], "tilemap": {"tile": 16, "rows": ["#..#", "###"]}})"),
              "tilemap.rows[1]: has 3 columns, rows[0] has 4");
    // Every kind of object suggests among its own fields.
    EXPECT_EQ(sceneErrorOf(R"({"bodies": [], "Gravity": [0, 1]})"),
              R"(unknown field "Gravity" (did you mean "gravity"?))");
    EXPECT_EQ(sceneErrorOf(R"({"bodies": [], "physical": {"slopp": 1}})"),
              R"(physical: unknown field "slopp" (did you mean "slop"?))");
    EXPECT_EQ(sceneErrorOf(R"({"bodies": [], "classic": {"cdd": true}})"),
              R"(classic: unknown field "cdd" (did you mean "ccd"?))");
    EXPECT_EQ(sceneErrorOf(R"({"bodies": [], "tilemap": {"tiles": 16, "rows": ["#"]}})"),
              R"(tilemap: unknown field "tiles" (did you mean "tile"?))");
    EXPECT_EQ(sceneErrorOf(R"({"bodies": [], "tilemap": {"tile": 16, "row": ["#"]}})"),
              R"(tilemap: unknown field "row" (did you mean "rows"?))");
    EXPECT_EQ(sceneErrorOf(R"({"bodies": [{"hw": 1, "hh": 1, "ID": "a"}]})"),
              R"(bodies[0]: unknown field "ID" (did you mean "id"?))");
    // userData has no form in a file: never suggested there.
    EXPECT_EQ(sceneErrorOf(R"({"bodies": [{"hw": 1, "hh": 1, "userdata": 1}]})"),
              R"(bodies[0]: unknown field "userdata")");
    // A character the caller wrote is theirs, brace or not.
    EXPECT_EQ(sceneErrorOf(R"({"bodies": [], "tilemap": {"tile": 16, "rows": ["#{"]}})"),
              "tilemap.rows[0][1]: expected '#', '.' or a ramp, got '{'");
}

} // namespace
} // namespace jostle
