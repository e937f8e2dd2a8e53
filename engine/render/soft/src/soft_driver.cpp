// SPDX-License-Identifier: MIT
#include "engine/render/soft/soft_backend.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstring>
#include <optional>
#include <utility>

#include <tbb/task_arena.h>

#include "engine/core/error.hpp"
#include "engine/core/parallel_for.hpp"
#include "engine/core/log.hpp"
#include "engine/render/memory_budget.hpp"
#include "engine/render/resolved_draw_state.hpp"
#include "engine/render/native_slots.hpp"
#include "engine/render/standard_programs.hpp"
#include "engine/render/validation.hpp"
#include "engine/render/vertex.hpp"
#include "engine/render/kernel/detail/depth_block_bounds.hpp"
#include "engine/render/kernel/detail/draw_state.hpp"
#include "engine/render/pixel_codec.hpp"
#include "engine/render/kernel/sampler.hpp"
#include "engine/render/kernel/soft_texture.hpp"
#include "geometry_key.hpp"
#include "geometry_stage.hpp"
#include "instance_culling.hpp"
#include "standard_kernels.hpp"
#include "tile_rasterizer.hpp"
#include "engine/render/kernel/detail/triangle_setup.hpp"

namespace engine::render::soft {
namespace {

using Clock = std::chrono::steady_clock;

struct SoftBuffer {
    BufferDesc desc;
    std::vector<std::byte> bytes;
    // Vertex buffers: the box of the positions, found at the first draw after a write.
    std::optional<PositionBounds> bounds;
    std::uint64_t stamp = 0;  // of these contents (geometry_key.hpp): new at creation and each update
};

// A draw as the device resolved it, kept until the pass executes: what it reads is copied,
// since a pipeline made later in the pass may move the device's slots.
struct RecordedDraw {
    DrawDesc desc;
    ResolvedDrawState state;
    RasterState raster;
    NativeId program = kNoNative;
    NativeId vertices = kNoNative, indices = kNoNative, instances = kNoNative;
    bool fullscreen = false;
    FragmentSink* sink = nullptr;  // set: the draw's fragments are captured, not written
};

// An occlusion query: what the last pass that counted into it found.
struct SoftQuery {
    bool anyPassed = false;
};

class SoftDriverImpl final : public SoftDriver {
public:
    explicit SoftDriverImpl(const SoftOptions& options)
        : options_(options), arena_(options.threads > 0 ? options.threads : tbb::task_arena::automatic) {
        if (options.tileSize < 8 || options.tileSize % 8 != 0 || options.tileSize > 1024)
            throw Error("soft backend: tileSize " + std::to_string(options.tileSize) +
                        " must be a multiple of 8 in [8, 1024]");
        if (!options_.simd) options_.simd = bestSimdIsa();
        if (!simdIsaSupported(*options_.simd)) throw Error("soft backend: " + simdIsaRefusal(*options_.simd));
    }

    std::string name() const override { return "soft"; }
    std::string describe() const override {
        return "soft: " + std::to_string(arena_.max_concurrency()) + " thread(s), " + simdIsaName(*options_.simd);
    }
    void attach(const NativeTextures& textures) override { textureLookup_.natives = &textures; }
    // The kernels carry out the fail modes themselves: no emulation plan is made.
    FailModeEmulation failModeEmulation() const override { return FailModeEmulation::None; }
    SoftStats stats() const override { return stats_; }
    const SoftOptions& options() const override { return options_; }
    void setFragmentSink(FragmentSink* sink) override { sink_ = sink; }

    // Texels, plus the decoded float copies copyDecoded keeps beside sampled RGBA8 textures
    // (alpha: 4 bytes a texel; all four channels, up to kDecodedCopyMaxTexels: 16).
    std::uint64_t textureFootprint(const TextureDesc& desc) const override {
        const bool decodedCopies = (desc.format == Format::RGBA8_UNORM || desc.format == Format::RGBA8_SRGB) &&
                                   desc.samples == 1 && !(desc.usage & UsageRenderTarget);
        const std::uint64_t copies = !decodedCopies ? 0 : SoftTexture::keepsFourChannelCopy(desc) ? 5 : 1;
        return textureBytes(desc) * (1 + copies);
    }

