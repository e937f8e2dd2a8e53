#include "engine/render/validation.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "engine/core/error.hpp"
#include "engine/render/vertex.hpp"

namespace engine::render {

std::string quotedName(const std::string& name) { return "'" + (name.empty() ? std::string("<unnamed>") : name) + "'"; }

void validateTexture(const TextureDesc& desc, const std::string& what) {
    if (desc.width <= 0 || desc.height <= 0)
        throw Error(what + ": size " + std::to_string(desc.width) + "x" + std::to_string(desc.height) + " is empty");
    if (desc.width > kMaxTextureDimension || desc.height > kMaxTextureDimension)
        throw Error(what + ": size " + std::to_string(desc.width) + "x" + std::to_string(desc.height) +
                    " exceeds the " + std::to_string(kMaxTextureDimension) + " limit");
    if (desc.samples != 1 && desc.samples != 2 && desc.samples != 4 && desc.samples != 8)
        throw Error(what + ": " + std::to_string(desc.samples) + " samples (must be 1, 2, 4 or 8)");
    const FormatInfo& info = formatInfo(desc.format);
    if (desc.samples > 1 && !(desc.usage & UsageRenderTarget))
        throw Error(what + ": multisampled textures must be render targets");
    if (info.isDepth && !(desc.usage & UsageRenderTarget))
        throw Error(what + ": depth format D32F is only for render targets");
    const int maxLevels = 1 + static_cast<int>(std::floor(std::log2(std::max(desc.width, desc.height))));
    if (desc.mipLevels < 1 || desc.mipLevels > maxLevels || (desc.mipLevels > 1 && desc.samples > 1))
        throw Error(what + ": " + std::to_string(desc.mipLevels) + " mip levels (1.." + std::to_string(maxLevels) +
                    ", and 1 when multisampled)");
    const std::uint64_t bytes = std::uint64_t(desc.width) * desc.height * desc.samples * info.bytesPerPixel;
    if (bytes > kMaxTextureBytes)
        throw Error(what + ": " + std::to_string(bytes >> 20) + " MiB exceeds the 1 GiB texture limit");
}

void validateBuffer(const BufferDesc& desc, std::span<const std::byte> data, const std::string& what) {
    const std::uint64_t stride = desc.kind == BufferKind::Vertex  ? sizeof(Vertex)
                                 : desc.kind == BufferKind::Index ? sizeof(std::uint32_t)
                                                                  : sizeof(Instance);
    if (desc.size == 0 || desc.size % stride != 0)
        throw Error(what + ": size " + std::to_string(desc.size) + " is not a positive multiple of " +
                    std::to_string(stride));
    if (!data.empty() && data.size() != desc.size)
        throw Error(what + ": " + std::to_string(data.size()) + " bytes given for a " + std::to_string(desc.size) +
                    "-byte buffer");
}

Error uncountedQueryError(const std::string& queryName) {
    return Error("occlusion query " + quotedName(queryName) + " is read before any pass counted into it");
}

void checkQueryUse(QueryHandle query, const std::string& queryName, const PassDesc* open, bool destroying) {
    if (!open) return;
    if (open->countSamplesInto == query)
        throw Error("occlusion query " + quotedName(queryName) + (destroying ? " destroyed" : " read") + " while pass " +
                    quotedName(open->name) + " counts into it");
    if (destroying && open->drawOnlyIfSamplesIn == query)
        throw Error("occlusion query " + quotedName(queryName) + " destroyed while pass " + quotedName(open->name) +
                    " draws only if it found samples");
}

PassExtent validatePass(const PassDesc& pass, const ResourceLookup& lookup) {
    const std::string what = "pass " + quotedName(pass.name);
    PassExtent extent;
    auto checkSize = [&](const TextureDesc& t) {
        if (extent.width == 0) {
            extent = {t.width, t.height, t.samples};
        } else if (t.width != extent.width || t.height != extent.height || t.samples != extent.samples) {
            throw Error(what + ": attachment " + quotedName(t.name) + " differs in size or sample count from the others");
        }
        if (!(t.usage & UsageRenderTarget)) throw Error(what + ": " + quotedName(t.name) + " is not a render target");
    };
    for (const ColorAttachment& c : pass.color) {
        if (!c.texture) continue;
        const TextureDesc& t = lookup.texture(c.texture);
        if (formatInfo(t.format).isDepth) throw Error(what + ": depth texture " + quotedName(t.name) + " bound as colour");
        checkSize(t);
    }
    if (pass.depth.texture) {
        const TextureDesc& t = lookup.texture(pass.depth.texture);
        if (!formatInfo(t.format).isDepth)
            throw Error(what + ": " + quotedName(t.name) + " bound as depth is " + std::string(formatName(t.format)));
        checkSize(t);
    }
    if (extent.width == 0) throw Error(what + " has no attachments");
    if (pass.countSamplesInto && pass.countSamplesInto == pass.drawOnlyIfSamplesIn)
        throw Error(what + ": draws only if samples are in the occlusion query it counts into");
    return extent;
}

namespace {

const TextureDesc& sampledTexture(TextureHandle h, const PassDesc& pass, const ResourceLookup& lookup,
                                  const std::string& what) {
    const TextureDesc& t = lookup.texture(h);
    if (t.samples != 1) throw Error(what + ": samples multisampled texture " + quotedName(t.name));
    for (const ColorAttachment& c : pass.color)
        if (c.texture == h) throw Error(what + ": samples " + quotedName(t.name) + " while rendering into it");
    if (pass.depth.texture == h) throw Error(what + ": samples depth target " + quotedName(t.name));
    return t;
}

const BufferDesc& bufferOfKind(BufferHandle h, BufferKind kind, const char* kindName, const ResourceLookup& lookup,
                               const std::string& what) {
    const BufferDesc& b = lookup.buffer(h);
    if (b.kind != kind) throw Error(what + ": " + quotedName(b.name) + " is not " + kindName);
    return b;
}

}  // namespace

void validateDraw(const DrawDesc& d, const PassDesc& pass, const PassExtent& extent, const ResourceLookup& lookup) {
    const PipelineDesc& p = lookup.pipeline(d.pipeline);
    const std::string what = "draw with pipeline " + quotedName(p.name) + " in pass " + quotedName(pass.name);
    if (d.params.index() != paramsIndexFor(p.program))
        throw Error(what + ": parameters do not match program " + programKindName(p.program));
    if (p.depth.test && !pass.depth.texture) throw Error(what + ": depth test on but the pass has no depth target");
    if (pass.countSamplesInto && (p.alphaTest.enabled || p.alphaTest.alphaToCoverage))
        throw Error(what + ": alpha test or alpha-to-coverage in a pass that counts samples into an occlusion query");

    if (isFullscreen(p.program)) {
        // Full-screen programs read their inputs at every target pixel.
        auto input = [&](TextureHandle h) {
            const TextureDesc& t = sampledTexture(h, pass, lookup, what);
            if (t.width < extent.width || t.height < extent.height)
                throw Error(what + ": input " + quotedName(t.name) + " is smaller than the target");
        };
        if (const auto* w = std::get_if<WboitResolveParams>(&d.params)) {
            input(w->accumulation);
            input(w->revealage);
            return;
        }
        if (const auto* c = std::get_if<CoverageCompositeParams>(&d.params)) {
            input(c->foliage);
            input(c->mask);
            if (c->maskAdd) input(c->maskAdd);
            if (c->model != CoverageModel::EqualLayers && c->model != CoverageModel::Exponential)
                throw Error(what + ": unknown coverage model " + std::to_string(int(c->model)));
            return;
        }
        if (const auto* shafts = std::get_if<LightShaftParams>(&d.params)) {
            input(shafts->depth);
            const Format depthFormat = lookup.texture(shafts->depth).format;
            if (depthFormat != Format::D32F && depthFormat != Format::R32F)
                throw Error(what + ": light-shaft depth is " + std::string(formatName(depthFormat)) + ", not D32F or R32F");
            if (shafts->samples < 1 || shafts->samples > 128)
                throw Error(what + ": light-shaft samples " + std::to_string(shafts->samples) + " not in 1..128");
            for (float v : {shafts->sunPixel.x, shafts->sunPixel.y, shafts->farDepth, shafts->intensity, shafts->decay,
                            shafts->density, shafts->color.r, shafts->color.g, shafts->color.b, shafts->glowRadius})
                if (!std::isfinite(v)) throw Error(what + ": light-shaft parameters are not finite");
            return;
        }
        if (const auto* l = std::get_if<LayerCompositeParams>(&d.params)) {
            // A layer of 1/layerScale the target's size (rounded up), upsampled by the program.
            if (l->layerScale != 1 && l->layerScale != 2)
                throw Error(what + ": layerScale " + std::to_string(l->layerScale) + " is not 1 or 2");
            const TextureDesc& t = sampledTexture(l->layer, pass, lookup, what);
            const int s = l->layerScale;
            if (t.width < (extent.width + s - 1) / s || t.height < (extent.height + s - 1) / s)
                throw Error(what + ": layer " + quotedName(t.name) + " is smaller than the target / " + std::to_string(s));
            if (l->sceneDepth) input(l->sceneDepth);
            if (!std::isfinite(l->depthScale) || !std::isfinite(l->depthOffset))
                throw Error(what + ": depth-to-distance factors are not finite");
            return;
        }
        const CompositeParams& c = std::get<CompositeParams>(d.params);
        input(c.foliage);
        input(c.mask);
        if (c.maskAdd) input(c.maskAdd);  // the split ADD mask is optional
        if (!std::isfinite(c.maskLerp)) throw Error(what + ": maskLerp is not finite");
        return;
    }

    if (d.count % 3 != 0) throw Error(what + ": count " + std::to_string(d.count) + " is not a multiple of 3");
    if (const auto* particle = std::get_if<ParticleParams>(&d.params)) {
        if (particle->depthStride != 1 && particle->depthStride != 2)
            throw Error(what + ": depthStride " + std::to_string(particle->depthStride) + " is not 1 or 2");
        if (!(particle->softness > 0.0f) || !std::isfinite(particle->softness))
            throw Error(what + ": softness must be finite and > 0");
        if (!std::isfinite(particle->depthScale) || !std::isfinite(particle->depthOffset))
            throw Error(what + ": depth-to-distance factors are not finite");
        if (particle->sceneDepth) sampledTexture(particle->sceneDepth, pass, lookup, what);
    }
    const BufferDesc& vb = bufferOfKind(d.vertices, BufferKind::Vertex, "a vertex buffer", lookup, what);
    const std::uint64_t vertexCount = vb.size / sizeof(Vertex);
    if (d.indices) {
        const BufferDesc& ib = bufferOfKind(d.indices, BufferKind::Index, "an index buffer", lookup, what);
        const std::uint64_t indexCount = ib.size / 4;
        if (std::uint64_t(d.first) + d.count > indexCount)
            throw Error(what + ": indices [" + std::to_string(d.first) + ", " + std::to_string(d.first + d.count) +
                        ") outside " + quotedName(ib.name) + " of " + std::to_string(indexCount));
        const auto* indices = reinterpret_cast<const std::uint32_t*>(lookup.indexData(d.indices).data()) + d.first;
        for (std::uint32_t i = 0; i < d.count; ++i)
            if (indices[i] >= vertexCount)
                throw Error(what + ": index " + std::to_string(indices[i]) + " at position " +
                            std::to_string(d.first + i) + " >= vertex count " + std::to_string(vertexCount));
    } else if (std::uint64_t(d.first) + d.count > vertexCount) {
        throw Error(what + ": vertices [" + std::to_string(d.first) + ", " + std::to_string(d.first + d.count) +
                    ") outside " + quotedName(vb.name) + " of " + std::to_string(vertexCount));
    }
    if (d.instances) {
        const BufferDesc& inst = bufferOfKind(d.instances, BufferKind::Instance, "an instance buffer", lookup, what);
        if (std::uint64_t(d.instanceCount) * sizeof(Instance) > inst.size)
            throw Error(what + ": " + std::to_string(d.instanceCount) + " instances exceed " + quotedName(inst.name));
    } else if (d.instanceCount != 1) {
        throw Error(what + ": instanceCount " + std::to_string(d.instanceCount) + " without an instance buffer");
    }
    std::visit(
        [&](const auto& params) {
            using P = std::decay_t<decltype(params)>;
            if constexpr (std::is_same_v<P, SurfaceParams> || std::is_same_v<P, AlphaOnlyParams>)
                if (params.baseColor.texture) sampledTexture(params.baseColor.texture, pass, lookup, what);
        },
        d.params);
}

}  // namespace engine::render
