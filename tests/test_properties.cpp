// The property tables of src/body_properties.hpp: every property reaches the world and
// comes back through World and through the C API, the defaults are the definitions', and
// the checks driven by the tables report in the order they always have.
#include "c_api/c_api.hpp"
#include "property_samples.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

namespace jostle {
namespace {

using properties::kBodyFields;
using properties::kTileMapFields;
using test_support::sampleNeeds;
using test_support::sampleOf;
using test_support::setValue;
using test_support::valueOf;

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

/// A valid body with `field` set to its sample value (and what the sample needs besides).
BodyDef bodyWithSample(const properties::BodyField& field) {
    BodyDef def{.hw = 1, .hh = 1};
    for (const auto& [property, value] : sampleNeeds(*field.property))
        setValue(def, *properties::find(kBodyFields, property->name), value);
    setValue(def, field, sampleOf(*field.property));
    return def;
}

/// Expects `got` to hold every field of `expected`.
void expectSameFields(const BodyDef& expected, const BodyDef& got, const std::string& context) {
    for (const auto& field : kBodyFields)
        EXPECT_TRUE(valueOf(got, field) == valueOf(expected, field))
            << context << ": " << field.property->name;
}

TEST(Properties, NamesAreUniqueAndFound) {
    for (const auto& field : kBodyFields)
        EXPECT_EQ(properties::find(kBodyFields, field.property->name), &field);
    for (const auto& field : kTileMapFields)
        EXPECT_EQ(properties::find(kTileMapFields, field.property->name), &field);
    EXPECT_EQ(properties::find(kBodyFields, "rows"), nullptr);
}

TEST(Properties, DefaultsAreThoseOfTheDefinitionsAndOfTheCApi) {
    EXPECT_TRUE(properties::defaultsAgree(BodyDef{}, kBodyFields));
    EXPECT_TRUE(properties::defaultsAgree(TileMapDef{}, kTileMapFields));
    expectSameFields(BodyDef{}, c_api::toCpp(jostle_default_body_def()), "C default");
    const jostle_tile_map_def map = jostle_default_tile_map_def();
    EXPECT_EQ(map.friction, TileMapDef{}.friction);
    EXPECT_EQ(map.mask, TileMapDef{}.mask);
}

TEST(Properties, TheWorldKeepsEveryProperty) {
    World world;
    for (const auto& field : kBodyFields) {
        const BodyDef def = bodyWithSample(field);
        ASSERT_FALSE(checkBodyDef(def)) << field.property->name;
        expectSameFields(def, world.bodyDef(world.createBody(def)), field.property->name);
    }
}

TEST(Properties, TheCApiCarriesEveryProperty) {
    const jostle_world_def worldDef = jostle_default_world_def();
    jostle_world* world = jostle_world_create(&worldDef);
    for (const auto& field : kBodyFields) {
        const BodyDef def = bodyWithSample(field);
        const jostle_body_def c = c_api::toC(def);
        const jostle_body_id id = jostle_body_create(world, &c);
        ASSERT_TRUE(jostle_body_is_valid(world, id)) << field.property->name;
        expectSameFields(def, c_api::toCpp(jostle_body_get_def(world, id)), field.property->name);
    }
    jostle_world_destroy(world);
}

// Fields side by side under one rule take each check in turn (both half extents > 0
// before either's minimum), while a setter checks its argument's numbers one by one.
TEST(Properties, ChecksReportInTheirOrder) {
    auto problem = [](BodyDef def) {
        auto found = checkBodyDef(def);
        return found ? found->field + ": " + found->problem : "ok";
    };
    EXPECT_EQ(problem({.hw = 1e-10f, .hh = -1}), "hh: must be > 0");
    EXPECT_EQ(problem({.hw = 1e-10f, .hh = 1e-10f}), "hw: must be >= 1e-9");
    EXPECT_EQ(problem({.hw = 1, .hh = 1, .mass = 1e-10f, .density = 0}),
              "mass: must be 0 (from density) or >= 1e-9");
    EXPECT_EQ(problem({.type = static_cast<BodyType>(9), .x = kNaN}),
              "type: must be static, kinematic or dynamic");
    EXPECT_EQ(problem({.hw = 0, .oneWay = {kNaN, 0}}), "oneWay: must be a finite number");

    World world;
    const BodyId body = world.createBody({.hw = 1, .hh = 1});
    auto setterProblem = [&](auto set) {
        try {
            set();
        } catch (const Error& error) {
            return std::string(error.what());
        }
        return std::string("ok");
    };
    EXPECT_EQ(setterProblem([&] {
                  world.setHalfExtents(body, {1e-10f, -1});
              }),
              "setHalfExtents: halfExtents.x must be >= 1e-9");
    EXPECT_EQ(setterProblem([&] { world.setBounce(body, kNaN); }),
              "setBounce: bounce must be in [0, 1]");
    EXPECT_EQ(setterProblem([&] { world.setMass(body, 0); }), "setMass: mass must be > 0");
    EXPECT_EQ(setterProblem([&] { world.setGravityScale(body, kNaN); }),
              "setGravityScale: scale must be a finite number");
    EXPECT_EQ(setterProblem([&] { world.setType(body, static_cast<BodyType>(9)); }),
              "setType: type must be static, kinematic or dynamic");
}

} // namespace
} // namespace jostle
