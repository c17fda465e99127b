// Stage: order by support. Static and kinematic bodies are level 0 and a dynamic body
// touching a level-k body is level k + 1; contacts are sorted from the ground up, and
// each contact names the body that holds the other, if one does.
#pragma once

#include "../counting_sort.hpp"

#include <cstdint>
#include <vector>

namespace jostle {

struct StepContext;

struct SupportScratch {
    Buckets graph; ///< the contact graph: each solver body's run of neighbours
    std::vector<std::uint32_t> neighbours;
    /// Beside each neighbour, the contact it is met by, as its index before the sort;
    /// sortedPlace maps that to where the sort put it.
    std::vector<std::uint32_t> edgeContact;
    std::vector<std::uint32_t> sortedPlace;
    std::vector<std::uint32_t> levels; ///< support level by solver body
    std::vector<std::uint8_t> backing; ///< by solver body: sides touching a static or kinematic one
    std::vector<std::uint32_t> queue;
    Buckets byLevel;
    std::vector<std::uint32_t> destination; ///< the sort's scratch
    std::vector<std::uint32_t> topOfBlock;  ///< one above the highest level, by block of contacts
    /// One above the highest level of a contact (its lower body's). A contact of level L
    /// and the contacts down its lower body's path to the ground are L + 1 contacts in
    /// support order, each sharing a dynamic body with the next: solver layers (which
    /// keep that order) number at least this many.
    std::uint32_t top = 0;
};

/// Sets each contact's supporter and sorts step.contacts by support level, ties in the
/// order they were made.
void orderBySupport(StepContext& step);

/// Whether the contact graph the last orderBySupport built joins solver bodies `ia` and
/// `ib` (false for a body it did not know).
bool haveContact(const StepContext& step, std::uint32_t ia, std::uint32_t ib);

} // namespace jostle