    NativeId createTexture(const TextureDesc& desc, const TextureData* data, const std::string&) override {
        const FormatInfo& info = formatInfo(desc.format);
        SoftTexture t;
        t.desc = desc;
        t.bytesPerSample = info.bytesPerPixel;
        for (int level = 0; level < desc.mipLevels; ++level) {
            MipLevel l;
            l.width = std::max(1, desc.width >> level);
            l.height = std::max(1, desc.height >> level);
            l.texels.assign(std::size_t(l.width) * l.height * desc.samples * info.bytesPerPixel, std::byte{0});
            t.levels.push_back(std::move(l));
        }
        if (data) upload(t, *data);
        t.copyDecoded();  // texels are final here unless the texture is a render target
        return textures_.add(std::move(t));
    }

    NativeId createBuffer(const BufferDesc& desc, std::span<const std::byte> data, const std::string&) override {
        SoftBuffer b{desc, std::vector<std::byte>(desc.size), std::nullopt, ++lastStamp_};
        if (!data.empty()) std::memcpy(b.bytes.data(), data.data(), data.size());
        return buffers_.add(std::move(b));
    }

    void updateBuffer(NativeId handle, std::uint64_t offset, std::span<const std::byte> data) override {
        SoftBuffer& b = buffers_[handle];
        // Recorded draws read their buffers when the pass executes; one that reads this buffer
        // must see it as it was when it was drawn (as on GL), so the draws so far run first.
        if (pass_ && std::any_of(draws_.begin(), draws_.end(), [&](const RecordedDraw& r) {
                return r.vertices == handle || r.indices == handle || r.instances == handle;
            })) {
            struct Clear {
                std::vector<RecordedDraw>& draws;
                ~Clear() { draws.clear(); }
            } clear{draws_};
            execute();
        }
        std::memcpy(b.bytes.data() + offset, data.data(), data.size());
        b.bounds.reset();
        b.stamp = ++lastStamp_;
    }

    NativeId createProgram(std::shared_ptr<const ProgramDesc> desc) override {
        if (!desc->soft) throw Error("program " + quotedName(desc->name) + " has no CPU kernel for the soft backend");
        return programs_.add(std::move(desc));
    }
    NativeId createStandardProgram(ProgramKind kind, ProgramDesc desc) override {
        desc.soft = standardKernel(kind);
        return programs_.add(std::make_shared<const ProgramDesc>(std::move(desc)));
    }

    void destroyTexture(NativeId h) override { textures_.remove(h); }
    void destroyBuffer(NativeId h) override { buffers_.remove(h); }
    void destroyProgram(NativeId h) override { programs_.remove(h); }

    NativeId createQuery(const std::string&) override { return queries_.add({}); }
    void destroyQuery(NativeId h) override { queries_.remove(h); }
    bool anySamplesPassed(NativeId h) override { return queries_[h].anyPassed; }

    void beginPass(const DriverPass& pass) override {
        pass_ = pass;
        passWidth_ = pass.extent.width, passHeight_ = pass.extent.height, passSamples_ = pass.extent.samples;
        passStart_ = Clock::now();
        passSkipped_ = pass.drawOnlyIfSamplesIn != kNoNative && !queries_[pass.drawOnlyIfSamplesIn].anyPassed;
        passTouched_ = 0;
        draws_.clear();
        colorTargets_.clear();
        for (std::size_t i = 0; i < pass.color.size(); ++i) {
            if (pass.color[i] == kNoNative) continue;
            colorTargets_.push_back(pass.color[i]);
            if (pass.desc->color[i].load == LoadOp::Clear) clear(textures_[pass.color[i]], pass.desc->color[i].clear);
        }
        if (pass.depth != kNoNative && pass.desc->depth.load == LoadOp::Clear)
            clear(textures_[pass.depth], glm::vec4(pass.desc->depth.clear));
    }

