// The two directions of a snapshot's bytes (docs/snapshots.md): Writer puts values into a
// Sink (counted, written into the caller's buffer, or hashed), Reader takes them back out,
// checked. One function describes what is saved, with the same calls for both
// (world_archive.cpp), so saving and restoring cannot drift apart.
//
// The bytes: integers little-endian; floats as their IEEE-754 bits; `var`
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

// A record's fill function (Writer::record, BasicReader::record) is inlined into it where
// clang compiles it (the web build's compiler, and the sanitizers'): left out of line, each
// value it writes goes through memory, and the WebAssembly save took 1.7 times as long.
// g++ inlines it by its own measure, which is faster there than forcing it (by a tenth).
#if defined(__clang__)
#define JOSTLE_RECORD_INLINE __attribute__((always_inline))
#else
#define JOSTLE_RECORD_INLINE
#endif

/// A snapshot that cannot be restored: what is wrong with it (World::restore's message).
struct Refused {
    std::string what;
};

// --- Sinks: where a Writer's bytes go -----------------------------------------------------
//
// A Sink is memory a Writer fills: a byte at a time (put), or a record's at once (room(n):
// where to write n bytes, or null; then advance(k) for the k written), so that the loops
// over many small records (bodies, contacts) write straight into their place. When it is
// full, its drain() takes what it holds (counts it, hashes it) and it starts again; the
// caller's buffer cannot drain, and says it overflowed. One Writer type for the three
// (the size, the bytes, the hash): one copy of the world's description in the code.

/// Straight into memory that has room: a record's bytes.
struct PointerSink {
    std::uint8_t* at;
    void put(std::uint8_t byte) { *at++ = byte; }
    /// The low `N` bytes of `v`, little-endian, in one store where the machine is.
    template <int N> void putLE(std::uint64_t v) {
        if constexpr (std::endian::native == std::endian::little) {
            std::memcpy(at, &v, N);
            at += N;
        } else {
            for (int i = 0; i < N; ++i)
                put(static_cast<std::uint8_t>(v >> (8 * i)));
        }
    }
};

class Sink {
public:
    void put(std::uint8_t byte) {
        if (at_ == end_ && !drained(1)) {
            overflowed_ = true;
            return;
        }
        *at_++ = byte;
    }
    std::uint8_t* room(std::size_t n) {
        return static_cast<std::size_t>(end_ - at_) >= n || drained(n) ? at_ : nullptr;
    }
    void advance(std::size_t n) { at_ += n; }
    /// Bytes were dropped for want of room (the caller's buffer).
    bool overflowed() const { return overflowed_; }

protected:
    Sink(std::uint8_t* begin, std::uint8_t* end) : begin_(begin), at_(begin), end_(end) {}
    ~Sink() = default;
    /// Takes the bytes from begin_ to at_; false if it cannot.
    virtual bool drain() = 0;
    /// Whether draining made room for `n` bytes.
    bool drained(std::size_t n) {
        if (!drain())
            return false;
        at_ = begin_;
        return static_cast<std::size_t>(end_ - at_) >= n;
    }
    std::uint8_t* begin_;
    std::uint8_t* at_;
    std::uint8_t* end_;

private:
    bool overflowed_ = false;
};

/// Into the caller's buffer, as far as it goes.
class BufferSink final : public Sink {
public:
    BufferSink(std::uint8_t* begin, std::uint8_t* end) : Sink(begin, end) {}
    std::size_t written() const { return static_cast<std::size_t>(at_ - begin_); }

private:
    bool drain() override { return false; }
};

/// A chunk of memory drained into `Take` (a count, a hash) each time it is full.
template <class Take> class ChunkSink final : public Sink {
public:
    ChunkSink() : Sink(chunk_, chunk_ + sizeof chunk_) {}
    /// What took every byte.
    Take& taken() {
        drained(0);
        return take_;
    }

private:
    bool drain() override {
        take_.update(begin_, static_cast<std::size_t>(at_ - begin_));
        return true;
    }
    std::uint8_t chunk_[4096];
    Take take_;
};

