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

struct CountingSink {
    std::size_t size = 0;
    void put(const std::uint8_t*, std::size_t n) { size += n; }
};

/// Into the caller's buffer, as far as it goes: past its end, nothing more is written and
/// `overflowed` says so.
struct BoundedSink {
    std::uint8_t* at;
    std::uint8_t* end;
    bool overflowed = false;
    void put(const std::uint8_t* bytes, std::size_t n) {
        if (overflowed || static_cast<std::size_t>(end - at) < n) {
            overflowed = true;
            return;
        }
        std::memcpy(at, bytes, n);
        at += n;
    }
};

/// Into XXH64, a chunk at a time (hashing value by value would cost more than writing).
struct HashingSink {
    XxHash64 hash;
    std::uint8_t chunk[1024];
    std::size_t used = 0;
    void put(const std::uint8_t* bytes, std::size_t n) {
        if (used + n > sizeof chunk) {
            hash.update(chunk, used);
            used = 0;
        }
        std::memcpy(chunk + used, bytes, n); // n is at most 10: one value
        used += n;
    }
    std::uint64_t digest() {
        hash.update(chunk, used);
        used = 0;
        return hash.digest();
    }
};

/// A record's bytes on their way to the sink, in the writer's own memory (Writer::record).
template <std::size_t Bound> struct RecordSink {
    std::uint8_t bytes[Bound];
    std::size_t size = 0;
    void put(const std::uint8_t* from, std::size_t n) {
        if (size + n > Bound) // a record's bound is its longest encoding: never
            throw std::logic_error("snapshot: a record is longer than its bound");
        std::memcpy(bytes + size, from, n);
        size += n;
    }
};

// --- Writer and Reader ------------------------------------------------------------------

template <class Sink> class Writer {
public:
    static constexpr bool kReading = false;
    explicit Writer(Sink& sink) : sink_(sink) {}

    void u8(const std::uint8_t& v) { sink_.put(&v, 1); }
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
        if (v < 0x80) { // most numbers: one byte
            const auto byte = static_cast<std::uint8_t>(v);
            sink_.put(&byte, 1);
            return;
        }
        std::uint8_t bytes[10];
        std::size_t n = 0;
        do {
            bytes[n] = static_cast<std::uint8_t>(v & 0x7F);
            v >>= 7;
            if (v != 0)
                bytes[n] |= 0x80;
            ++n;
        } while (v != 0);
        sink_.put(bytes, n);
    }
    /// A count of what follows, each at least `minBytes` long (Reader checks there is room).
    template <class T> void count(const T& n, std::size_t /*minBytes*/) { var(n); }
    /// Calls fill(ar) with a writer of its own, whose bytes (`Bound` at most) go to the sink
    /// at once: the loops over many small records (bodies, contacts) write a record at a
    /// time, not a value at a time. A reader calls fill(*this).
    template <std::size_t Bound, class Fill> void record(Fill&& fill) {
        RecordSink<Bound> local;
        Writer<RecordSink<Bound>> ar(local);
        fill(ar);
        sink_.put(local.bytes, local.size);
    }
    /// A condition the reader checks: a writer's values meet it by construction.
    void check(bool, const char*) {}
    template <class Describe> void checkOr(bool, Describe&&) {}

private:
    void fixed(std::uint64_t v, int n) {
        std::uint8_t bytes[8];
        for (int i = 0; i < n; ++i)
            bytes[i] = static_cast<std::uint8_t>(v >> (8 * i));
        sink_.put(bytes, static_cast<std::size_t>(n));
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