    void draw(const DriverDraw& d) override {
        if (sink_ && (passSamples_ != 1 || !d.pipeline->depth.test || pass_->depth == kNoNative))
            throw Error("draw with pipeline '" + d.pipeline->name +
                        "': fragment capture needs a single-sampled pass and a depth test");
        draws_.push_back({*d.desc, *d.state, d.pipeline->raster, d.program, d.vertices, d.indices, d.instances,
                          d.fullscreen, sink_});
    }

    void endPass() override {
        // The pass is over even when executing it throws: the error must not leave the
        // driver stuck in it.
        struct Close {
            SoftDriverImpl& self;
            ~Close() {
                self.pass_.reset();
                self.draws_.clear();
            }
        } close{*this};
        execute();
        if (pass_->countSamplesInto != kNoNative) queries_[pass_->countSamplesInto].anyPassed = passTouched_ > 0;
        const double ms = std::chrono::duration<double, std::milli>(Clock::now() - passStart_).count();
        timings_.push_back({pass_->serial, ms, passSkipped_});
        ++stats_.passes;
    }

    void abortPass() noexcept override {
        pass_.reset();
        draws_.clear();
    }

    void resolve(NativeId source, NativeId destination, const ResolveDesc& r, const std::string&) override {
        SoftTexture& src = textures_[source];
        SoftTexture& dst = textures_[destination];
        const bool depth = formatInfo(src.desc.format).isDepth;
        const int n = src.desc.samples;
        arena_.execute([&] {
            parallelForChunks(0, src.desc.height, 1, [&](int firstRow, int endRow) {
                for (int y = firstRow; y != endRow; ++y) {
                    for (int x = 0; x < src.desc.width; ++x) {
                        if (depth) {
                            // The closest sample, never an average ([Hathaway 2010] §3.5.1).
                            float best = loadTexel(src.sample(x, y, 0), src.desc.format).r;
                            for (int s = 1; s < n; ++s) {
                                const float z = loadTexel(src.sample(x, y, s), src.desc.format).r;
                                if (isCloser(r.depthFunc, z, best)) best = z;
                            }
                            std::memcpy(dst.sample(x, y, 0), &best, sizeof best);
                        } else {
                            glm::vec4 sum(0.0f);
                            for (int s = 0; s < n; ++s) sum += loadTexel(src.sample(x, y, s), src.desc.format);
                            storeTexel(dst.sample(x, y, 0), dst.desc.format, sum / float(n), 0xF);
                        }
                    }
                }
            });
        });
    }

    Readback readback(NativeId h, const TextureDesc&) override {
        const SoftTexture& t = textures_[h];
        const FormatInfo& info = formatInfo(t.desc.format);
        Readback r;
        r.width = t.desc.width;
        r.height = t.desc.height;
        r.channels = info.channels;
        r.format = t.desc.format;
        r.values.resize(std::size_t(r.width) * r.height * r.channels);
        const ByteTables& tables = byteTables();
        for (int y = 0; y < r.height; ++y) {
            for (int x = 0; x < r.width; ++x) {
                const std::byte* p = t.texel(0, x, y);
                float* out = &r.values[(std::size_t(y) * r.width + x) * r.channels];
                if (info.isNormalized()) {  // stored codes, sRGB not decoded
                    for (int c = 0; c < r.channels; ++c) out[c] = tables.unorm[std::to_integer<std::uint8_t>(p[c])];
                } else {
                    const glm::vec4 v = loadTexel(p, t.desc.format);
                    for (int c = 0; c < r.channels; ++c) out[c] = v[c];
                }
            }
        }
        return r;
    }

    std::vector<DriverTiming> takeTimings() override { return std::exchange(timings_, {}); }

private:
    // Data that validateTextureData accepted.
    void upload(SoftTexture& t, const TextureData& data) {
        const bool half =
            t.desc.format == Format::RGBA16F || t.desc.format == Format::RG16F || t.desc.format == Format::R16F;
        const int channels = formatInfo(t.desc.format).channels;
        for (std::size_t level = 0; level < data.levels.size(); ++level) {
            MipLevel& l = t.levels[level];
            const std::size_t pixels = std::size_t(l.width) * l.height;
            if (!half) {
                std::memcpy(l.texels.data(), data.levels[level].data(), l.texels.size());
                continue;
            }
            const float* src = reinterpret_cast<const float*>(data.levels[level].data());
            for (std::size_t i = 0; i < pixels * channels; ++i) {
                const std::uint16_t bits = encodeHalf(src[i]);
                std::memcpy(l.texels.data() + 2 * i, &bits, 2);
            }
        }
        for (std::size_t level = std::max<std::size_t>(1, data.levels.size()); level < t.levels.size(); ++level)
            generateMipLevel(t, static_cast<int>(level));
    }

