// Handles (BodyId, TileMapId): a slot's index and a generation that counts the slot's
// reuses, so that a handle to something destroyed is caught, never mistaken for what took
// its slot. Bodies and tile maps keep their slots by these rules, written here once.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace jostle {

/// The generation of a slot's next occupant: 0 is the null handle's, skipped on
/// wrap-around.
inline std::uint32_t nextGeneration(std::uint32_t generation) {
    return generation == UINT32_MAX ? 1 : generation + 1;
}

/// Whether `id` names the live occupant of its slot in `slots` (whose elements have
/// `alive` and `generation`). False for the null handle: no slot has generation 0.
template <class Slot, class Id> bool isCurrent(const std::vector<Slot>& slots, Id id) {
    return id.index < slots.size() && slots[id.index].alive &&
           slots[id.index].generation == id.generation;
}

/// What is wrong with `id` as a handle into `slots`, in the words of errors, or nothing:
/// "null BodyId", "stale or foreign BodyId (the body was destroyed or is not of this
/// world)", with `type` "BodyId" and `thing` "body".
template <class Slot, class Id>
std::optional<std::string> handleProblem(const std::vector<Slot>& slots, Id id, const char* type,
                                         const char* thing) {
    if (id.isNull())
        return std::string("null ") + type;
    if (!isCurrent(slots, id))
        return std::string("stale or foreign ") + type + " (the " + thing +
               " was destroyed or is not of this world)";
    return std::nullopt;
}

/// A slot for a new occupant: the last of `free`, or a new slot at generation
/// `firstGeneration`; nothing if every index is in use. The slot keeps its generation,
/// which is the new handle's.
template <class Slot>
std::optional<std::uint32_t> takeSlot(std::vector<Slot>& slots, std::vector<std::uint32_t>& free,
                                      std::uint32_t firstGeneration) {
    if (!free.empty()) {
        const std::uint32_t slot = free.back();
        free.pop_back();
        return slot;
    }
    if (slots.size() >= UINT32_MAX)
        return std::nullopt;
    slots.emplace_back().generation = firstGeneration;
    return static_cast<std::uint32_t>(slots.size() - 1);
}

} // namespace jostle
