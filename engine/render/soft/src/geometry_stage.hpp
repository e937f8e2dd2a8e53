// SPDX-License-Identifier: MIT
#pragma once
// The geometry stage of a pass: vertex stage + clipping + setup + binning for each draw, in
// fixed chunks of triangles; each chunk keeps its triangles and their (tile, triangle) bin
// entries in submission order, and the tile loop merges chunks into the tile bins in order,
// so the result is independent of the thread count. A draw's chunks are only planned as the
// pass's draws are read: runGeometry() runs every chunk of the pass in one parallel loop, so a
// pass of many small draws (foliage batches of a chunk or two each) uses every thread. Chunk
// storage is reused from pass to pass, and a pass may take the chunks of the pass before for
// the draws that have the same geometry (geometry_key.hpp) instead of setting them up again.
#include <cstddef>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include <tbb/task_arena.h>

#include "engine/render/raster_state.hpp"
#include "engine/render/vertex.hpp"
#include "engine/render/kernel/detail/triangle_setup.hpp"
#include "geometry_key.hpp"
#include "instance_culling.hpp"
#include "tile_rasterizer.hpp"

namespace engine::render::soft {

// What the vertex stage of one draw reads, resolved once per draw.
struct DrawGeometry {
    const Vertex* vertices;
    const std::uint32_t* indices;  // from the draw's first index; null: non-indexed
    std::uint32_t first;
    const Instance* instances;
    const PositionBounds* bounds;  // of the vertex buffer's positions
    glm::mat4 viewProj;
    Viewport viewport;
    RasterState raster;
    std::uint32_t drawIndex;
    std::uint64_t trianglesPerInstance, total;
};

constexpr std::size_t kNoGeometry = ~std::size_t(0);

// One chunk of a draw's triangles after setup, with the tiles each may cover.
struct GeometryChunk {
    std::vector<SetupTriangle> triangles;
    std::vector<BinEntry> bins;  // in submission order
    SetupCounters counters;
    // The DrawGeometry it sets up triangles [begin, end) of; kNoGeometry: already set up and
    // binned when planned (a full-screen triangle, or a draw's chunks kept from the last pass).
    std::size_t geometry = kNoGeometry;
    std::uint64_t begin = 0, end = 0;
};

class GeometryStage {
public:
    explicit GeometryStage(bool reuseGeometry) : reuseGeometry_(reuseGeometry) {}

    // The last pass's chunks are kept for this one's draws to take; their storage, and the
    // older one's, is reused for the chunks set up here.
    void beginPass();
    // A full-screen draw's one triangle, set up and binned here.
    void planFullscreen(const Viewport& vp, std::uint32_t drawIndex, const TileGrid& grid);
    // The chunks of a draw with triangles (g.total > 0) and a scissor that is not empty;
    // whether they were taken from the last pass, set up already.
    bool plan(const DrawGeometry& g, const GeometryKey& key);
    // Sets up and bins every chunk planned in this pass and not set up yet.
    void runGeometry(tbb::task_arena& arena, const TileGrid& grid);
    // The chunks of this pass, in submission order.
    std::span<const GeometryChunk> chunks() const { return {chunks_.data(), chunksUsed_}; }
    // After the tile loop: this pass's chunks are kept for the next.
    void endPass();
    // Chunks of a pass that threw may not have been set up: none is offered to the next.
    void forgetPlanned() noexcept { planned_.clear(); }

private:
    // A draw's chunks in a pass, found by what they were set up from.
    struct PlannedGeometry {
        GeometryKey key;
        std::size_t firstChunk = 0, chunkCount = 0;
        std::uint32_t drawIndex = 0;
        bool taken = false;  // moved into a later pass
    };

    bool takeKeptGeometry(const GeometryKey& key, std::size_t first, std::uint32_t drawIndex);
    std::size_t nextChunks(std::uint64_t count);

    bool reuseGeometry_;
    std::vector<GeometryChunk> chunks_;   // setup output of the pass being executed
    std::vector<DrawGeometry> geometry_;  // the vertex input of its draws
    std::size_t chunksUsed_ = 0;
    std::vector<PlannedGeometry> planned_;   // which of chunks_ each draw's are
    std::vector<GeometryChunk> keptChunks_;  // the last execution's chunks, while this one plans
    std::vector<PlannedGeometry> kept_;      // which of keptChunks_ each of its draws' are
    // (geometryHash, index in kept_), sorted: a pass of many draws finds its kept ones by search.
    std::vector<std::pair<std::uint64_t, std::size_t>> keptByHash_;
};

}  // namespace engine::render::soft
