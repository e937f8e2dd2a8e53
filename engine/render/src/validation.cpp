// SPDX-License-Identifier: MIT
#include "engine/render/validation.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>

#include "engine/core/error.hpp"
#include "engine/render/vertex.hpp"
#include "texture_params.hpp"

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

void validateTextureData(const TextureDesc& desc, const TextureData& data, const std::string& what) {
    if (data.levels.size() > std::size_t(desc.mipLevels))
        throw Error(what + ": " + std::to_string(data.levels.size()) + " levels of data for " +
                    std::to_string(desc.mipLevels) + " mip levels");
    const FormatInfo& info = formatInfo(desc.format);
    const bool half = info.isFloat && info.bytesPerPixel == 2 * info.channels;
    for (std::size_t level = 0; level < data.levels.size(); ++level) {
        const std::size_t pixels =
            std::size_t(std::max(1, desc.width >> level)) * std::size_t(std::max(1, desc.height >> level));
        const std::size_t expected =
            half ? pixels * info.channels * sizeof(float) : pixels * std::size_t(desc.samples) * info.bytesPerPixel;
        if (data.levels[level].size() != expected)
            throw Error(what + ": level " + std::to_string(level) + " has " +
                        std::to_string(data.levels[level].size()) + " bytes, expected " + std::to_string(expected));
    }
}

void validateBuffer(const BufferDesc& desc, std::span<const std::byte> data, const std::string& what) {
    const std::uint64_t stride = elementSize(desc.kind);
    if (desc.size == 0 || desc.size % stride != 0)
        throw Error(what + ": size " + std::to_string(desc.size) + " is not a positive multiple of " +
                    std::to_string(stride));
    if (!data.empty() && data.size() != desc.size)
        throw Error(what + ": " + std::to_string(data.size()) + " bytes given for a " + std::to_string(desc.size) +
                    "-byte buffer");
}

void validateBufferUpdate(const BufferDesc& desc, std::uint64_t offset, std::uint64_t size) {
    if (offset > desc.size || size > desc.size - offset)
        throw Error("buffer " + quotedName(desc.name) + ": update of " + std::to_string(size) + " bytes at offset " +
                    std::to_string(offset) + " overruns its " + std::to_string(desc.size) + " bytes");
}

std::string validateResolve(const TextureDesc& source, const TextureDesc& destination) {
    std::string what = "resolve " + quotedName(source.name) + " -> " + quotedName(destination.name);
    if (source.width != destination.width || source.height != destination.height ||
        source.format != destination.format || destination.samples != 1)
        throw Error(what + ": needs the same size and format and a single-sampled destination");
    return what;
}

void validateReadback(const TextureDesc& desc) {
    if (desc.samples != 1) throw Error("readback of " + quotedName(desc.name) + ": multisampled; resolve it first");
}

Error uncountedQueryError(const std::string& queryName) {
    return Error("occlusion query " + quotedName(queryName) + " is read before any pass counted into it");
}

