// How run, render and synctest load their scene: a scene file or a Tiled map (.tmj, .tmx),
// in the model --solver asks for.
#pragma once

#include "jostle/level.hpp"
#include "jostle/scene.hpp"

#include <string>

namespace jostle::cli {

/// True if `path` names a Tiled map: .tmj or .tmx (a Tiled map saved as .json is read
/// as a scene file: name it .tmj).
inline bool isTiledMap(const std::string& path) {
    return path.ends_with(".tmj") || path.ends_with(".tmx");
}

/// The scene of the file at `path`, in the model named by `solver` ("classic",
/// "physical", as --solver checked it), or in the file's own model if `solver` is empty.
/// Throws what jostle::loadScene and jostle::loadTiled throw.
inline Scene loadScene(const std::string& path, const std::string& solver) {
    Scene scene = isTiledMap(path) ? jostle::loadTiled(path).scene : jostle::loadScene(path);
    if (!solver.empty())
        scene.world.solver = solverFromString(solver).value();
    return scene;
}

} // namespace jostle::cli
