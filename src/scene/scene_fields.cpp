// Scene files: what each field of a scene means, and the checks of a body, a tile map and
// the whole world when each ends (reader_state.hpp; the events are scene_reader.cpp's).
//
// The value rules of bodies and worlds are not repeated here: checkBodyDef and
// checkWorldDef are the one source of truth, and this file only adds the place and writes
// their words in JSON's notation (notation.hpp: [0, -1], not {0, -1}).
#include "model_rules.hpp"
#include "notation.hpp"
#include "reader_state.hpp"

#include <optional>
#include <string>

namespace jostle::scene_file {

namespace {

/// Fails at `place` with a rule of the C++ library (checkBodyDef, ...), in JSON's notation.
[[noreturn]] void failRule(const std::string& place, const std::string& rule) {
    fail(place, inNotation(rule, Notation::Json));
}

/// Fails unless the object of `frame` has every field its definition requires, in table
/// order.
template <class F, std::size_t N> void requireFields(const Frame& frame, const F (&fields)[N]) {
    for (std::size_t i = 0; i < N; ++i)
        if (fields[i].property->required && !frame.has(i))
            fail(frame.place, std::string("missing field \"") + fields[i].property->name + "\"");
}

} // namespace

void SceneReader::takeSceneField(const Frame& frame, const Json& v) {
    const std::string& name = frame.key;
    if (frame.field < kWorldRows) {
        takeOption(scene_.world, properties::kWorldFields[frame.field], v, name);
        return;
    }
    switch (frame.field) {
    case kDt:
        scene_.dt = readFloat(v, name);
        if (!(scene_.dt > 0.0f))
            fail(name, "must be > 0");
        if (scene_.dt < kMinMagnitude || scene_.dt > kMaxMagnitude)
            fail(name, "must be in [1e-9, 1e9]"); // what World::step accepts
        break;
    case kBodies:
    case kTileMaps:
        failType(v, name, "an array");
    default: // classic, physical, tilemap
        failType(v, name, "an object");
    }
}

void SceneReader::endBody(Frame& frame) {
    using properties::kBodyFields;
    requireFields(frame, kBodyFields); // hw, hh: a box has no default size

    // In a file, 0 is not a way to ask for the density mass (BodyDef's convention):
    // leaving "mass" out is. And a body cannot have both an explicit mass and a density.
    static const std::size_t kMass = fileFieldIndex(kBodyFields, "mass");
    static const std::size_t kDensity = fileFieldIndex(kBodyFields, "density");
    const bool mass = frame.has(kMass);
    if (mass && frame.has(kDensity))
        fail(frame.place, R"(give "mass" or "density", not both)");
    if (mass && !(frame.body.def.mass > 0.0f))
        fail(field(frame.place, "mass"), "must be > 0");

    if (auto problem = checkBodyDef(frame.body.def))
        failRule(field(frame.place, problem->field), problem->problem);

    scene_.bodies.push_back(std::move(frame.body));
    if (const std::size_t owner = ids_.insert(scene_.bodies.size() - 1); owner != kNone) {
        const bool explicitId = frame.has(kIdField);
        fail(explicitId ? field(frame.place, "id") : frame.place,
             (explicitId ? "" : "its default id ") + quoteName(scene_.bodies.back().id) +
                 " is already the id of " + element("bodies", owner));
    }
}

void SceneReader::endTileMap(Frame& frame) {
    // A map has no sensible default tile size, nor default tiles.
    requireFields(frame, properties::kTileMapFields);
    if (!frame.has(kRowsField))
        fail(frame.place, R"(missing field "rows")");
    if (auto problem = checkTileMapDef(frame.map))
        failRule(field(frame.place, problem->field), problem->problem);
    scene_.tileMaps.push_back(std::move(frame.map));
}

Scene SceneReader::finish() {
    if ((sceneFields_ >> kBodies & 1u) == 0)
        fail("", R"(missing field "bodies")");
    if (auto problem = checkWorldDef(scene_.world)) {
        std::string rule = problem->problem;
        for (const auto& [place, text] : written_)
            if (place == problem->field)
                rule += ", got " + text;
        failRule(problem->field, rule);
    }
    // Only now is the model known ("solver" may come last); its problems are looked for
    // in file order, bodies and tile maps alike.
    for (const std::size_t name : order_) {
        std::optional<FieldError> problem;
        if (name == kBodies)
            problem = modelProblem(scene_.world.solver, scene_.bodies);
        else
            problem = modelProblem(scene_.world.solver, scene_.tileMaps, [&](std::size_t i) {
                const std::string place(kSceneOwnFields[name - kWorldRows]);
                return name == kTileMap ? place : element(place, i);
            });
        if (problem)
            failRule(problem->field, problem->problem);
    }
    return std::move(scene_);
}

} // namespace jostle::scene_file