    void clear(SoftTexture& t, const glm::vec4& value) {
        std::byte encoded[16] = {};
        storeTexel(encoded, t.desc.format, value, 0xF);
        std::vector<std::byte>& texels = t.levels[0].texels;
        const std::size_t stride = t.bytesPerSample, size = texels.size();
        // One texel, then the filled prefix doubled up to 4 KiB, then 4 KiB copies: a fill
        // at memset speed for every texel size (1, 2, 4, 8 or 16 bytes all divide 4 KiB).
        std::byte* out = texels.data();
        std::size_t filled = std::min(stride, size);
        std::memcpy(out, encoded, filled);
        constexpr std::size_t kBlock = 4096;
        while (filled < size && filled < kBlock) {
            const std::size_t n = std::min({filled, size - filled, kBlock - filled});
            std::memcpy(out + filled, out, n);
            filled += n;
        }
        const std::size_t blocks = (size - filled) / kBlock;
        auto copyBlocks = [&](std::size_t begin, std::size_t end) {
            for (std::size_t b = begin; b < end; ++b) std::memcpy(out + filled + b * kBlock, out, kBlock);
        };
        if (blocks >= 256) {  // 1 MiB and more: split over the threads
            arena_.execute([&] { parallelForChunks(std::size_t(0), blocks, std::size_t(64), copyBlocks); });
        } else {
            copyBlocks(0, blocks);
        }
        filled += blocks * kBlock;
        if (filled < size) std::memcpy(out + filled, out, size - filled);
    }

    Viewport viewportFor(const Rect& scissor) const {
        return {passWidth_, passHeight_, scissor, &samplePattern(passSamples_)};
    }

    // The draw's state as the device resolved it (resolved_draw_state.hpp), translated into
    // the tile loop's terms.
    DrawState drawStateFor(const RecordedDraw& d) {
        const ResolvedDrawState& r = d.state;
        DrawState s;
        for (NativeId target : colorTargets_) s.colorTargets[s.colorTargetCount++] = &textures_[target];
        s.depthTarget = pass_->depth != kNoNative ? &textures_[pass_->depth] : nullptr;
        s.samples = passSamples_;
        s.pattern = &samplePattern(passSamples_);
        s.depthTest = r.depthTest;
        s.depthWrite = r.depthWrite;
        s.depthFunc = r.depthFunc;
        s.alphaToCoverage = r.alphaToCoverage;
        s.blendConstant = r.blendConstant;
        s.blend = r.blend;
        s.blendNeeded = r.blendNeeded;
        s.alphaTest = r.alphaTest;
        s.shade = r.shade;
        s.program = programs_[d.program]->soft->bind(d.desc.params, textureLookup_);
        s.isa = *options_.simd;
        return s;
    }

    // The draw's vertex input resolved from its buffers for the geometry stage, which plans
    // its chunks (geometry_stage.hpp).
    void planGeometry(const RecordedDraw& r, const DrawState& state, std::uint32_t drawIndex, const Viewport& vp,
                      const TileGrid& grid) {
        const DrawDesc& d = r.desc;
        if (r.fullscreen) {
            geometryStage_.planFullscreen(vp, drawIndex, grid);
            return;
        }
        SoftBuffer& vb = buffers_[r.vertices];
        const auto* vertices = reinterpret_cast<const Vertex*>(vb.bytes.data());
        if (!vb.bounds) vb.bounds = positionBounds({vertices, vb.bytes.size() / sizeof(Vertex)});
        static const Instance identity{};
        DrawGeometry g{vertices,
                       r.indices != kNoNative
                           ? reinterpret_cast<const std::uint32_t*>(buffers_[r.indices].bytes.data()) + d.first
                           : nullptr,
                       d.first,
                       r.instances != kNoNative ? reinterpret_cast<const Instance*>(buffers_[r.instances].bytes.data())
                                                : &identity,
                       &*vb.bounds,
                       state.program->viewProj(),
                       vp,
                       r.raster,
                       drawIndex,
                       d.count / 3,
                       0};
        g.total = g.trianglesPerInstance * d.instanceCount;
        stats_.trianglesIn += g.total;
        if (g.total == 0 || vp.scissor.empty()) return;
        const GeometryKey key{vb.stamp,
                              r.indices != kNoNative ? buffers_[r.indices].stamp : 0,
                              r.instances != kNoNative ? buffers_[r.instances].stamp : 0,
                              d.first,
                              d.count,
                              d.instanceCount,
                              g.viewProj,
                              vp,
                              r.raster};
        if (geometryStage_.plan(g, key)) stats_.trianglesReused += g.total;
    }

