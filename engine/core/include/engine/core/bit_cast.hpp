// SPDX-License-Identifier: MIT
#pragma once
// engine::bitCast<To>(from): the bits of one trivially copyable value as another type of the same
// size (std::bit_cast). It exists because the C++ library of Debian's Emscripten 3.1.6 (the web
// page's build, README "In a browser") has no std::bit_cast: there it is a memcpy, which compilers
// lower to the same single move, and not constexpr. Every caller that needs the bits (the soft
// backend's same-input checks, hashed alpha's seeds and cells) uses this one helper.
#include <cstring>
#include <type_traits>
#if __has_include(<bit>)
#include <bit>
#endif

namespace engine {

#if defined(__cpp_lib_bit_cast)
template <typename To, typename From>
constexpr To bitCast(const From& from) noexcept {
    return std::bit_cast<To>(from);
}
#else
template <typename To, typename From>
To bitCast(const From& from) noexcept {
    static_assert(sizeof(To) == sizeof(From), "bitCast: both types have the same size");
    static_assert(std::is_trivially_copyable_v<To> && std::is_trivially_copyable_v<From>,
                  "bitCast: both types are trivially copyable");
    To to;
    std::memcpy(&to, &from, sizeof to);
    return to;
}
#endif

}  // namespace engine
