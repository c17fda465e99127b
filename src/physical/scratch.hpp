// The physical step's buffers, kept in the world from step to step so that a step
// allocates nothing once the world has reached its size. Each stage's own part is
// declared in its header.
#pragma once

#include "../broadphase.hpp"
#include "contact.hpp"
#include "contact_cache.hpp"
#include "contacts.hpp"
#include "continuous.hpp"
#include "impacts.hpp"
#include "report.hpp"
#include "riders.hpp"
#include "sleep.hpp"
#include "solver_layers.hpp"
#include "support.hpp"

#include <cstdint>
#include <vector>

namespace jostle {

struct PhysicalScratch {
    std::vector<Contact> contacts;
    std::vector<SolverBody> bodies;
    std::vector<std::uint32_t> solverIndex; ///< by slot
    /// Pairs of a sensor (`a`) and a body that may overlap it.
    std::vector<BodyPair> sensorPairs;
    ContactsScratch contactsBuild;
    SupportScratch support;
    ContinuousScratch continuous;
    PlatformScratch platforms;
    SleepScratch sleep;
    ImpactsScratch impacts;
    ReportScratch report;
    StoreScratch store;
    SolverLayers layers;
};

} // namespace jostle
