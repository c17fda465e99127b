// The two directions of a snapshot's bytes (docs/snapshots.md): Writer puts values into a
// sink (counting, writing into the caller's buffer, or hashing), Reader takes them back
// out, checked. One function describes what is saved, with the same calls for both
// (world_archive.cpp), so saving and restoring cannot drift apart.
//
// The bytes: integers little-endian, byte by byte; floats as their IEEE-754 bits; `var`
// numbers as unsigned LEB128 (7 bits a byte, low first), the shortest form only.
#pragma once

#include "jostle/math.hpp"
#include "xxhash64.hpp"

#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>
#include <stdexcept>
#include <string>

namespace jostle::snapshot {

/// A snapshot that cannot be restored: what is wrong with it (World::restore's message).
struct Refused {
    std::string what;
};

// --- Sinks: where a Writer's bytes go -----------------------------------------------------
//
// A sink takes bytes one at a time (put). One that holds them in memory also gives a
// record room for `n` bytes at once (room(n): where to write them, or null; then advance(k)
// for the k written), so that the loops over many small records (bodies, contacts) write
// straight into their place.

/// Straight into memory that has room: a record's bytes.
struct PointerSink {
    std::uint8_t* at;
    void put(std::uint8_t byte) { *at++ = byte; }
};

struct CountingSink {
    std::size_t size = 0;
    void put(std::uint8_t) { ++size; }
};

/// Into the caller's buffer, as far as it goes: past its end, nothing more is written and
/// `overflowed` says so.
struct BoundedSink {
    std::uint8_t* at;
    std::uint8_t* end;
    bool overflowed = false;
    void put(std::uint8_t byte) {
        if (at == end) {
            overflowed = true;
            return;
        }
        *at++ = byte;
    }
    /// Null near the end: the record then goes byte by byte, each put checked.
    std::uint8_t* room(std::size_t n) {
        return static_cast<std::size_t>(end - at) >= n ? at : nullptr;
    }
    void advance(std::size_t n) { at += n; }
};

/// Into XXH64, a chunk at a time (hashing value by value would cost more than writing).
struct HashingSink {
    XxHash64 hash;
    std::uint8_t chunk[4096];
    std::size_t used = 0;
    void put(std::uint8_t byte) {
        if (used == sizeof chunk)
            flush();
        chunk[used++] = byte;
    }
    std::uint8_t* room(std::size_t n) {
        if (n > sizeof chunk)
            return nullptr;
        if (used + n > sizeof chunk)
            flush();
        return chunk + used;
    }
    void advance(std::size_t n) { used += n; }
    std::uint64_t digest() {
        flush();
        return hash.digest();
    }

private:
    void flush() {
        hash.update(chunk, used);
        used = 0;
    }
};

// --- Writer and Reader ------------------------------------------------------------------

template <class Sink> class Writer {
public:
    static constexpr bool kReading = false;
    explicit Writer(Sink& sink) : sink_(sink) {}

    void u8(const std::uint8_t& v) { sink_.put(v); }
    void u32(const std::uint32_t& v) { fixed(v, 4); }
    void u64(const std::uint64_t& v) { fixed(v, 8); }
    void f32(const float& v) { u32(std::bit_cast<std::uint32_t>(v)); }
    void vec(const Vec2& v) {
        f32(v.x);
        f32(v.y);
    }
    void flag(const bool& v) { u8(static_cast<std::uint8_t>(v ? 1 : 0)); }
    template <class T> void var(const T& value) {
        std::uint64_t v = value;
        while (v >= 0x80) {
            sink_.put(static_cast<std::uint8_t>(v | 0x80));
            v >>= 7;
        }
        sink_.put(static_cast<std::uint8_t>(v));
    }
    /// A count of what follows, each at least `minBytes` long (Reader checks there is room).
    template <class T> void count(const T& n, std::size_t /*minBytes*/) { var(n); }
    /// Calls fill(ar) with a writer straight into the sink's room for `Bound` bytes, the
    /// record's longest encoding, where the sink gives room: the loops over many small
    /// records (bodies, contacts) write without a check a byte. Else, and for a reader,
    /// fill(*this).
    template <std::size_t Bound, class Fill> void record(Fill&& fill) {
        if constexpr (requires { sink_.room(Bound); }) {
            if (std::uint8_t* at = sink_.room(Bound)) {
                PointerSink local{at};
                Writer<PointerSink> ar(local);
                fill(ar);
                const auto written = static_cast<std::size_t>(local.at - at);
                if (written > Bound) // a record's bound is its longest encoding: never
                    throw std::logic_error("snapshot: a record is longer than its bound");
                sink_.advance(written);
                return;
            }
        }
        fill(*this);
    }
    /// A condition the reader checks: a writer's values meet it by construction.
    void check(bool, const char*) {}
    template <class Describe> void checkOr(bool, Describe&&) {}

private:
    void fixed(std::uint64_t v, int n) {
        for (int i = 0; i < n; ++i)
            sink_.put(static_cast<std::uint8_t>(v >> (8 * i)));
    }
    Sink& sink_;
};

class Reader {
public:
    static constexpr bool kReading = true;
    explicit Reader(std::span<const std::uint8_t> bytes)
        : at_(bytes.data()), end_(at_ + bytes.size()) {}

