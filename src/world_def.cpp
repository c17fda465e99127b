// Names of solvers and the rules a WorldDef must follow.
#include "jostle/world.hpp"

#include <cmath>

namespace jostle {

const char* toString(Solver solver) {
    switch (solver) {
    case Solver::Classic:
        return "classic";
    case Solver::Physical:
        return "physical";
    }
    return "unknown";
}

std::optional<Solver> solverFromString(const std::string& name) {
    for (Solver solver : {Solver::Classic, Solver::Physical})
        if (name == toString(solver))
            return solver;
    return std::nullopt;
}

std::optional<FieldError> checkWorldDef(const WorldDef& def) {
    if (!isFinite(def.gravity))
        return FieldError{"gravity", "must be finite numbers"};
    // Infinity is allowed here: it is how "no clamp" is spelt.
    if (std::isnan(def.maxVelocity) || def.maxVelocity <= 0.0f)
        return FieldError{"maxVelocity", "must be > 0"};
    if (def.solver != Solver::Classic && def.solver != Solver::Physical)
        return FieldError{"solver", "must be classic or physical"};
    return std::nullopt;
}

} // namespace jostle
