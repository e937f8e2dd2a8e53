// SPDX-License-Identifier: MIT
#pragma once
// Everything a draw's geometry work reads (vertex stage, clipping, set-up and binning), so
// that two draws with equal keys make the same set-up triangles and bins, bit for bit: the
// soft backend then sets a draw up once for consecutive passes that draw the same thing
// (SSAM's mask and colour passes draw the same foliage batches with the same camera,
// [Hathaway 2010] §3.5.2-§3.5.3), instead of twice.
//
// Buffers are named by their content stamp, not their handle: a stamp is given to a buffer's
// contents at creation and at every update, from one counter that never repeats, so a buffer
// written in between, or destroyed and replaced by another at the same handle, never matches.
#include <cstddef>
#include <cstdint>

#include <glm/glm.hpp>

#include "engine/render/raster_state.hpp"
#include "engine/render/kernel/detail/same_bits.hpp"
#include "engine/render/kernel/detail/triangle_setup.hpp"

namespace engine::render::soft {

struct GeometryKey {
    std::uint64_t vertices = 0, indices = 0, instances = 0;  // content stamps; 0: none bound
    std::uint32_t first = 0, count = 0, instanceCount = 0;
    glm::mat4 viewProj{1.0f};  // compared by its bits: -0 and +0, or two NaNs, are not the same input
    Viewport viewport;         // the pass's size, the scissor and the sample pattern (the tile grid follows)
    RasterState raster;
};

inline bool sameGeometry(const GeometryKey& a, const GeometryKey& b) {
    return a.vertices == b.vertices && a.indices == b.indices && a.instances == b.instances && a.first == b.first &&
           a.count == b.count && a.instanceCount == b.instanceCount && sameBits(a.viewProj, b.viewProj) &&
           a.viewport.width == b.viewport.width && a.viewport.height == b.viewport.height &&
           a.viewport.scissor.x == b.viewport.scissor.x && a.viewport.scissor.y == b.viewport.scissor.y &&
           a.viewport.scissor.width == b.viewport.scissor.width &&
           a.viewport.scissor.height == b.viewport.scissor.height && a.viewport.pattern == b.viewport.pattern &&
           a.raster.cull == b.raster.cull && a.raster.frontFace == b.raster.frontFace;
}

// A hash of every field sameGeometry compares (FNV-1a over their values' bytes), so that a pass
// of many draws finds its kept draws without comparing each against each.
inline std::uint64_t geometryHash(const GeometryKey& k) {
    std::uint64_t h = 14695981039346656037ull;
    auto mix = [&h](const void* p, std::size_t n) {
        for (std::size_t i = 0; i < n; ++i) h = (h ^ static_cast<const unsigned char*>(p)[i]) * 1099511628211ull;
    };
    const std::uint64_t words[] = {k.vertices, k.indices, k.instances, k.first, k.count, k.instanceCount};
    mix(words, sizeof words);
    mix(&k.viewProj, sizeof k.viewProj);
    const int ints[] = {k.viewport.width,     k.viewport.height,        k.viewport.scissor.x,
                        k.viewport.scissor.y, k.viewport.scissor.width, k.viewport.scissor.height,
                        int(k.raster.cull),   int(k.raster.frontFace)};
    mix(ints, sizeof ints);
    const auto pattern = reinterpret_cast<std::uintptr_t>(k.viewport.pattern);  // compared by address
    mix(&pattern, sizeof pattern);
    return h;
}

}  // namespace engine::render::soft