    void execute() {
        if (passSkipped_) return;  // drawOnlyIfSamplesIn found none: the draws do not run
        const int tileSize = options_.tileSize;
        const int tilesX = (passWidth_ + tileSize - 1) / tileSize, tilesY = (passHeight_ + tileSize - 1) / tileSize;
        const TileGrid grid{tileSize, tilesX, tilesY};
        std::vector<DrawState> drawStates;
        drawStates.reserve(draws_.size());
        geometryStage_.beginPass();
        // Chunks of an execution that threw may not have been set up: none is offered then.
        struct ForgetUnlessDone {
            GeometryStage& stage;
            bool done = false;
            ~ForgetUnlessDone() {
                if (!done) stage.forgetPlanned();
            }
        } forget{geometryStage_};
        for (std::uint32_t i = 0; i < draws_.size(); ++i) {
            drawStates.push_back(drawStateFor(draws_[i]));
            if (FragmentSink* sink = draws_[i].sink) {
                DrawState& s = drawStates.back();
                s.capture = sink;
                s.shade = true;
                s.depthWrite = false;
            }
            planGeometry(draws_[i], drawStates.back(), i, viewportFor(draws_[i].state.scissor), grid);
        }
        geometryStage_.runGeometry(arena_, grid);
        stats_.draws += draws_.size();
        boundDepthBlocks(drawStates);

        // Merging the chunks' bins in submission order keeps each tile's list ordered.
        bins_.resize(std::size_t(tilesX) * tilesY);
        for (auto& bin : bins_) bin.clear();
        for (const GeometryChunk& chunk : geometryStage_.chunks()) {
            stats_.trianglesRasterized += chunk.triangles.size();
            stats_.trianglesDropped += chunk.counters.dropped;
            for (const BinEntry& e : chunk.bins) bins_[e.tile].push_back(&chunk.triangles[e.triangle]);
        }

        std::atomic<std::uint64_t> shaded{0}, touched{0}, skipped{0};
        arena_.execute([&] {
            parallelFor(std::size_t(0), bins_.size(), [&](std::size_t tileIndex) {
                if (bins_[tileIndex].empty()) return;
                const int tx = int(tileIndex % tilesX), ty = int(tileIndex / tilesX);
                const Rect tile{tx * tileSize, ty * tileSize, std::min(tileSize, passWidth_ - tx * tileSize),
                                std::min(tileSize, passHeight_ - ty * tileSize)};
                TileCounters counters;
                rasterizeTile(tile, bins_[tileIndex], drawStates, counters);
                shaded += counters.pixelsShaded;
                touched += counters.pixelsTouched;
                skipped += counters.depthBlocksSkipped;
            });
        });
        stats_.depthBlocksSkipped += skipped;
        stats_.pixelsShaded += shaded;
        stats_.pixelsTouched += touched;
        passTouched_ += touched;
        geometryStage_.endPass();
        forget.done = true;
        if (options_.debugChecks) checkNonFinite();
    }

