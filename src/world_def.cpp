// Names of solvers and the rules a WorldDef must follow.
#include "jostle/world.hpp"
#include "range_check.hpp"

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

const char* toString(FrictionMix mix) {
    switch (mix) {
    case FrictionMix::Min:
        return "min";
    case FrictionMix::GeometricMean:
        return "geometricMean";
    }
    return "unknown";
}

std::optional<FrictionMix> frictionMixFromString(const std::string& name) {
    for (FrictionMix mix : {FrictionMix::Min, FrictionMix::GeometricMean})
        if (name == toString(mix))
            return mix;
    return std::nullopt;
}

namespace {

std::optional<FieldError> checkPhysicalOptions(const PhysicalOptions& p) {
    auto error = [](const char* field, const char* problem) {
        return FieldError{std::string("physical.") + field, problem};
    };
    if (p.velocityIterations < 1 || p.velocityIterations > 1000)
        return error("velocityIterations", "must be in [1, 1000]");
    if (p.positionIterations < 0 || p.positionIterations > 1000)
        return error("positionIterations", "must be in [0, 1000]");
    if (p.maxContactsPerBody < 1 || p.maxContactsPerBody > 65536)
        return error("maxContactsPerBody", "must be in [1, 65536]");
    if (!(p.slop >= 0.0f && p.slop <= 0.5f))
        return error("slop", "must be in [0, 0.5]");
    if (!(p.correction > 0.0f && p.correction <= 1.0f))
        return error("correction", "must be in (0, 1]");
    if (!(p.restitutionThreshold >= 0.0f) || std::isinf(p.restitutionThreshold))
        return error("restitutionThreshold", "must be a finite number >= 0");
    if (p.frictionMix != FrictionMix::Min && p.frictionMix != FrictionMix::GeometricMean)
        return error("frictionMix", "must be min or geometricMean");
    return std::nullopt;
}

} // namespace

std::optional<FieldError> checkWorldDef(const WorldDef& def) {
    if (const char* problem = rangeProblem(def.gravity))
        return FieldError{"gravity", problem};
    // Infinity is allowed here: it is how "no clamp" is spelt.
    if (std::isnan(def.maxVelocity) || def.maxVelocity <= 0.0f)
        return FieldError{"maxVelocity", "must be > 0"};
    if (def.solver != Solver::Classic && def.solver != Solver::Physical)
        return FieldError{"solver", "must be classic or physical"};
    if (def.tasks.workers < 1 || def.tasks.workers > 64)
        return FieldError{"tasks.workers", "must be in [1, 64]"};
    if ((def.tasks.enqueueTask == nullptr) != (def.tasks.finishTask == nullptr))
        return FieldError{"tasks", "enqueueTask and finishTask come together: both or neither"};
    return checkPhysicalOptions(def.physical);
}

} // namespace jostle