    void u8(std::uint8_t& v) { v = static_cast<std::uint8_t>(fixed(1)); }
    void u32(std::uint32_t& v) { v = static_cast<std::uint32_t>(fixed(4)); }
    void u64(std::uint64_t& v) { v = fixed(8); }
    void f32(float& v) { v = std::bit_cast<float>(static_cast<std::uint32_t>(fixed(4))); }
    void vec(Vec2& v) {
        f32(v.x);
        f32(v.y);
    }
    void flag(bool& v) {
        std::uint8_t b;
        u8(b);
        check(b <= 1, "a flag is neither 0 nor 1");
        v = b != 0;
    }
    template <class T> void var(T& value) {
        if (at_ != end_ && *at_ < 0x80) { // most numbers: one byte
            value = static_cast<T>(*at_++);
            return;
        }
        std::uint64_t v = 0;
        for (int shift = 0;; shift += 7) {
            check(shift < 64, "a number is longer than 10 bytes");
            const std::uint8_t byte = static_cast<std::uint8_t>(fixed(1));
            v |= std::uint64_t(byte & 0x7F) << shift;
            if ((byte & 0x80) == 0) {
                check(byte != 0 || shift == 0, "a number is not in its shortest form");
                break;
            }
        }
        check(v <= std::uint64_t(T(~T(0))), "a number is out of its range");
        value = static_cast<T>(v);
    }
    template <class T> void count(T& n, std::size_t minBytes) {
        var(n);
        check(std::uint64_t(n) <= left() / (minBytes == 0 ? 1 : minBytes),
              "a count is larger than the bytes that follow");
    }
    template <std::size_t Bound, class Fill> void record(Fill&& fill) { fill(*this); }
    void check(bool ok, const char* what) {
        if (!ok) [[unlikely]]
            refuse(what);
    }
    template <class Describe> void checkOr(bool ok, Describe&& describe) {
        if (!ok)
            throw Refused{describe()};
    }
    std::size_t left() const { return static_cast<std::size_t>(end_ - at_); }

private:
    [[noreturn]] [[gnu::cold]] [[gnu::noinline]] static void refuse(const char* what) {
        throw Refused{what};
    }
    std::uint64_t fixed(int n) {
        check(left() >= static_cast<std::size_t>(n), "truncated");
        std::uint64_t v = 0;
        for (int i = n - 1; i >= 0; --i)
            v = v << 8 | at_[i];
        at_ += n;
        return v;
    }
    const std::uint8_t* at_;
    const std::uint8_t* end_;
};

} // namespace jostle::snapshot
