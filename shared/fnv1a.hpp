// shared/fnv1a.hpp: FNV-1a over the bits of what a world says about itself, the hash of
// the determinism tests (tests/test_determinism.cpp) and of the web page's sample check.
#pragma once

#include "jostle/math.hpp"

#include <bit>
#include <cstdint>

namespace jostle::shared {

class Fnv1a {
public:
    void add(std::uint32_t word) {
        for (int byte = 0; byte < 4; ++byte) {
            value_ ^= (word >> (8 * byte)) & 0xFFu;
            value_ *= 1099511628211ULL;
        }
    }
    void add(float f) { add(std::bit_cast<std::uint32_t>(f)); }
    void add(Vec2 v) {
        add(v.x);
        add(v.y);
    }
    std::uint64_t value() const { return value_; }

private:
    std::uint64_t value_ = 14695981039346656037ULL;
};

} // namespace jostle::shared
