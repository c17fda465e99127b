// How run and render load their scene: the file, in the model --solver asks for.
#pragma once

#include "jostle/scene.hpp"

#include <string>

namespace jostle::cli {

/// The scene file at `path`, in the model named by `solver` ("classic", "physical", as
/// --solver checked it), or in the file's own model if `solver` is empty. Throws what
/// jostle::loadScene throws.
inline Scene loadScene(const std::string& path, const std::string& solver) {
    Scene scene = jostle::loadScene(path);
    if (!solver.empty())
        scene.world.solver = solverFromString(solver).value();
    return scene;
}

} // namespace jostle::cli
