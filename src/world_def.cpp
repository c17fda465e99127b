// Names of solvers and friction mixes, and the rules a WorldDef must follow (the rules of
// each option are world_options.hpp's).
#include "jostle/world.hpp"

#include "world_options.hpp"

#include <string>

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

/// A problem of a group of options, named as a member of WorldDef ("physical.slop").
std::optional<FieldError> within(const char* group, std::optional<FieldError> problem) {
    if (problem)
        problem->field = std::string(group) + "." + problem->field;
    return problem;
}

} // namespace

std::optional<FieldError> checkWorldDef(const WorldDef& def) {
    using namespace properties;
    if (auto problem = ruleProblem(def, kWorldFields))
        return problem;
    if (auto problem = within("tasks", ruleProblem(def.tasks, kTaskFields)))
        return problem;
    if ((def.tasks.enqueueTask == nullptr) != (def.tasks.finishTask == nullptr))
        return FieldError{"tasks", "enqueueTask and finishTask come together: both or neither"};
    if (auto problem = within("classic", ruleProblem(def.classic, kClassicFields)))
        return problem;
    return within("physical", ruleProblem(def.physical, kPhysicalFields));
}

static_assert(properties::defaultsAgree(WorldDef{}, properties::kWorldFields) &&
                  properties::defaultsAgree(TaskSystem{}, properties::kTaskFields) &&
                  properties::defaultsAgree(ClassicOptions{}, properties::kClassicFields) &&
                  properties::defaultsAgree(PhysicalOptions{}, properties::kPhysicalFields),
              "world_options.hpp's defaults are world.hpp's");

} // namespace jostle
