// Sleep (docs/sleeping.md): islands of bodies at rest fall asleep together and wake
// together. Falling asleep is a stage of the physical step; waking happens when a body
// is disturbed through the API or an awake body comes near.
#pragma once

#include <cstdint>
#include <vector>

namespace jostle {

struct StepContext;
struct Body;
struct Box;
struct WorldState;

struct SleepScratch {
    std::vector<std::uint32_t> parent; ///< union-find of islands, by slot
    std::vector<float> islandTime;
    std::vector<std::uint32_t> islandOf;
};

/// A body slower than this (units per second) is at rest.
float restingSpeed(const Body& body);

/// Stage: fall asleep. Islands of awake dynamic bodies joined by contacts fall asleep
/// together once every body of the island has been at rest for kTimeToSleep, and every
/// contact among them is within the slop. A body touching a moving kinematic body never
/// sleeps: its platform may carry it off.
void fallAsleep(StepContext& step);

/// Wakes the island of the body in `slot` (nothing if it is awake).
void wakeIsland(WorldState& world, std::uint32_t slot);

/// Wakes every sleeping body touching `box`.
void wakeTouching(WorldState& world, const Box& box);

/// A body is about to change (or go) through the API: it and whatever sleeps against it
/// wake, the resting grid is rebuilt if it is part of it, and the world counts a change.
void disturb(WorldState& world, std::uint32_t slot);

} // namespace jostle
