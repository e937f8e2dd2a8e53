// SPDX-License-Identifier: MIT
#pragma once
// Entity: a 32-bit handle = slot index (low 22 bits) + generation (high 10 bits).
//
// Why 22/10: the index bits bound how many entities can be alive at once (4,194,303,
// room for the 1M-entity benchmarks and then some); the generation bits only bound
// how often one slot can be reused before it is retired. A slot whose generation
// would wrap (its 1024th destroy) is retired for good instead of going back to the
// free list, so a stale handle can never alias a later occupant. The price is index
// space: a registry hands out about 2^32 entity lifetimes (4M slots x 1024
// generations) before create() throws engine::Error; 10k creates per frame at
// 60 fps would take about two hours to get there.
//
// An Entity is plain data: comparing and hashing it is cheap, and it says nothing
// about liveness on its own. Ask the Registry (`registry.alive(e)`).
#include <compare>
#include <cstdint>
#include <functional>
#include <ostream>

namespace engine::ecs {

class Entity {
public:
    static constexpr unsigned kIndexBits = 22;
    static constexpr unsigned kGenerationBits = 32 - kIndexBits;
    static constexpr std::uint32_t kIndexMask = (1u << kIndexBits) - 1;
    static constexpr std::uint32_t kGenerationMask = (1u << kGenerationBits) - 1;
    // The all-ones index belongs to null(), so it is never handed out.
    static constexpr std::uint32_t kMaxIndex = kIndexMask - 1;
    static constexpr std::uint32_t kMaxGeneration = kGenerationMask;

    // Default-constructed handles are null: never alive in any registry.
    constexpr Entity() noexcept = default;

    static constexpr Entity null() noexcept { return Entity{}; }
    // `index` and `generation` are masked to their widths.
    static constexpr Entity fromParts(std::uint32_t index, std::uint32_t generation) noexcept {
        return fromBits((index & kIndexMask) | ((generation & kGenerationMask) << kIndexBits));
    }
    static constexpr Entity fromBits(std::uint32_t bits) noexcept {
        Entity e;
        e.bits_ = bits;
        return e;
    }

    constexpr std::uint32_t index() const noexcept { return bits_ & kIndexMask; }
    constexpr std::uint32_t generation() const noexcept { return bits_ >> kIndexBits; }
    constexpr std::uint32_t bits() const noexcept { return bits_; }
    constexpr bool isNull() const noexcept { return bits_ == ~std::uint32_t{0}; }

    friend constexpr bool operator==(Entity, Entity) noexcept = default;
    // An arbitrary but stable order, so handles can key ordered containers.
    friend constexpr auto operator<=>(Entity, Entity) noexcept = default;

private:
    std::uint32_t bits_ = ~std::uint32_t{0};
};

// "entity 12 (gen 3)", or "null entity"; used in every ECS error message.
inline std::ostream& operator<<(std::ostream& out, Entity e) {
    if (e.isNull()) return out << "null entity";
    return out << "entity " << e.index() << " (gen " << e.generation() << ')';
}

}  // namespace engine::ecs

template <>
struct std::hash<engine::ecs::Entity> {
    std::size_t operator()(engine::ecs::Entity e) const noexcept { return std::hash<std::uint32_t>{}(e.bits()); }
};
