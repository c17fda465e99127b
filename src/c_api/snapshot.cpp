// The C API's snapshots (jostle.h): World::snapshot and restore over the caller's bytes.
#include "c_api.hpp"

#include <cstddef>
#include <span>

extern "C" {

using namespace jostle;
using namespace jostle::c_api;

size_t jostle_world_snapshot_size(const jostle_world* world) {
    return guard(__func__, size_t{0}, [&] { return outsideStep(world).world.snapshotSize(); });
}

size_t jostle_world_snapshot(const jostle_world* world, void* out, size_t capacity) {
    return guard(__func__, size_t{0}, [&] {
        if (out == nullptr && capacity > 0)
            misuse("out is NULL");
        return outsideStep(world).world.snapshot(std::span(static_cast<std::byte*>(out), capacity));
    });
}

bool jostle_world_restore(jostle_world* world, const void* snapshot, size_t size) {
    return guard(__func__, false, [&] {
        if (snapshot == nullptr && size > 0)
            misuse("snapshot is NULL");
        jostle_world& w = outsideStep(world);
        w.world.restore(std::span(static_cast<const std::byte*>(snapshot), size));
        publishEvents(w); // the last step's events are gone
        return true;
    });
}

uint64_t jostle_world_state_hash(const jostle_world* world) {
    return guard(__func__, std::uint64_t{0}, [&] { return outsideStep(world).world.stateHash(); });
}

} // extern "C"
