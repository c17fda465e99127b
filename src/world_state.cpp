// A world's state: built and torn down where the physical step's buffers are whole.
#include "world_state.hpp"

#include "physical/scratch.hpp"

namespace jostle {

WorldState::WorldState() : physical(std::make_unique<PhysicalScratch>()) {}

WorldState::~WorldState() = default;

bool WorldState::askPreSolve(Collision& c) {
    if (preSolveThrew)
        return true;
    const Collision given = c;
    try {
        return preSolve(c);
    } catch (...) {
        preSolveThrew = std::current_exception();
        c = given;
        return true;
    }
}

} // namespace jostle
