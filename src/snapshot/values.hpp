// The values a snapshot is made of, each in its one encoding (docs/snapshots.md), for both
// directions of archive.hpp: settings by their type, lists of slots, references to a body,
// normals.
#pragma once

#include "../handles.hpp"
#include "archive.hpp"
#include "jostle/body.hpp"
#include "jostle/world.hpp"

#include <bit>
#include <cstdint>
#include <type_traits>
#include <vector>

namespace jostle::snapshot {

// A setting, by its type: floats by their bits, whole numbers as `var`, enumerations and
// flags as a byte (their tables' checks refuse what no setter would take).
template <class Ar> void value(Ar& ar, float& v) {
    ar.f32(v);
}
template <class Ar> void value(Ar& ar, Vec2& v) {
    ar.vec(v);
}
template <class Ar> void value(Ar& ar, bool& v) {
    ar.flag(v);
}
template <class Ar> void value(Ar& ar, std::uint32_t& v) {
    ar.var(v);
}
template <class Ar> void value(Ar& ar, int& v) {
    std::uint32_t bits = static_cast<std::uint32_t>(v);
    ar.var(bits);
    v = static_cast<int>(bits);
}
template <class Ar, class E>
requires std::is_enum_v<E>
void value(Ar& ar, E& v) {
    auto byte = static_cast<std::uint8_t>(v);
    ar.u8(byte);
    v = static_cast<E>(byte);
}
/// Pointers (userData) belong to the process: never saved.
template <class Ar> void value(Ar&, void*&) {}

/// A list: its count, then each item by each(item), at least `minBytes` long (a reader
/// checks the count against the bytes left before it makes room).
template <class Ar, class T, class Each>
void sequence(Ar& ar, std::vector<T>& items, std::size_t minBytes, Each&& each) {
    std::uint32_t count = static_cast<std::uint32_t>(items.size());
    ar.count(count, minBytes);
    if constexpr (Ar::kReading)
        items.resize(count);
    for (T& item : items)
        each(item);
}

/// What a reader has met of the numbers below a limit, for lists in which each may stand
/// once (free slots, a map's free tickets, an island's bodies); a writer keeps nothing and
/// asks nothing.
template <class Ar> class MetOnce {
public:
    explicit MetOnce(std::size_t limit) : met_(Ar::kReading ? limit : 0, 0) {}
    /// True the first time `n` is met.
    bool first(std::uint32_t n) {
        if (met_[n] != 0)
            return false;
        met_[n] = 1;
        return true;
    }
    bool met(std::uint32_t n) const { return met_[n] != 0; }

private:
    std::vector<std::uint8_t> met_;
};

/// A list of numbers below `limit` (slots, islands, tickets, pieces) in its order;
/// `check(n)` is called on each number read.
template <class Ar, class N, class Check>
void slotList(Ar& ar, std::vector<N>& list, std::uint32_t limit, Check&& check) {
    std::uint32_t count = static_cast<std::uint32_t>(list.size());
    ar.count(count, 1);
    if constexpr (Ar::kReading)
        list.resize(count);
    for (N& item : list) {
        std::uint32_t n = static_cast<std::uint32_t>(item);
        ar.var(n);
        if constexpr (Ar::kReading) {
            ar.check(n < limit, "a list's number is out of range");
            check(n);
            item = static_cast<N>(n);
        }
    }
}

/// A slot and its occupant's generation (0: none), the slot below `slots`.
template <class Ar>
[[gnu::always_inline]] inline void ref(Ar& ar, SlotRef& r, std::uint32_t slots) {
    ar.var(r.index);
    ar.var(r.generation);
    ar.check(r.index < slots || r.isNull(), "a body's slot is out of range");
}

/// A handle this world gave: saved as its slot and generation; read back as this world's
/// (`serial`), the null handle as null.
template <class Ar, class Id>
void handle(Ar& ar, Id& id, std::uint32_t serial, std::uint32_t slots) {
    SlotRef r{id.index, id.generation};
    ref(ar, r, slots);
    if constexpr (Ar::kReading)
        id = r.isNull() ? Id{} : Id{r.index, r.generation, serial};
}

/// A normal: one byte for the four axis directions (most contacts between boxes), else the
/// byte 4 and its two floats.
template <class Ar> [[gnu::always_inline]] inline void normal(Ar& ar, Vec2& n) {
    static constexpr Vec2 kAxes[] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
    std::uint8_t code = 4;
    if constexpr (!Ar::kReading) {
        constexpr std::uint32_t kOne = 0x3F800000, kMinusOne = 0xBF800000; // ±1.0f's bits
        const auto x = std::bit_cast<std::uint32_t>(n.x), y = std::bit_cast<std::uint32_t>(n.y);
        if (y == 0)
            code = x == kOne ? 0 : x == kMinusOne ? 1 : 4;
        else if (x == 0)
            code = y == kOne ? 2 : y == kMinusOne ? 3 : 4;
    }
    ar.u8(code);
    ar.check(code <= 4, "a normal's code");
    if (code < 4)
        n = kAxes[code];
    else
        ar.vec(n);
    ar.check(isFinite(n), "a normal is not finite");
}

} // namespace jostle::snapshot
