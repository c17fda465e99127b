// std::bit_cast where the standard library lacks it: Debian's emscripten 3.1.6 ships
// libc++ 13, which has the rest of <bit> but not bit_cast (libc++ 14 added it). Forced
// into every file of the web build (-include), so that the code keeps the standard name.
#pragma once

#include <bit>
#include <version>

#ifndef __cpp_lib_bit_cast
#include <type_traits>

namespace std {

template <class To, class From>
requires(sizeof(To) == sizeof(From) && is_trivially_copyable_v<To> &&
         is_trivially_copyable_v<From>) constexpr To bit_cast(const From& from) noexcept {
    return __builtin_bit_cast(To, from);
}

} // namespace std
#endif
