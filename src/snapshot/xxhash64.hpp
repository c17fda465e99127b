// XXH64, the 64-bit xxHash (its published specification, seed 0 by default), fed in
// pieces: the snapshot's checksum and World::stateHash. It reads bytes as little-endian
// words, so a byte string hashes to the same number on every machine.
#pragma once

#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>

namespace jostle::snapshot {

class XxHash64 {
public:
    explicit XxHash64(std::uint64_t seed = 0)
        : lanes_{seed + kP1 + kP2, seed + kP2, seed, seed - kP1}, seed_(seed) {}

    void update(const std::uint8_t* bytes, std::size_t n) {
        total_ += n;
        if (held_ + n < 32) {
            std::memcpy(buffer_ + held_, bytes, n);
            held_ += n;
            return;
        }
        if (held_ > 0) {
            const std::size_t fill = 32 - held_;
            std::memcpy(buffer_ + held_, bytes, fill);
            stripe(buffer_);
            bytes += fill;
            n -= fill;
            held_ = 0;
        }
        for (; n >= 32; bytes += 32, n -= 32)
            stripe(bytes);
        std::memcpy(buffer_, bytes, n);
        held_ = n;
    }

    std::uint64_t digest() const {
        std::uint64_t h;
        if (total_ >= 32) {
            h = std::rotl(lanes_[0], 1) + std::rotl(lanes_[1], 7) + std::rotl(lanes_[2], 12) +
                std::rotl(lanes_[3], 18);
            for (std::uint64_t lane : lanes_)
                h = (h ^ round(0, lane)) * kP1 + kP4;
        } else {
            h = seed_ + kP5;
        }
        h += total_;
        const std::uint8_t* p = buffer_;
        std::size_t n = held_;
        for (; n >= 8; p += 8, n -= 8)
            h = std::rotl(h ^ round(0, word64(p)), 27) * kP1 + kP4;
        if (n >= 4) {
            h = std::rotl(h ^ (std::uint64_t{word32(p)} * kP1), 23) * kP2 + kP3;
            p += 4;
            n -= 4;
        }
        for (; n > 0; ++p, --n)
            h = std::rotl(h ^ (std::uint64_t{*p} * kP5), 11) * kP1;
        h ^= h >> 33;
        h *= kP2;
        h ^= h >> 29;
        h *= kP3;
        h ^= h >> 32;
        return h;
    }

private:
    static constexpr std::uint64_t kP1 = 0x9E3779B185EBCA87ull;
    static constexpr std::uint64_t kP2 = 0xC2B2AE3D27D4EB4Full;
    static constexpr std::uint64_t kP3 = 0x165667B19E3779F9ull;
    static constexpr std::uint64_t kP4 = 0x85EBCA77C2B2AE63ull;
    static constexpr std::uint64_t kP5 = 0x27D4EB2F165667C5ull;

    static std::uint64_t round(std::uint64_t acc, std::uint64_t input) {
        return std::rotl(acc + input * kP2, 31) * kP1;
    }
    static std::uint64_t word64(const std::uint8_t* p) {
        std::uint64_t v = 0;
        for (int i = 7; i >= 0; --i)
            v = v << 8 | p[i];
        return v;
    }
    static std::uint32_t word32(const std::uint8_t* p) {
        return std::uint32_t(p[0]) | std::uint32_t(p[1]) << 8 | std::uint32_t(p[2]) << 16 |
               std::uint32_t(p[3]) << 24;
    }
    void stripe(const std::uint8_t* p) {
        for (int i = 0; i < 4; ++i)
            lanes_[i] = round(lanes_[i], word64(p + 8 * i));
    }

    std::uint64_t lanes_[4];
    std::uint64_t seed_;
    std::uint64_t total_ = 0;
    std::uint8_t buffer_[32] = {};
    std::size_t held_ = 0;
};

/// The XXH64 of `n` bytes, seed 0.
inline std::uint64_t xxHash64(const std::uint8_t* bytes, std::size_t n) {
    XxHash64 hash;
    hash.update(bytes, n);
    return hash.digest();
}

} // namespace jostle::snapshot