    // SoftOptions::depthBlockBounds: where every draw of the pass tests the pass's single-sampled
    // depth with an ordering function and none writes it or captures, the depth's block bounds
    // (depth_block_bounds.hpp), built over both threads, for the rasterizer to skip by.
    void boundDepthBlocks(std::vector<DrawState>& drawStates) {
        if (!options_.depthBlockBounds || drawStates.empty() || passSamples_ != 1) return;
        const SoftTexture* depth = drawStates.front().depthTarget;
        if (!depth || depth->desc.format != Format::D32F || depth->desc.samples != 1) return;
        for (const DrawState& s : drawStates)
            if (!s.depthTest || s.depthWrite || s.capture || s.depthTarget != depth ||
                (s.depthFunc != CompareFunc::Less && s.depthFunc != CompareFunc::LessEqual &&
                 s.depthFunc != CompareFunc::Greater && s.depthFunc != CompareFunc::GreaterEqual))
                return;
        const int width = depth->desc.width, height = depth->desc.height;
        depthBounds_.resize(width, height);
        const std::byte* texels = depth->levels[0].texels.data();
        const std::size_t rowBytes = std::size_t(depth->levels[0].width) * depth->bytesPerSample;
        arena_.execute([&] {
            parallelForChunks(0, depthBounds_.blockRows(), 1, [&](int firstRow, int endRow) {
                depthBounds_.buildRows(texels, rowBytes, width, height, firstRow, endRow);
            });
        });
        for (DrawState& s : drawStates) s.depthBounds = &depthBounds_;
    }

    void checkNonFinite() {
        std::uint64_t count = 0;
        for (NativeId target : colorTargets_) {
            const SoftTexture& t = textures_[target];
            if (!formatInfo(t.desc.format).isFloat) continue;
            const int channels = formatInfo(t.desc.format).channels;
            for (int y = 0; y < t.desc.height; ++y)
                for (int x = 0; x < t.desc.width; ++x)
                    for (int s = 0; s < t.desc.samples; ++s) {
                        const glm::vec4 v = loadTexel(const_cast<SoftTexture&>(t).sample(x, y, s), t.desc.format);
                        for (int ch = 0; ch < channels; ++ch) count += !std::isfinite(v[ch]);
                    }
        }
        if (count)
            log::warn("pass ", quotedName(pass_->desc->name), ": ", count, " non-finite values in float targets");
        stats_.nonFiniteStores += count;
    }

    SoftOptions options_;
    tbb::task_arena arena_;
    NativeSlots<SoftTexture> textures_;
    NativeSlots<SoftBuffer> buffers_;
    NativeSlots<SoftQuery> queries_;
    NativeSlots<std::shared_ptr<const ProgramDesc>> programs_;
    // How bound programs resolve texture handles: the device's index, then this driver's slot.
    struct Textures final : TextureLookup {
        explicit Textures(const NativeSlots<SoftTexture>& slots) : slots(slots) {}
        const SoftTexture* texture(TextureHandle h) const override { return h ? &slots[natives->texture(h)] : nullptr; }
        SampleFunction sampleFunction() const override { return &sampleTexture<SampledChannels::All>; }
        const NativeSlots<SoftTexture>& slots;
        const NativeTextures* natives = nullptr;
    } textureLookup_{textures_};
    std::optional<DriverPass> pass_;
    DepthBlockBounds depthBounds_;        // the running pass's, when boundDepthBlocks built them
    std::vector<NativeId> colorTargets_;  // the pass's colour attachments, packed
    int passWidth_ = 0, passHeight_ = 0, passSamples_ = 1;
    Clock::time_point passStart_;
    bool passSkipped_ = false;
    std::uint64_t passTouched_ = 0;  // pixels where a sample passed the depth test
    std::vector<RecordedDraw> draws_;
    FragmentSink* sink_ = nullptr;
    GeometryStage geometryStage_{options_.reuseGeometry};
    std::uint64_t lastStamp_ = 0;                          // the last buffer content stamp given
    std::vector<std::vector<const SetupTriangle*>> bins_;  // per tile, in submission order
    std::vector<DriverTiming> timings_;
    SoftStats stats_;
};

}  // namespace

std::unique_ptr<Device> createSoftBackend(const SoftOptions& options) {
    return std::make_unique<Device>(std::make_unique<SoftDriverImpl>(options));
}

}  // namespace engine::render::soft
