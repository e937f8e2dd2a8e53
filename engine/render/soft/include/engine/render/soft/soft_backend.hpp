// SPDX-License-Identifier: MIT
#pragma once
// The CPU software driver under the render front end (device.hpp): the embedded default,
// what CI runs and what goldens come from. Fixed-point tile rasterizer (8 sub-pixel bits, top-left rule), hierarchical
// tile -> block -> pixel coverage, oneTBB across tiles with primitives in submission
// order inside each tile, so images are bit-identical for any thread count.
#include <cstdint>
#include <memory>
#include <optional>

#include <glm/glm.hpp>

#include "engine/render/device.hpp"
#include "engine/render/driver.hpp"
#include "engine/render/kernel/simd_isa.hpp"

namespace engine::render::soft {

struct SoftOptions {
    int threads = 0;           // 0: all hardware threads
    int tileSize = 64;         // pixels, a multiple of 8 (llvmpipe's choice by default)
    bool debugChecks = false;  // count NaN/Inf stored into float targets and log them per pass
    // The wide kernels' instruction set; unset: the widest this CPU runs (bestSimdIsa()). One
    // this CPU does not run is refused at creation. Images are the same bits with any.
    std::optional<SimdIsa> simd = std::nullopt;
    // A draw whose geometry input equals one of the last pass's draws (same buffer contents,
    // camera, viewport, scissor, sample pattern and raster state: src/geometry_key.hpp) takes
    // that draw's set-up triangles and bins instead of making them again (SSAM's colour pass
    // after its mask pass). Off only to measure what it saves; images are the same bits.
    bool reuseGeometry = true;
    // In a pass whose draws test depth and none writes it, a triangle's 8x8 block that lies behind
    // every depth stored there is skipped before its rows (kernel/detail/depth_block_bounds.hpp).
    // Off only to measure what it saves; images are the same bits.
    bool depthBlockBounds = true;
};

// Work counters since creation, for tests and the benchmark (what was skipped is visible).
struct SoftStats {
    std::uint64_t passes = 0;
    std::uint64_t draws = 0;
    std::uint64_t trianglesIn = 0;          // primitives submitted
    std::uint64_t trianglesRasterized = 0;  // after clipping, culling, dropping degenerate/NaN ones
    std::uint64_t trianglesDropped = 0;     // degenerate, NaN or fully clipped
    std::uint64_t trianglesReused = 0;      // of trianglesIn: set up in the pass before (reuseGeometry)
    std::uint64_t pixelsShaded = 0;         // program invocations
    std::uint64_t pixelsTouched = 0;        // pixels for which any sample passed coverage + depth
    std::uint64_t depthBlocksSkipped = 0;   // a triangle's 8x8 blocks behind every stored depth (depthBlockBounds)
    std::uint64_t nonFiniteStores = 0;      // NaN/Inf written to float targets (debugChecks only)
};

// Fragment capture (engine/render/fragment_capture.hpp), by the names it had here.
using engine::render::CapturedFragment;
using engine::render::FragmentSink;

// What only the soft driver offers, reached as device.driverAs<SoftDriver>().
class SoftDriver : public Driver, public FragmentCapture {
public:
    virtual SoftStats stats() const = 0;
    virtual const SoftOptions& options() const = 0;
    FragmentCapture* fragmentCapture() override { return this; }
};

// A render device over the soft driver. Throws engine::Error for options it cannot use.
std::unique_ptr<Device> createSoftBackend(const SoftOptions& options = {});

// The soft driver under `device`; engine::Error when it runs another.
inline SoftDriver& softDriver(const Device& device) { return device.driverAs<SoftDriver>(); }

}  // namespace engine::render::soft
