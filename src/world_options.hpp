// Every option of a world, described once (properties.hpp has what a description is): its
// name, type, rule (with its range, written here alone) and default, bound to the member of
// WorldDef, TaskSystem, ClassicOptions or PhysicalOptions that holds it and to the member
// of its C struct. checkWorldDef, the scene loader, the C API's conversions and the Lua
// module walk these tables: a new option is one Property, one row, and its behaviour.
#pragma once

#include "jostle/jostle.h"
#include "jostle/tasks.hpp"
#include "jostle/world.hpp"
#include "properties.hpp"

#include <limits>

namespace jostle::properties {

// WorldDef's own members; ClassicOptions, PhysicalOptions and TaskSystem below.
inline constexpr Property kGravity{"gravity", Rule::Finite, Vec2{}};
inline constexpr Property kMaxVelocity{"maxVelocity", Rule::PositiveOrInfinity,
                                       std::numeric_limits<float>::infinity()};
inline constexpr Property kSolver{"solver", Rule::Any, Solver::Physical};
inline constexpr Property kSleeping{"sleeping", Rule::Any, true};

// TaskSystem's: the threads a world steps on. Its functions are the game's job system, a
// C++ and C matter: not settings of a scene file or a Lua table.
inline constexpr Property kWorkers = inInterval("workers", 1, {1, 64});

// ClassicOptions'.
inline constexpr Property kClassicMass{"mass", Rule::Any, false};
inline constexpr Property kCoulomb{"coulomb", Rule::Any, false};
inline constexpr Property kCcd{"ccd", Rule::Any, false};

// PhysicalOptions'.
inline constexpr Property kVelocityIterations = inInterval("velocityIterations", 4, {1, 1000});
inline constexpr Property kPositionIterations = inInterval("positionIterations", 3, {0, 1000});
inline constexpr Property kMaxContactsPerBody = inInterval("maxContactsPerBody", 64, {1, 65536});
inline constexpr Property kSlop = inInterval("slop", 0.01f, {0.0, 0.5});
inline constexpr Property kCorrection = inInterval("correction", 0.2f, {0.0, 1.0, false});
inline constexpr Property kRestitutionThreshold{"restitutionThreshold", Rule::FiniteNonNegative,
                                                0.0f};
inline constexpr Property kFrictionMix{"frictionMix", Rule::Any, FrictionMix::Min};

using WorldField = Field<WorldDef, jostle_world_def, Vec2, float, Solver, bool>;
using TaskField = Field<TaskSystem, jostle_task_system, int>;
using ClassicField = Field<ClassicOptions, jostle_classic_options, bool>;
using PhysicalField = Field<PhysicalOptions, jostle_physical_options, int, float, FrictionMix>;

/// WorldDef's own members, in world.hpp's order: the order in which checkWorldDef reports.
inline constexpr WorldField kWorldFields[] = {
    {kGravity, &WorldDef::gravity, &jostle_world_def::gravity},
    {kMaxVelocity, &WorldDef::maxVelocity, &jostle_world_def::max_velocity},
    {kSolver, &WorldDef::solver, &jostle_world_def::solver},
    {kSleeping, &WorldDef::sleeping, &jostle_world_def::sleeping},
};

/// WorldDef::tasks' settings ("tasks.workers"; Lua's newWorld has them at its top level).
inline constexpr TaskField kTaskFields[] = {
    {kWorkers, &TaskSystem::workers, &jostle_task_system::workers},
};

/// WorldDef::classic's members ("classic.ccd").
inline constexpr ClassicField kClassicFields[] = {
    {kClassicMass, &ClassicOptions::mass, &jostle_classic_options::mass},
    {kCoulomb, &ClassicOptions::coulomb, &jostle_classic_options::coulomb},
    {kCcd, &ClassicOptions::ccd, &jostle_classic_options::ccd},
};

/// WorldDef::physical's members ("physical.slop"), in the order checkWorldDef reports.
inline constexpr PhysicalField kPhysicalFields[] = {
    {kVelocityIterations, &PhysicalOptions::velocityIterations,
     &jostle_physical_options::velocity_iterations},
    {kPositionIterations, &PhysicalOptions::positionIterations,
     &jostle_physical_options::position_iterations},
    {kMaxContactsPerBody, &PhysicalOptions::maxContactsPerBody,
     &jostle_physical_options::max_contacts_per_body},
    {kSlop, &PhysicalOptions::slop, &jostle_physical_options::slop},
    {kCorrection, &PhysicalOptions::correction, &jostle_physical_options::correction},
    {kRestitutionThreshold, &PhysicalOptions::restitutionThreshold,
     &jostle_physical_options::restitution_threshold},
    {kFrictionMix, &PhysicalOptions::frictionMix, &jostle_physical_options::friction_mix},
};

} // namespace jostle::properties
