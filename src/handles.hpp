// Handles (BodyId, TileMapId): the serial number of the world that made the handle, a
// slot's index, and a generation that counts the slot's reuses. A handle of another world
// is caught by its serial, a handle to something destroyed by its generation; neither can
// be mistaken for a live body or map of this world:
// - no two worlds of a process have the same serial (WorldSerials refuses a world past
//   the last one instead of wrapping around);
// - no slot of a world gives the same generation twice (a slot whose generation is the
//   last one is retired, never reused, instead of wrapping around).
// Bodies and tile maps keep their slots by these rules, written here once.
#pragma once

#include <atomic>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace jostle {

/// Hands out world serial numbers: 1, 2, 3, ... up to UINT32_MAX, each once, safe from
/// several threads at once. 0 is the null handle's.
class WorldSerials {
public:
    /// The next serial, or nothing once UINT32_MAX has been given.
    std::optional<std::uint32_t> take() {
        std::uint32_t last = last_.load();
        do {
            if (last == UINT32_MAX)
                return std::nullopt;
        } while (!last_.compare_exchange_weak(last, last + 1));
        return last + 1;
    }
    /// Makes `last` the last serial given, and returns the one that was: for tests of
    /// the end of the range, which put it back.
    std::uint32_t exchangeLast(std::uint32_t last) { return last_.exchange(last); }

private:
    std::atomic<std::uint32_t> last_{0};
};

/// The serials of the worlds of this process (world.cpp).
WorldSerials& worldSerials();

/// A slot's occupant within its own world: a handle without the world's serial, for the
/// records a world keeps of its own bodies (where the serial would only cost memory).
/// WorldState::idOf and idFor make handles of them.
struct SlotRef {
    std::uint32_t index = 0;
    std::uint32_t generation = 0; ///< 0: no occupant (as in the null handle)

    constexpr bool isNull() const { return generation == 0; }
    friend constexpr bool operator==(SlotRef a, SlotRef b) = default;
};

/// Whether slot `index` of `slots` (whose elements have `alive` and `generation`) holds
/// the live occupant of `generation`. False for generation 0: no slot has it.
template <class Slot>
bool isCurrent(const std::vector<Slot>& slots, std::uint32_t index, std::uint32_t generation) {
    return index < slots.size() && slots[index].alive && slots[index].generation == generation;
}

/// Whether `id` (a BodyId or TileMapId) names the live occupant of its slot in `slots`,
/// the slots of the world whose serial is `world`.
template <class Slot, class Id>
bool isCurrent(const std::vector<Slot>& slots, std::uint32_t world, Id id) {
    return id.world == world && isCurrent(slots, id.index, id.generation);
}

/// What is wrong with `id` as a handle into `slots`, the slots of the world whose serial
/// is `world`, in the words of errors, or nothing. With `type` "BodyId" and `thing`
/// "body": "null BodyId", "BodyId of another world", "stale BodyId (the body was
/// destroyed)".
template <class Slot, class Id>
std::optional<std::string> handleProblem(const std::vector<Slot>& slots, std::uint32_t world, Id id,
                                         const char* type, const char* thing) {
    if (id.isNull())
        return std::string("null ") + type;
    if (id.world != world)
        return std::string(type) + " of another world";
    if (!isCurrent(slots, id.index, id.generation))
        return std::string("stale ") + type + " (the " + thing + " was destroyed)";
    return std::nullopt;
}

/// A slot for a new occupant: the last of `free`, or a new slot at generation 1;
/// nothing if every index is in use. The slot keeps its generation, which is the new
/// handle's.
template <class Slot>
std::optional<std::uint32_t> takeSlot(std::vector<Slot>& slots, std::vector<std::uint32_t>& free) {
    if (!free.empty()) {
        const std::uint32_t slot = free.back();
        free.pop_back();
        return slot;
    }
    if (slots.size() >= UINT32_MAX)
        return std::nullopt;
    slots.emplace_back().generation = 1;
    return static_cast<std::uint32_t>(slots.size() - 1);
}

/// Moves the generation of `slot`, whose occupant was just destroyed, past that
/// occupant's, so that its handles are stale for good. Returns whether the slot may be
/// reused (the caller frees it); a slot whose occupant had the last generation,
/// UINT32_MAX, is retired instead: it keeps that generation, empty, for good.
template <class Slot> bool moveGenerationOn(Slot& slot) {
    if (slot.generation == UINT32_MAX)
        return false;
    ++slot.generation;
    return true;
}

} // namespace jostle
