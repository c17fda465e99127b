// The tables of src/body_properties.hpp and src/world_options.hpp: every row of every
// table (a body's property, a tile map's setting, a world's option) reaches the world and
// comes back through C++ and through the C API, the defaults are the definitions', and the
// checks driven by the tables report in the order they always have. (Scene files walk the
// same rows in tests/scene/test_scene.cpp; Lua and JavaScript in bindings/lua/tests/
// test_rows.lua and bindings/web/tests/js_api.js, from jostle-test-rows.)
#include "c_api/c_api.hpp"
#include "property_samples.hpp"
#include "world_access.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

namespace jostle {
namespace {

using properties::kBodyFields;
using properties::kTileMapFields;
using test_support::forEachWorldTable;
using test_support::partOf;
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

/// A world's definition as it gives it back: through World's getters, and through the C
/// API's.
WorldDef definitionOf(const World& world) {
    WorldDef def{.gravity = world.gravity(),
                 .maxVelocity = world.maxVelocity(),
                 .solver = world.solver(),
                 .classic = world.classicOptions(),
                 .physical = world.physicalOptions(),
                 .sleeping = world.sleeping()};
    def.tasks.workers = world.workers();
    return def;
}
WorldDef definitionOf(const jostle_world* world) {
    jostle_world_def def = jostle_default_world_def();
    def.gravity = jostle_world_get_gravity(world);
    def.max_velocity = jostle_world_get_max_velocity(world);
    def.solver = jostle_world_get_solver(world);
    def.classic = jostle_world_get_classic_options(world);
    def.physical = jostle_world_get_physical_options(world);
    def.sleeping = jostle_world_get_sleeping(world);
    def.tasks.workers = jostle_world_get_workers(world);
    return c_api::toCpp(def);
}

TEST(Properties, NamesAreUniqueAndFound) {
    test_support::forEachTable([](const char*, const auto& fields) {
        for (const auto& field : fields)
            EXPECT_EQ(properties::find(fields, field.property->name), &field);
    });
    EXPECT_EQ(properties::find(kBodyFields, "rows"), nullptr);
}

// No sample is its row's default, so that a row given back as its default (not read, not
// kept, not carried) fails every test that walks the tables.
TEST(Properties, EverySampleIsNotItsDefault) {
    test_support::forEachTable([](const char* table, const auto& fields) {
        for (const auto& field : fields) {
            const properties::Property& property = *field.property;
            EXPECT_FALSE(sampleOf(property) == property.byDefault) << table << "." << property.name;
        }
    });
}

// An interval's words are made from its bounds.
static_assert(std::string_view(properties::kVelocityIterations.range.words) ==
              "must be in [1, 1000]");
static_assert(std::string_view(properties::kSlop.range.words) == "must be in [0, 0.5]");
static_assert(std::string_view(properties::kCorrection.range.words) == "must be in (0, 1]");

TEST(Properties, DefaultsAreThoseOfTheDefinitionsAndOfTheCApi) {
    EXPECT_TRUE(properties::defaultsAgree(BodyDef{}, kBodyFields));
    EXPECT_TRUE(properties::defaultsAgree(TileMapDef{}, kTileMapFields));
    expectSameFields(BodyDef{}, c_api::toCpp(jostle_default_body_def()), "C default");
    TileMapDef map;
    c_api::copyFromC(jostle_default_tile_map_def(), map, kTileMapFields);
    EXPECT_TRUE(properties::defaultsAgree(map, kTileMapFields));
    WorldDef world = c_api::toCpp(jostle_default_world_def());
    forEachWorldTable([&](const char* table, const auto& fields) {
        EXPECT_TRUE(properties::defaultsAgree(partOf(world, fields[0]), fields)) << table;
    });
}

TEST(Properties, TheWorldKeepsEveryProperty) {
    World world;
    for (const auto& field : kBodyFields) {
        const BodyDef def = bodyWithSample(field);
        ASSERT_FALSE(checkBodyDef(def)) << field.property->name;
        expectSameFields(def, world.bodyDef(world.createBody(def)), field.property->name);
    }
}

// The world's counts of bodies that are shaped, snap, are conveyors or slip round corners
// follow every way a body comes, changes and goes.
TEST(Properties, TheCountsOfBodiesFollowTheirSettings) {
    World world;
    const WorldState& w = WorldAccess::state(world);
    auto expectCounted = [&](const char* when) {
        std::uint32_t shaped = 0, snapping = 0, conveyors = 0, corners = 0;
        for (const BodyId id : world.bodies()) {
            const Body& body = w.slots[id.index];
            shaped += !body.isBox();
            snapping += body.maySnap();
            conveyors += body.surfaceVelocity != Vec2{};
            corners += w.asGiven[id.index].slipsRoundCorners();
        }
        EXPECT_EQ(w.shapedBodies, shaped) << when;
        EXPECT_EQ(w.snappingBodies, snapping) << when;
        EXPECT_EQ(w.conveyors, conveyors) << when;
        EXPECT_EQ(w.cornerBodies, corners) << when;
    };
    for (const auto& field : kBodyFields)
        world.createBody(bodyWithSample(field));
    expectCounted("created");
    for (const BodyId id : std::vector<BodyId>(world.bodies().begin(), world.bodies().end())) {
        world.setSnapDown(id, world.snapDown(id) > 0.0f ? 0.0f : 2.0f);
        if (!world.isCharacter(id))
            world.setCharacter(id, true);
        world.setStepUp(id, 1.0f);
        world.setCornerCorrection(id, 0.0f);
        if (world.type(id) != BodyType::Dynamic)
            world.setSurfaceVelocity(id, world.surfaceVelocity(id) != Vec2{} ? Vec2{} : Vec2{1, 0});
    }
    expectCounted("changed");
    while (world.bodyCount() > 0)
        world.destroyBody(world.bodies().front());
    expectCounted("destroyed");
    EXPECT_EQ(w.shapedBodies + w.snappingBodies + w.conveyors + w.cornerBodies, 0u);
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

TEST(Properties, TheWorldKeepsEveryTileMapSetting) {
    World world;
    const jostle_world_def cWorldDef = jostle_default_world_def();
    jostle_world* cWorld = jostle_world_create(&cWorldDef);
    const unsigned char cells[] = {'#'};
    for (const auto& field : kTileMapFields) {
        const char* name = field.property->name;
        TileMapDef def{.tile = 1, .rows = {"#"}};
        setValue(def, field, sampleOf(*field.property));
        ASSERT_FALSE(checkTileMapDef(def)) << name;
        const TileMapId made = createTileMap(world, def);
        EXPECT_TRUE(valueOf(tileMapDef(world, made), field) == valueOf(def, field)) << name;
        // Its bodies take the settings a body has too, but the map's corner.
        const properties::BodyField* bodyField = properties::find(kBodyFields, *field.property);
        if (bodyField && field.property != &properties::kX && field.property != &properties::kY) {
            ASSERT_EQ(tileMapBodies(world, made).size(), 1u) << name;
            EXPECT_TRUE(valueOf(world.bodyDef(tileMapBodies(world, made)[0]), *bodyField) ==
                        valueOf(def, field))
                << name;
        }
        // The C struct carries it to the world.
        jostle_tile_map_def c = jostle_default_tile_map_def();
        c_api::copyToC(def, c, kTileMapFields);
        c.columns = 1;
        c.rows = 1;
        c.cells = cells;
        const TileMapId map = c_api::toCpp(jostle_tile_map_create(cWorld, &c));
        ASSERT_TRUE(cWorld->world.isValid(map)) << name << ": " << jostle_last_error();
        EXPECT_TRUE(valueOf(tileMapDef(cWorld->world, map), field) == valueOf(def, field)) << name;
    }
    jostle_world_destroy(cWorld);
}

TEST(Properties, TheWorldKeepsEveryOption) {
    forEachWorldTable([](const char* table, const auto& fields) {
        for (const auto& field : fields) {
            const std::string name = std::string(table) + "." + field.property->name;
            WorldDef def;
            setValue(partOf(def, field), field, sampleOf(*field.property));
            ASSERT_FALSE(checkWorldDef(def)) << name;
            const properties::Value sample = valueOf(partOf(def, field), field);
            WorldDef got = definitionOf(World(def));
            EXPECT_TRUE(valueOf(partOf(got, field), field) == sample) << name;
            // The C struct carries it to the world and back.
            const jostle_world_def c = c_api::toC(def);
            jostle_world* world = jostle_world_create(&c);
            ASSERT_NE(world, nullptr) << name << ": " << jostle_last_error();
            got = definitionOf(world);
            EXPECT_TRUE(valueOf(partOf(got, field), field) == sample) << name;
            jostle_world_destroy(world);
        }
    });
}

// The rules of the world's options report as checkWorldDef always has.
TEST(Properties, WorldOptionsReportTheirRanges) {
    auto problem = [](WorldDef def) {
        auto found = checkWorldDef(def);
        return found ? found->field + ": " + found->problem : "ok";
    };
    EXPECT_EQ(problem({.gravity = {kNaN, 0}}), "gravity: must be finite numbers");
    EXPECT_EQ(problem({.maxVelocity = 0}), "maxVelocity: must be > 0");
    EXPECT_EQ(problem({.maxVelocity = kNaN}), "maxVelocity: must be > 0");
    EXPECT_EQ(problem({.maxVelocity = std::numeric_limits<float>::infinity()}), "ok");
    EXPECT_EQ(problem({.solver = static_cast<Solver>(7)}), "solver: must be classic or physical");
    EXPECT_EQ(problem({.tasks = {.workers = 65}}), "tasks.workers: must be in [1, 64]");
    EXPECT_EQ(problem({.physical = {.velocityIterations = 0}}),
              "physical.velocityIterations: must be in [1, 1000]");
    EXPECT_EQ(problem({.physical = {.positionIterations = -1}}),
              "physical.positionIterations: must be in [0, 1000]");
    EXPECT_EQ(problem({.physical = {.slop = kNaN}}), "physical.slop: must be in [0, 0.5]");
    EXPECT_EQ(problem({.physical = {.correction = 0}}), "physical.correction: must be in (0, 1]");
    EXPECT_EQ(problem({.physical = {.restitutionThreshold = -1}}),
              "physical.restitutionThreshold: must be a finite number >= 0");
    EXPECT_EQ(problem({.physical = {.restitutionThreshold = 1e30f}}), "ok");
    EXPECT_EQ(problem({.physical = {.frictionMix = static_cast<FrictionMix>(5)}}),
              "physical.frictionMix: must be min or geometricMean");
    EXPECT_EQ(problem({.physical = {.maxContactsPerBody = 65537}}),
              "physical.maxContactsPerBody: must be in [1, 65536]");
    // In checkWorldDef's order: the contact budget before the slop.
    EXPECT_EQ(problem({.physical = {.slop = 1, .maxContactsPerBody = 0}}),
              "physical.maxContactsPerBody: must be in [1, 65536]");
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
