// SPDX-License-Identifier: MIT
#pragma once
// A virtual texture as passes see it while the graph is being built: which resource, and
// which version of its contents. Every write produces a new version, so a handle names
// one specific state of the texture; that is what lets the graph tell a read of the
// opaque colour from a read of the opaque colour *after* foliage was composited into it.
#include <cstdint>
#include <limits>

namespace engine::render {

class FrameGraphTexture {
public:
    constexpr FrameGraphTexture() = default;

    constexpr bool isValid() const { return resource_ != kInvalid; }
    constexpr std::uint32_t resource() const { return resource_; }  // index in its graph
    constexpr std::uint32_t version() const { return version_; }    // 0 = as created / imported

    constexpr bool operator==(const FrameGraphTexture&) const = default;

private:
    friend class FrameGraph;  // the only place handles are minted, so they cannot be forged
    static constexpr std::uint32_t kInvalid = std::numeric_limits<std::uint32_t>::max();

    constexpr FrameGraphTexture(std::uint32_t resource, std::uint32_t version)
        : resource_(resource), version_(version) {}

    std::uint32_t resource_ = kInvalid;
    std::uint32_t version_ = 0;
};

}  // namespace engine::render