/// How many bytes: a Take for ChunkSink.
struct ByteCount {
    std::size_t size = 0;
    void update(const std::uint8_t*, std::size_t n) { size += n; }
};

// --- Writer and Reader ------------------------------------------------------------------

template <class Into> class Writer {
public:
    static constexpr bool kReading = false;
    explicit Writer(Into& sink) : sink_(sink) {}

    void u8(const std::uint8_t& v) { sink_.put(v); }
    void u32(const std::uint32_t& v) { fixed<4>(v); }
    void u64(const std::uint64_t& v) { fixed<8>(v); }
    void f32(const float& v) { u32(std::bit_cast<std::uint32_t>(v)); }
    void vec(const Vec2& v) {
        f32(v.x);
        f32(v.y);
    }
    void flag(const bool& v) { u8(static_cast<std::uint8_t>(v ? 1 : 0)); }
    template <class T> [[gnu::always_inline]] void var(const T& value) {
        std::uint64_t v = value;
        if (v < 0x80) [[likely]] {
            sink_.put(static_cast<std::uint8_t>(v));
            return;
        }
        if (v < 0x4000) {
            sink_.put(static_cast<std::uint8_t>(v | 0x80));
            sink_.put(static_cast<std::uint8_t>(v >> 7));
            return;
        }
        while (v >= 0x80) {
            sink_.put(static_cast<std::uint8_t>(v | 0x80));
            v >>= 7;
        }
        sink_.put(static_cast<std::uint8_t>(v));
    }
    /// A count of what follows, each at least `minBytes` long (Reader checks there is room).
    template <class T> void count(const T& n, std::size_t /*minBytes*/) { var(n); }
    /// Calls fill(ar) with a writer straight into memory with room for `Bound` bytes, the
    /// record's longest encoding: the sink's own where it gives room, so that the loops over
    /// many small records (bodies, contacts) write without a check a byte; else a scratch
    /// record, put into the sink after. One writer for every record: one copy of its code.
    template <std::size_t Bound, class Fill> void record(Fill&& fill) {
        std::uint8_t scratch[Bound];
        std::uint8_t* const room = sink_.room(Bound);
        std::uint8_t* const at = room != nullptr ? room : scratch;
        PointerSink local{at};
        Writer<PointerSink> ar(local);
        fill(ar);
        const auto written = static_cast<std::size_t>(local.at - at);
        if (written > Bound) // a record's bound is its longest encoding: never
            throw std::logic_error("snapshot: a record is longer than its bound");
        if (room != nullptr) {
            sink_.advance(written);
            return;
        }
        for (std::size_t i = 0; i < written; ++i)
            sink_.put(scratch[i]);
    }
    /// A condition the reader checks: a writer's values meet it by construction.
    void check(bool, const char*) {}
    template <class Describe> void checkOr(bool, Describe&&) {}

private:
    template <int N> [[gnu::always_inline]] void fixed(std::uint64_t v) {
        if constexpr (requires { sink_.template putLE<N>(v); })
            sink_.template putLE<N>(v);
        else
            for (int i = 0; i < N; ++i)
                sink_.put(static_cast<std::uint8_t>(v >> (8 * i)));
    }
    Into& sink_;
};

