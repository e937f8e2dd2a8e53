// SPDX-License-Identifier: MIT
#include "geometry_stage.hpp"

#include <algorithm>
#include <array>

#include "engine/core/parallel_for.hpp"

namespace engine::render::soft {
namespace {

// Triangles per chunk of a draw's geometry work, and how many chunks' storage the stage
// keeps when a pass needs fewer (up to 128k triangles' worth, about 30 MiB).
constexpr std::uint64_t kChunk = 2048;
constexpr std::size_t kKeptChunks = 64;

// mvp * vec4(p, 1) as glm computes it, (m0 * x + m1 * y) + (m2 * z + m3 * 1) component by
// component, so the same bits; written out so that it is inlined into the vertex loop, where
// GCC kept glm's operator* out of line (a call per vertex: 3% of the 160x90 frame).
[[gnu::always_inline]] inline glm::vec4 transformPosition(const glm::mat4& m, const glm::vec3& p) {
    return (m[0] * p.x + m[1] * p.y) + (m[2] * p.z + m[3] * 1.0f);
}

// The vertices of the current instance an indexed draw's triangles share (a card's two
// triangles two of their three, a terrain grid's six triangles each vertex), each
// transformed, tested and projected once (prepareVertex): a small cache by vertex index,
// one entry per index modulo its size, emptied when the instance changes.
class PreparedVertices {
public:
    void clear() { tags_.fill(0); }
    // Whether the three indices take three different entries (or share one by being equal).
    bool distinctSlots(const std::uint32_t (&index)[3]) const {
        auto clash = [&](int a, int b) { return index[a] != index[b] && slot(index[a]) == slot(index[b]); };
        return !clash(0, 1) && !clash(0, 2) && !clash(1, 2);
    }
    PreparedVertex& get(std::uint32_t index, const Vertex& vertex, const glm::mat4& mvp, const Viewport& vp) {
        const std::size_t s = slot(index);
        PreparedVertex& p = entries_[s];
        if (tags_[s] != index + 1u) {  // 0: empty (an index of 2^32 - 1 never reaches here)
            tags_[s] = index + 1u;
            p.clip.position = transformPosition(mvp, vertex.position);
            prepareVertex(p, vp);
        }
        return p;
    }

private:
    static constexpr std::size_t kEntries = 64;
    static std::size_t slot(std::uint32_t index) { return index % kEntries; }
    std::array<std::uint32_t, kEntries> tags_{};
    std::array<PreparedVertex, kEntries> entries_;
};

// A triangle's normals (by the instance's model matrix) and colours (tinted), computed
// when set-up asks: not for the triangles it culls or finds covering no sample.
class VertexAttributes final : public AttributeSource {
public:
    VertexAttributes(const Vertex* const (&v)[3], const glm::mat3& normalMatrix, const glm::vec4& tint)
        : v_(v), normalMatrix_(normalMatrix), tint_(tint) {}
    void fillVertex(int k, ClipVertex& cv) const override {
        const glm::vec3 n = normalMatrix_ * v_[k]->normal;
        const glm::vec4 c = v_[k]->color * tint_;
        cv.attributes = {v_[k]->uv.x, v_[k]->uv.y, n.x, n.y, n.z, c.r, c.g, c.b, c.a};
    }

private:
    const Vertex* const (&v_)[3];
    const glm::mat3& normalMatrix_;
    const glm::vec4& tint_;
};

void processChunk(const DrawGeometry& g, GeometryChunk& out) {
    std::uint64_t cachedInstance = ~0ull;
    glm::mat4 mvp(1.0f);
    glm::mat3 normalMatrix(1.0f);
    PreparedVertices prepared;
    for (std::uint64_t t = out.begin; t < out.end; ++t) {
        const std::uint64_t instance = t / g.trianglesPerInstance, tri = t % g.trianglesPerInstance;
        const Instance& inst = g.instances[instance];
        if (instance != cachedInstance) {
            mvp = g.viewProj * inst.model;
            normalMatrix = glm::mat3(inst.model);
            cachedInstance = instance;
            prepared.clear();
            // An instance wholly beyond a clip plane: each of its triangles (those in this
            // chunk) would be rejected, and counted, by setupTriangle.
            if (instanceOutsideOnePlane(mvp, *g.bounds, g.viewport)) {
                const std::uint64_t instanceEnd = std::min(out.end, (instance + 1) * g.trianglesPerInstance);
                out.counters.dropped += instanceEnd - t;
                t = instanceEnd - 1;
                continue;
            }
        }
        const Vertex* v[3];
        std::uint32_t index[3];
        for (int k = 0; k < 3; ++k) {
            index[k] = g.indices ? g.indices[tri * 3 + k] : g.first + std::uint32_t(tri * 3 + k);
            v[k] = &g.vertices[index[k]];
        }
        const VertexAttributes attributes(v, normalMatrix, inst.tint);
        if (g.indices && prepared.distinctSlots(index)) {
            PreparedVertex* const p[3] = {&prepared.get(index[0], *v[0], mvp, g.viewport),
                                          &prepared.get(index[1], *v[1], mvp, g.viewport),
                                          &prepared.get(index[2], *v[2], mvp, g.viewport)};
            // rejectedBeforeSetup, from what the vertices hold.
            if (!(p[0]->finite && p[1]->finite && p[2]->finite) ||
                outsideOnePlane(p[0]->clip, p[1]->clip, p[2]->clip, g.viewport)) {
                ++out.counters.dropped;
                continue;
            }
            setupPreparedTriangle(p, attributes, g.viewport, g.raster, g.drawIndex, out.triangles, out.counters);
            continue;
        }
        ClipVertex cv[3];
        for (int k = 0; k < 3; ++k) cv[k].position = transformPosition(mvp, v[k]->position);
        // Positions first: a triangle setupTriangle would reject at once (NaN, or beyond one
        // plane) needs no normals or colours (most of the terrain, off to the sides).
        if (rejectedBeforeSetup(cv[0], cv[1], cv[2], g.viewport)) {
            ++out.counters.dropped;
            continue;
        }
        setupUnrejectedTriangle(cv, attributes, g.viewport, g.raster, g.drawIndex, out.triangles, out.counters);
    }
}

}  // namespace

void GeometryStage::beginPass() {
    std::swap(chunks_, keptChunks_);
    std::swap(planned_, kept_);
    planned_.clear();
    keptByHash_.clear();
    if (reuseGeometry_) {
        for (std::size_t i = 0; i < kept_.size(); ++i) keptByHash_.emplace_back(geometryHash(kept_[i].key), i);
        std::sort(keptByHash_.begin(), keptByHash_.end());
    }
    chunksUsed_ = 0;
    geometry_.clear();
}

void GeometryStage::planFullscreen(const Viewport& vp, std::uint32_t drawIndex, const TileGrid& grid) {
    if (vp.scissor.empty()) return;
    GeometryChunk& chunk = chunks_[nextChunks(1)];
    chunk.triangles.push_back(fullscreenTriangle(vp, drawIndex));
    binTriangle(chunk.triangles.back(), 0, grid, chunk.bins);
}

bool GeometryStage::plan(const DrawGeometry& g, const GeometryKey& key) {
    const std::uint64_t chunks = (g.total + kChunk - 1) / kChunk;
    const std::size_t first = nextChunks(chunks);
    planned_.push_back({key, first, chunks, g.drawIndex, false});
    if (reuseGeometry_ && takeKeptGeometry(key, first, g.drawIndex)) return true;
    for (std::uint64_t c = 0; c < chunks; ++c) {
        GeometryChunk& chunk = chunks_[first + c];
        chunk.geometry = geometry_.size();
        chunk.begin = c * kChunk;
        chunk.end = std::min(g.total, chunk.begin + kChunk);
    }
    geometry_.push_back(g);
    return false;
}

// Moves the chunks of the last pass's draw with this key, if there is one, into this pass's
// chunks from `first` on, as set up and binned for `drawIndex`: the same triangles and bins
// the geometry work would make again (geometry_key.hpp); only the index of the draw they
// belong to may differ. Each kept draw is taken once.
bool GeometryStage::takeKeptGeometry(const GeometryKey& key, std::size_t first, std::uint32_t drawIndex) {
    const std::uint64_t hash = geometryHash(key);
    const auto byHash = [](const std::pair<std::uint64_t, std::size_t>& e, std::uint64_t h) { return e.first < h; };
    for (auto it = std::lower_bound(keptByHash_.begin(), keptByHash_.end(), hash, byHash);
         it != keptByHash_.end() && it->first == hash; ++it) {
        PlannedGeometry& kept = kept_[it->second];
        if (kept.taken || !sameGeometry(kept.key, key)) continue;
        kept.taken = true;
        for (std::size_t c = 0; c < kept.chunkCount; ++c) {
            GeometryChunk& chunk = chunks_[first + c];
            std::swap(chunk, keptChunks_[kept.firstChunk + c]);
            chunk.geometry = kNoGeometry;  // set up and binned already
            if (kept.drawIndex != drawIndex)
                for (SetupTriangle& t : chunk.triangles) t.drawIndex = drawIndex;
        }
        return true;
    }
    return false;
}

void GeometryStage::runGeometry(tbb::task_arena& arena, const TileGrid& grid) {
    arena.execute([&] {
        parallelFor(std::size_t(0), chunksUsed_, [&](std::size_t c) {
            GeometryChunk& out = chunks_[c];
            if (out.geometry == kNoGeometry) return;  // a full-screen triangle, already binned
            processChunk(geometry_[out.geometry], out);
            for (std::size_t i = 0; i < out.triangles.size(); ++i)
                binTriangle(out.triangles[i], std::uint32_t(i), grid, out.bins);
        });
    });
}

void GeometryStage::endPass() {
    // Storage this pass did not need is given back beyond a frame's worth (passes of one
    // frame need different amounts: freeing it each pass reallocated it each frame);
    // what it used is kept for the next.
    chunks_.resize(std::max(chunksUsed_, std::min(chunks_.size(), kKeptChunks)));
    keptChunks_.resize(std::min(keptChunks_.size(), kKeptChunks));
    kept_.clear();
    keptByHash_.clear();
}

// `count` cleared chunks after those already used in this pass; the index of the first.
std::size_t GeometryStage::nextChunks(std::uint64_t count) {
    if (chunks_.size() < chunksUsed_ + count) chunks_.resize(chunksUsed_ + count);
    for (std::size_t i = chunksUsed_; i < chunksUsed_ + count; ++i) {
        GeometryChunk& c = chunks_[i];
        c.triangles.clear();
        c.bins.clear();
        c.counters = {};
        c.geometry = kNoGeometry;
    }
    const std::size_t first = chunksUsed_;
    chunksUsed_ += count;
    return first;
}

}  // namespace engine::render::soft
