// SPDX-License-Identifier: MIT
#pragma once
// Component type identity without RTTI lookups: a dense id per type (so the Registry
// finds a pool by indexing a vector) and a readable name (for error messages).
#include <atomic>
#include <cstddef>
#include <string_view>
#include <type_traits>

namespace engine::ecs {

using ComponentTypeId = std::size_t;

namespace detail {
// One counter for the whole program: an inline function's static is shared by every
// translation unit, so a type gets the same id wherever it is first asked for.
inline ComponentTypeId nextComponentTypeId() noexcept {
    static std::atomic<ComponentTypeId> next{0};
    return next.fetch_add(1, std::memory_order_relaxed);
}

template <class T>
constexpr std::string_view prettyTypeName() noexcept {
    // GCC: "... [with T = Position; ...]"   Clang: "... [T = Position]"
    constexpr std::string_view signature = __PRETTY_FUNCTION__;
    constexpr std::string_view marker = "T = ";
    constexpr std::size_t start = signature.find(marker) + marker.size();
    constexpr std::size_t semicolon = signature.find(';', start);
    constexpr std::size_t end = semicolon != std::string_view::npos ? semicolon : signature.rfind(']');
    return signature.substr(start, end - start);
}
}  // namespace detail

// Ids are dense from 0 in first-use order; cv-qualifiers do not make a new type.
template <class T>
ComponentTypeId componentTypeId() noexcept {
    using Plain = std::remove_cv_t<T>;
    if constexpr (!std::is_same_v<Plain, T>) {
        return componentTypeId<Plain>();
    } else {
        static const ComponentTypeId id = detail::nextComponentTypeId();
        return id;
    }
}

// The type as written in source, e.g. "game::Velocity".
template <class T>
constexpr std::string_view componentTypeName() noexcept {
    return detail::prettyTypeName<std::remove_cv_t<T>>();
}

}  // namespace engine::ecs