void checkQueryUse(QueryHandle query, const std::string& queryName, const PassDesc* open, bool destroying) {
    if (!open) return;
    if (open->countSamplesInto == query)
        throw Error("occlusion query " + quotedName(queryName) + (destroying ? " destroyed" : " read") +
                    " while pass " + quotedName(open->name) + " counts into it");
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
            throw Error(what + ": attachment " + quotedName(t.name) +
                        " differs in size or sample count from the others");
        }
        if (!(t.usage & UsageRenderTarget)) throw Error(what + ": " + quotedName(t.name) + " is not a render target");
    };
    for (const ColorAttachment& c : pass.color) {
        if (!c.texture) continue;
        const TextureDesc& t = lookup.texture(c.texture);
        if (formatInfo(t.format).isDepth)
            throw Error(what + ": depth texture " + quotedName(t.name) + " bound as colour");
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

// DrawCheck for one draw. Messages name the draw's pipeline and pass; they are built only
// when a check fails, so a valid draw costs no string work.
class DrawChecks final : public DrawCheck {
public:
    DrawChecks(const PipelineDesc& pipeline, const PassDesc& pass, const PassExtent& extent,
               const ResourceLookup& lookup)
        : pipeline_(pipeline), pass_(pass), extent_(extent), lookup_(lookup) {}

    [[noreturn]] void fail(const std::string& message) const override {
        throw Error("draw with pipeline " + quotedName(pipeline_.name) + " in pass " + quotedName(pass_.name) + ": " +
                    message);
    }
    const TextureDesc& texture(TextureHandle texture) const override { return lookup_.texture(texture); }
    const TextureDesc& sampled(TextureHandle h) const override {
        const TextureDesc& t = lookup_.texture(h);
        if (t.samples != 1) fail("samples multisampled texture " + quotedName(t.name));
        for (const ColorAttachment& c : pass_.color)
            if (c.texture == h) fail("samples " + quotedName(t.name) + " while rendering into it");
        if (pass_.depth.texture == h) fail("samples depth target " + quotedName(t.name));
        return t;
    }
    int targetWidth() const override { return extent_.width; }
    int targetHeight() const override { return extent_.height; }

    const BufferDesc& bufferOfKind(BufferHandle h, BufferKind kind, const char* kindName) const {
        const BufferDesc& b = lookup_.buffer(h);
        if (b.kind != kind) fail(quotedName(b.name) + " is not " + kindName);
        return b;
    }

private:
    const PipelineDesc& pipeline_;
    const PassDesc& pass_;
    const PassExtent& extent_;
    const ResourceLookup& lookup_;
};

// The textures a program's parameters name, as its layout declares them.
void checkTextures(const ProgramDesc& program, const DrawParams& params, const DrawChecks& check) {
    forEachTextureParam(program, params, [&](const TextureField& field, TextureHandle handle) {
        if (!handle && field.optional) return;
        const TextureDesc& t = check.sampled(handle);
        if (field.use == TextureUse::FullSize && (t.width < check.targetWidth() || t.height < check.targetHeight()))
            check.fail("input " + quotedName(t.name) + " is smaller than the target");
    });
}

// Every index of the draw's range names a vertex of the buffer. The largest index of the
// buffer, kept by the backend since the buffer was last written, settles nearly every draw
// at once; only a buffer holding an index out of this draw's vertex range is scanned, to say
// which index and where.
void checkIndices(const DrawDesc& d, std::uint64_t vertexCount, const DrawChecks& check, const ResourceLookup& lookup) {
    const BufferDesc& ib = check.bufferOfKind(d.indices, BufferKind::Index, "an index buffer");
    const std::uint64_t indexCount = ib.size / 4;
    if (std::uint64_t(d.first) + d.count > indexCount)
        check.fail("indices [" + std::to_string(d.first) + ", " + std::to_string(d.first + d.count) + ") outside " +
                   quotedName(ib.name) + " of " + std::to_string(indexCount));
    if (lookup.maxIndex(d.indices) < vertexCount) return;
    const auto* indices = reinterpret_cast<const std::uint32_t*>(lookup.indexData(d.indices).data()) + d.first;
    for (std::uint32_t i = 0; i < d.count; ++i)
        if (indices[i] >= vertexCount)
            check.fail("index " + std::to_string(indices[i]) + " at position " + std::to_string(d.first + i) +
                       " >= vertex count " + std::to_string(vertexCount));
}

}  // namespace

void validateDraw(const DrawDesc& d, const PassDesc& pass, const PassExtent& extent, const ResourceLookup& lookup) {
    const PipelineDesc& p = lookup.pipeline(d.pipeline);
    const ProgramDesc& program = lookup.program(d.pipeline);
    const DrawChecks check(p, pass, extent, lookup);
    if (d.params.type() != program.params) check.fail("parameters do not match program " + program.name);
    if (p.depth.test && !pass.depth.texture) check.fail("depth test on but the pass has no depth target");
    if (pass.countSamplesInto && (p.alphaTest.enabled || p.alphaTest.alphaToCoverage))
        check.fail("alpha test or alpha-to-coverage in a pass that counts samples into an occlusion query");
    checkTextures(program, d.params, check);
    if (program.check) program.check(d.params.data(), check);
    if (program.vertexInput == VertexInput::Fullscreen) return;  // no vertex input

    if (d.count % 3 != 0) check.fail("count " + std::to_string(d.count) + " is not a multiple of 3");
    const BufferDesc& vb = check.bufferOfKind(d.vertices, BufferKind::Vertex, "a vertex buffer");
    const std::uint64_t vertexCount = vb.size / sizeof(Vertex);
    if (d.indices) {
        checkIndices(d, vertexCount, check, lookup);
    } else if (std::uint64_t(d.first) + d.count > vertexCount) {
        check.fail("vertices [" + std::to_string(d.first) + ", " + std::to_string(d.first + d.count) + ") outside " +
                   quotedName(vb.name) + " of " + std::to_string(vertexCount));
    }
    if (d.instances) {
        const BufferDesc& inst = check.bufferOfKind(d.instances, BufferKind::Instance, "an instance buffer");
        if (std::uint64_t(d.instanceCount) * sizeof(Instance) > inst.size)
            check.fail(std::to_string(d.instanceCount) + " instances exceed " + quotedName(inst.name));
    } else if (d.instanceCount != 1) {
        check.fail("instanceCount " + std::to_string(d.instanceCount) + " without an instance buffer");
    }
}

std::uint32_t largestIndex(std::span<const std::byte> indexData) {
    std::uint32_t largest = 0;
    const std::size_t count = indexData.size() / sizeof(std::uint32_t);
    for (std::size_t i = 0; i < count; ++i) {
        std::uint32_t index;
        std::memcpy(&index, indexData.data() + i * sizeof index, sizeof index);
        largest = index > largest ? index : largest;
    }
    return largest;
}

}  // namespace engine::render
