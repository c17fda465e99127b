// Room in a list that a step fills again each time (contacts, the events' lists of
// touching pairs): made to measure the first time, then grown to what it needs and an
// eighth more, not doubled, so that it holds little more than it needs (doubling left up
// to twice) and a growing world still grows it once in a few steps, not every step.
#pragma once

#include <cstddef>
#include <vector>

namespace jostle {

/// Makes `items` able to hold `n` without growing again, keeping what it holds.
template <class T> void makeRoom(std::vector<T>& items, std::size_t n) {
    if (items.capacity() < n)
        items.reserve(items.capacity() == 0 ? n : n + n / 8);
}

/// Room kept whatever a list needs: below it, giving room back saves too little to pay.
inline constexpr std::size_t kRoomAlwaysKept = 256;

/// Resizes `items` to `n` for contents written anew: if it must grow, what it holds is
/// dropped first, so that nothing is copied, and it grows as makeRoom grows it.
template <class T> void resizeAnew(std::vector<T>& items, std::size_t n) {
    if (items.capacity() < n)
        items.clear();
    makeRoom(items, n);
    items.resize(n);
}

/// resizeAnew for the lists made of a step's contacts, which a burst may have grown (a
/// pile's contacts while it landed): where it holds room for a quarter more than `n` and
/// beyond, it is made anew at what makeRoom would grow it to. (Not for a list whose size
/// swings from step to step, such as the events' sort scratch, which takes turns with the
/// last step's list: it would be made anew every step.)
template <class T> void resizeAnewToFit(std::vector<T>& items, std::size_t n) {
    if (items.capacity() > n + n / 4 + kRoomAlwaysKept) {
        std::vector<T> smaller;
        smaller.reserve(n + n / 8);
        items.swap(smaller);
    }
    resizeAnew(items, n);
}

/// The room a table indexed by body slot grows to when it is full and `size` slots are not
/// enough: half as many again, not double, so that it holds at most a third more than it
/// needs (doubling left up to half of it empty), for a third more copies as it grows.
inline std::size_t slotRoomAfter(std::size_t size) {
    constexpr std::size_t kFirstRoom = 16;
    return size < kFirstRoom ? kFirstRoom : size + size / 2;
}

/// Empties `items`, giving its memory back where it holds far more than it held last: the
/// lists of one step's events, which a burst (a pile landing at once begins thousands of
/// contacts in one step, then none) would otherwise keep at the burst's size for good.
template <class T> void clearAfterBurst(std::vector<T>& items) {
    if (items.capacity() > 4 * items.size() + kRoomAlwaysKept)
        std::vector<T>().swap(items);
    else
        items.clear();
}

} // namespace jostle