/// Reads values back, checked. `Bounded`: each read checks first that its bytes are there;
/// a record whose longest encoding is left (and a number's longest more: a reader may read
/// one over-long number before refusing it) is read by an unbounded reader.
template <bool Bounded> class BasicReader {
public:
    static constexpr bool kReading = true;
    explicit BasicReader(std::span<const std::uint8_t> bytes)
        : at_(bytes.data()), end_(at_ + bytes.size()) {}

    void u8(std::uint8_t& v) { v = static_cast<std::uint8_t>(fixed<1>()); }
    void u32(std::uint32_t& v) { v = static_cast<std::uint32_t>(fixed<4>()); }
    void u64(std::uint64_t& v) { v = fixed<8>(); }
    void f32(float& v) { v = std::bit_cast<float>(static_cast<std::uint32_t>(fixed<4>())); }
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
        if ((!Bounded || at_ != end_) && *at_ < 0x80) [[likely]] { // most numbers: one byte
            value = static_cast<T>(*at_++);
            return;
        }
        if ((!Bounded || left() >= 2) && at_[1] < 0x80) { // and many two (slots)
            const std::uint64_t v = (at_[0] & 0x7Fu) | std::uint64_t{at_[1]} << 7;
            check(at_[1] != 0, "a number is not in its shortest form");
            check(v <= std::uint64_t(T(~T(0))), "a number is out of its range");
            at_ += 2;
            value = static_cast<T>(v);
            return;
        }
        value = static_cast<T>(longVar(std::uint64_t(T(~T(0)))));
    }
    template <class T> void count(T& n, std::size_t minBytes) {
        var(n);
        check(std::uint64_t(n) <= left() / (minBytes == 0 ? 1 : minBytes),
              "a count is larger than the bytes that follow");
    }
    /// Calls fill(ar) with a reader that checks no bounds: over the bytes themselves where
    /// the record's longest encoding is left (and a number's longest more: a reader may read
    /// one over-long number before it refuses it), else over a copy of what is left padded
    /// with zeros, refused as truncated if the record went past the end.
    template <std::size_t Bound, class Fill> void record(Fill&& fill) {
        static_assert(Bounded, "a record in a record");
        constexpr std::size_t kReach = Bound + kLongestVar;
        const std::uint8_t* from = at_;
        const std::uint8_t* end = end_;
        std::uint8_t padded[kReach];
        if (left() < kReach) {
            std::memset(padded, 0, kReach);
            if (left() > 0)
                std::memcpy(padded, at_, left());
            from = padded;
            end = padded + kReach;
        }
        BasicReader<false> unbounded({from, end});
        fill(unbounded);
        const auto read = static_cast<std::size_t>(unbounded.at() - from);
        check(read <= left(), "truncated");
        at_ += read;
    }
    void check(bool ok, const char* what) {
        if (!ok) [[unlikely]]
            refuse(what);
    }
    template <class Describe> void checkOr(bool ok, Describe&& describe) {
        if (!ok)
            throw Refused{describe()};
    }
    std::size_t left() const { return static_cast<std::size_t>(end_ - at_); }
    const std::uint8_t* at() const { return at_; }

private:
    static constexpr std::size_t kLongestVar = 10;
    [[noreturn]] [[gnu::cold]] [[gnu::noinline]] static void refuse(const char* what) {
        throw Refused{what};
    }
    template <int N> std::uint64_t fixed() {
        if constexpr (Bounded)
            check(left() >= static_cast<std::size_t>(N), "truncated");
        std::uint64_t v = 0;
        if constexpr (std::endian::native == std::endian::little) {
            std::memcpy(&v, at_, N);
        } else {
            for (int i = N - 1; i >= 0; --i)
                v = v << 8 | at_[i];
        }
        at_ += N;
        return v;
    }
    /// A number of more than one byte, at most `largest`.
    std::uint64_t longVar(std::uint64_t largest) {
        std::uint64_t v = 0;
        for (int shift = 0;; shift += 7) {
            check(shift < 64, "a number is longer than 10 bytes");
            const std::uint8_t byte = static_cast<std::uint8_t>(fixed<1>());
            v |= std::uint64_t(byte & 0x7F) << shift;
            if ((byte & 0x80) == 0) {
                check(byte != 0 || shift == 0, "a number is not in its shortest form");
                break;
            }
        }
        check(v <= largest, "a number is out of its range");
        return v;
    }
    const std::uint8_t* at_;
    const std::uint8_t* end_;
};

using Reader = BasicReader<true>;

} // namespace jostle::snapshot
