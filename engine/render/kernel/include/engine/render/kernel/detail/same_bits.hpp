// SPDX-License-Identifier: MIT
#pragma once
// Whether two values hold the same bits: how the soft backend recognises the same input again
// (a cached blend table, a kept draw's geometry), where -0 and +0, or two NaNs, are different
// inputs even though they compare equal, or unequal, as numbers.
#include <array>
#include <cstddef>
#include <type_traits>

#include "engine/core/bit_cast.hpp"

namespace engine::render::soft {

template <typename T>
bool sameBits(const T& a, const T& b) {
    static_assert(std::is_trivially_copyable_v<T>, "compared by its bits");
    using Bytes = std::array<std::byte, sizeof(T)>;
    return engine::bitCast<Bytes>(a) == engine::bitCast<Bytes>(b);
}

}  // namespace engine::render::soft
