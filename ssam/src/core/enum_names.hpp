// SPDX-License-Identifier: MIT
#pragma once
// The names of SSAM's public enums. Each enum is numbered from 0 in declaration order, so its
// names are a table in that order; the table is checked against the enum's last value, so a
// value added without a name does not compile. A value outside the enum (a cast, a corrupted
// struct) gets `unknown`.
#include <cstddef>

namespace ssam::core {

template <auto Last, std::size_t N>
const char* enumName(decltype(Last) value, const char* const (&names)[N], const char* unknown) noexcept {
    static_assert(static_cast<std::size_t>(Last) + 1 == N, "one name for every value of the enum, in order");
    const auto index = static_cast<std::size_t>(value);  // a negative value wraps far past N
    return index < N ? names[index] : unknown;
}

}  // namespace ssam::core
