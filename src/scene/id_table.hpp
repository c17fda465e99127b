// Scene files: the ids of the bodies read so far, for the scene reader (scene_reader.cpp).
#pragma once

#include "definition_fields.hpp"
#include "jostle/scene.hpp"

#include <algorithm>
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace jostle::scene_file {

/// The ids of the bodies read so far, each by the body's index in `bodies`: a table of
/// (hash, index) with open addressing, so that a lookup is one slot or a few neighbours
/// and a new id allocates nothing.
class IdTable {
public:
    explicit IdTable(const std::vector<SceneBody>& bodies) : bodies_(bodies) {}

    /// The index of the body whose id is bodies[index].id, if one came before; else kNone,
    /// and bodies[index] is in the table.
    std::size_t insert(std::size_t index) {
        if (2 * (count_ + 1) > slots_.size())
            grow();
        const std::string& id = bodies_[index].id;
        const std::size_t hash = std::hash<std::string>{}(id);
        for (std::size_t at = hash & (slots_.size() - 1);; at = (at + 1) & (slots_.size() - 1)) {
            Slot& slot = slots_[at];
            if (slot.index == kNone) {
                slot = {hash, index};
                ++count_;
                return kNone;
            }
            if (slot.hash == hash && bodies_[slot.index].id == id)
                return slot.index;
        }
    }

private:
    struct Slot {
        std::size_t hash = 0;
        std::size_t index = kNone;
    };

    void grow() {
        std::vector<Slot> old(std::max<std::size_t>(64, 2 * slots_.size()));
        old.swap(slots_);
        for (const Slot& slot : old) {
            if (slot.index == kNone)
                continue;
            std::size_t at = slot.hash & (slots_.size() - 1);
            while (slots_[at].index != kNone)
                at = (at + 1) & (slots_.size() - 1);
            slots_[at] = slot;
        }
    }

    const std::vector<SceneBody>& bodies_;
    std::vector<Slot> slots_; ///< a power of two of them, at most half used
    std::size_t count_ = 0;
};

} // namespace jostle::scene_file
