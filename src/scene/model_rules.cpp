// Scene files: what the classic model refuses (model_rules.hpp).
#include "model_rules.hpp"

#include "json.hpp"
#include "tile_chars.hpp"

namespace jostle::scene_file {

using namespace json;

namespace {

/// Why a world in the classic model refuses a shape: it has sharp boxes only (createBody,
/// createTileMap, setTile and setSolver refuse the others there).
constexpr const char* kSharpBoxesOnly =
    R"(the classic model has sharp boxes only (solver "classic"))";

} // namespace

std::optional<FieldError> modelProblem(Solver solver, const std::vector<SceneBody>& bodies) {
    if (solver != Solver::Classic)
        return std::nullopt;
    for (std::size_t i = 0; i < bodies.size(); ++i) {
        const BodyDef& def = bodies[i].def;
        const char* shape = def.slope != Vec2{} ? "slope" : def.radius > 0.0f ? "radius" : nullptr;
        if (shape)
            return FieldError{field(element("bodies", i), shape), kSharpBoxesOnly};
    }
    return std::nullopt;
}

std::optional<FieldError> modelProblem(Solver solver, const std::vector<TileMapDef>& maps,
                                       const std::function<std::string(std::size_t)>& placeOf) {
    if (solver != Solver::Classic)
        return std::nullopt;
    for (std::size_t i = 0; i < maps.size(); ++i) {
        const std::vector<std::string>& rows = maps[i].rows;
        for (std::size_t row = 0; row < rows.size(); ++row)
            for (std::size_t column = 0; column < rows[row].size(); ++column)
                if (rampTile(rows[row][column]))
                    return FieldError{element(element(field(placeOf(i), "rows"), row), column),
                                      kSharpBoxesOnly};
    }
    return std::nullopt;
}

} // namespace jostle::scene_file
