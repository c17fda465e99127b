// shared/random.hpp: the random numbers of the shared scenes, the same on every platform.
//
// std::mt19937's output is fixed by the standard, but the distributions of <random> are
// not (libstdc++ and libc++ turn the same bits into different floats), so the scenes map
// the raw 32-bit outputs to floats themselves.
#pragma once

#include <cstdint>
#include <random>

namespace jostle::shared {

class Random {
public:
    explicit Random(std::uint32_t seed) : engine_(seed) {}

    /// A float in [0, 1): the top 24 bits of one output, which a float holds exactly.
    float unit() { return static_cast<float>(engine_() >> 8) * 0x1p-24f; }

    /// A float in [low, high).
    float uniform(float low, float high) { return low + (high - low) * unit(); }

    /// A whole number in [low, high], by the same top-bits mapping (bias is irrelevant
    /// at the small ranges the scenes use).
    int between(int low, int high) {
        const auto span = static_cast<std::uint64_t>(high - low + 1);
        return low + static_cast<int>((std::uint64_t{engine_()} * span) >> 32);
    }

    /// -1 or +1, evenly.
    float sign() { return (engine_() & 0x80000000u) != 0 ? -1.0f : 1.0f; }

private:
    std::mt19937 engine_;
};

} // namespace jostle::shared
