// SPDX-License-Identifier: MIT
#pragma once
// One draw's program parameters: a copy of the program's own plain parameter struct, kept in
// place (no allocation per draw) and tagged with its type, so a backend hands the kernel
// exactly the struct its program was described with (ProgramDesc::params) and refuses any
// other. Parameter structs are plain data: trivially copyable, at most kCapacity bytes.
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <type_traits>

namespace engine::render {

// Identifies a parameter struct type: the address of a per-type object (one per program
// image, as every inline function's static is).
using ParamsType = const void*;
template <typename Params>
ParamsType paramsType() {
    static constexpr char tag = 0;
    return &tag;
}

class DrawParams {
public:
    static constexpr std::size_t kCapacity = 240;

    DrawParams() = default;
    template <typename Params>
    requires(!std::is_same_v<std::decay_t<Params>, DrawParams>) DrawParams(const Params& params)
        : type_(paramsType<Params>()) {  // NOLINT: implicit by design
        static_assert(std::is_trivially_copyable_v<Params>, "draw parameters are plain data");
        static_assert(sizeof(Params) <= kCapacity, "draw parameters exceed DrawParams::kCapacity");
        static_assert(alignof(Params) <= 16, "draw parameters need at most 16-byte alignment");
        std::memcpy(bytes_.data(), &params, sizeof(Params));
    }

    ParamsType type() const { return type_; }
    bool empty() const { return type_ == nullptr; }
    const void* data() const { return bytes_.data(); }

    // The parameters as `Params`, or null when they are of another type.
    template <typename Params>
    const Params* get() const {
        return type_ == paramsType<Params>() ? reinterpret_cast<const Params*>(bytes_.data()) : nullptr;
    }

private:
    alignas(16) std::array<std::byte, kCapacity> bytes_{};
    ParamsType type_ = nullptr;
};

}  // namespace engine::render
