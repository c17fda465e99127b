// World's snapshots (docs/snapshots.md): the header, and restoring through a fresh state
// that replaces the world's only once the whole snapshot has been read and checked.
#include "jostle/version.h"
#include "physical/scratch.hpp"
#include "snapshot/world_archive.hpp"
#include "world_access.hpp"

#include <cstring>

namespace jostle {

namespace {

// The header: magic, format, header length, library version, payload length, checksum
// (XXH64 of the payload), little-endian, 32 bytes.
constexpr char kMagic[8] = {'J', 'S', 'T', 'L', 'S', 'N', 'A', 'P'};
constexpr std::size_t kHeaderSize = 32;
constexpr std::uint32_t kLibraryVersion =
    JOSTLE_VERSION_MAJOR << 16 | JOSTLE_VERSION_MINOR << 8 | JOSTLE_VERSION_PATCH;

void putLE(std::uint8_t* at, std::uint64_t v, int bytes) {
    for (int i = 0; i < bytes; ++i)
        at[i] = static_cast<std::uint8_t>(v >> (8 * i));
}

std::uint64_t getLE(const std::uint8_t* at, int bytes) {
    std::uint64_t v = 0;
    for (int i = bytes - 1; i >= 0; --i)
        v = v << 8 | at[i];
    return v;
}

void requireBetweenSteps(const WorldState& w, const char* function) {
    requireChangeable(w, function);
    if (w.stepping)
        fail(function, "called from a callback during step()");
}

/// The snapshot's payload, once its header is found sound.
std::span<const std::uint8_t> payloadOf(std::span<const std::byte> snapshot) {
    const auto* bytes = reinterpret_cast<const std::uint8_t*>(snapshot.data());
    if (snapshot.size() < kHeaderSize || std::memcmp(bytes, kMagic, sizeof kMagic) != 0)
        fail("restore", "not a jostle snapshot");
    const auto format = getLE(bytes + 8, 2);
    if (format != snapshot::kFormat)
        fail("restore", "snapshot format " + std::to_string(format) +
                            ", this library reads format " + std::to_string(snapshot::kFormat));
    if (getLE(bytes + 10, 2) != kHeaderSize)
        fail("restore", "the snapshot's header is corrupted");
    const std::uint64_t payload = getLE(bytes + 16, 8);
    if (snapshot.size() - kHeaderSize != payload)
        fail("restore",
             std::string(snapshot.size() - kHeaderSize < payload ? "truncated" : "too long") +
                 " snapshot: " + std::to_string(snapshot.size()) + " bytes, its header says " +
                 std::to_string(payload + kHeaderSize));
    const std::span<const std::uint8_t> body{bytes + kHeaderSize,
                                             static_cast<std::size_t>(payload)};
    if (snapshot::xxHash64(body.data(), body.size()) != getLE(bytes + 24, 8))
        fail("restore", "the snapshot is corrupted (its checksum does not match)");
    return body;
}

/// Hands `to` what a world keeps through a restore: what ties it to the program (serial,
/// workers, callback, userData) and the step's buffers.
void keepThroughRestore(WorldState& from, WorldState& to) {
    to.serial = from.serial;
    to.def.tasks = from.def.tasks;
    to.tasks = std::move(from.tasks);
    to.preSolve = std::move(from.preSolve);
    to.physical = std::move(from.physical);
    to.changes = from.changes;
    // A body's userData stays with it: its slot holds it still, or held it last.
    const std::size_t slots = std::min(from.slots.size(), to.slots.size());
    for (std::size_t s = 0; s < slots; ++s) {
        const Body &was = from.slots[s], &is = to.slots[s];
        if (is.alive &&
            (was.alive ? was.generation == is.generation : was.generation == is.generation + 1))
            to.asGiven[s].userData = from.asGiven[s].userData;
    }
    const std::size_t maps = std::min(from.tileMaps.maps.size(), to.tileMaps.maps.size());
    for (std::size_t m = 0; m < maps; ++m) {
        const TileMapData &was = from.tileMaps.maps[m], &is = to.tileMaps.maps[m];
        if (is.alive && was.alive && was.generation == is.generation)
            to.tileMaps.maps[m].settings.userData = was.settings.userData;
    }
}

} // namespace

std::size_t World::snapshotSize() const {
    requireBetweenSteps(*state_, "snapshotSize");
    return kHeaderSize + snapshot::payloadSize(*state_);
}

std::size_t World::snapshot(std::span<std::byte> out) const {
    requireBetweenSteps(*state_, "snapshot");
    auto* bytes = reinterpret_cast<std::uint8_t*>(out.data());
    const std::optional<std::size_t> payload =
        out.size() < kHeaderSize
            ? std::nullopt
            : snapshot::writePayload(*state_, {bytes + kHeaderSize, out.size() - kHeaderSize});
    if (!payload)
        fail("snapshot", "the buffer holds " + std::to_string(out.size()) +
                             " bytes, the snapshot needs " + std::to_string(snapshotSize()));
    std::memcpy(bytes, kMagic, sizeof kMagic);
    putLE(bytes + 8, snapshot::kFormat, 2);
    putLE(bytes + 10, kHeaderSize, 2);
    putLE(bytes + 12, kLibraryVersion, 4);
    putLE(bytes + 16, *payload, 8);
    putLE(bytes + 24, snapshot::xxHash64(bytes + kHeaderSize, *payload), 8);
    return kHeaderSize + *payload;
}

std::vector<std::byte> World::snapshot() const {
    requireBetweenSteps(*state_, "snapshot"); // named as the call the game made
    std::vector<std::byte> bytes(snapshotSize());
    snapshot(bytes);
    return bytes;
}

void World::restore(std::span<const std::byte> bytes) {
    WorldState& w = *state_;
    requireBetweenSteps(w, "restore");
    const std::span<const std::uint8_t> payload = payloadOf(bytes);
    auto restored = std::make_unique<WorldState>();
    restored->serial = w.serial;
    try {
        snapshot::readPayload(payload, *restored);
    } catch (const snapshot::Refused& refused) {
        fail("restore", "the snapshot is corrupted: " + refused.what);
    }
    keepThroughRestore(w, *restored);
    state_ = std::move(restored);
}

std::uint64_t World::stateHash() const {
    requireBetweenSteps(*state_, "stateHash");
    return snapshot::payloadHash(*state_);
}

} // namespace jostle
