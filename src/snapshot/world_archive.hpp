// What a snapshot holds of a world, and its bytes (docs/snapshots.md): the payload that
// follows the header. world_archive.cpp describes it once, for writing and for reading.
#pragma once

#include "archive.hpp"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>

namespace jostle {
struct WorldState;
} // namespace jostle

namespace jostle::snapshot {

/// The format of the payload; what world_archive.cpp writes changing makes it the next.
inline constexpr std::uint16_t kFormat = 2;

/// The payload's length in bytes.
std::size_t payloadSize(const WorldState& world);
/// Writes the payload into `out` and returns its length, or nothing if `out` is too short.
std::optional<std::size_t> writePayload(const WorldState& world, std::span<std::uint8_t> out);
/// XXH64 of the payload, without writing it anywhere.
std::uint64_t payloadHash(const WorldState& world);
/// Reads a payload into `into`, a WorldState fresh from its constructor whose serial is
/// the restoring world's (the contact cache comes back as it lay: nothing to sort). Throws
/// Refused, leaving `into` to be thrown away, on anything that is not a payload this
/// library wrote.
void readPayload(std::span<const std::uint8_t> payload, WorldState& into);

} // namespace jostle::snapshot
