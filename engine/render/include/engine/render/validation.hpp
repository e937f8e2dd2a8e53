// SPDX-License-Identifier: MIT
#pragma once
// The misuse checks every backend makes before it renders, in one place so every backend
// refuses the same things with the same messages (the GL tests compare them with soft's).
// Resources are reached through lookups that throw engine::Error for stale handles.
#include <cstddef>
#include <functional>
#include <span>

#include "engine/core/error.hpp"
#include "engine/render/buffer.hpp"
#include "engine/render/pass.hpp"
#include "engine/render/pipeline.hpp"
#include "engine/render/program_desc.hpp"
#include "engine/render/texture.hpp"

namespace engine::render {

struct PassExtent {
    int width = 0;
    int height = 0;
    int samples = 0;
};

struct ResourceLookup {
    std::function<const TextureDesc&(TextureHandle)> texture;
    std::function<const BufferDesc&(BufferHandle)> buffer;
    std::function<std::span<const std::byte>(BufferHandle)> indexData;  // contents of an index buffer
    std::function<std::uint32_t(BufferHandle)> maxIndex;  // its largest index (largestIndex, kept per write)
    std::function<const PipelineDesc&(PipelineHandle)> pipeline;
    std::function<const ProgramDesc&(PipelineHandle)> program;  // the program a pipeline runs
};

// A size in 1..16384 per side and at most 1 GiB, 1/2/4/8 samples (multisampled and depth
// textures are render targets), a mip count that fits the size and 1 when multisampled.
// Checked before anything is allocated; `what` names the texture in the message.
void validateTexture(const TextureDesc& desc, const std::string& what);

// Initial data: at most one level per mip level, each of exactly the level's size (16F formats
// given as 32-bit floats; a multisampled level holds every sample).
void validateTextureData(const TextureDesc& desc, const TextureData& data, const std::string& what);

// A positive size that is a whole number of elements of its kind, and initial data (when
// given) of exactly that size.
void validateBuffer(const BufferDesc& desc, std::span<const std::byte> data, const std::string& what);

// An update of `size` bytes at `offset` that lies inside the buffer.
void validateBufferUpdate(const BufferDesc& desc, std::uint64_t offset, std::uint64_t size);

// A resolve between textures of one size and format into a single-sampled destination.
// Returns how errors after it name the resolve ("resolve 'a' -> 'b'").
std::string validateResolve(const TextureDesc& source, const TextureDesc& destination);

// Readback and presenting read single-sampled textures.
void validateReadback(const TextureDesc& desc);

// Colour attachments are colour render targets, the depth attachment is D32F, all share one
// size and sample count, and there is at least one. Returns that size.
PassExtent validatePass(const PassDesc& pass, const ResourceLookup& lookup);

// The draw's parameters match its program, buffers are of the right kind and hold every
// index, vertex and instance it reads, sampled textures are single-sampled, large enough
// for full-screen programs and not bound as a target of the pass.
void validateDraw(const DrawDesc& draw, const PassDesc& pass, const PassExtent& extent, const ResourceLookup& lookup);

// The largest of the uint32 indices (0 for none): a backend keeps it per index buffer, updated
// when the buffer is written, so validateDraw need not read every index of every draw.
std::uint32_t largestIndex(std::span<const std::byte> indexData);

// Occlusion queries: reading one before any pass counted into it, and reading one the open
// pass counts into or destroying one it uses (`open` null when no pass is open).
Error uncountedQueryError(const std::string& queryName);
void checkQueryUse(QueryHandle query, const std::string& queryName, const PassDesc* open, bool destroying);

// 'name', or '<unnamed>': how resources are named in error messages.
std::string quotedName(const std::string& name);

}  // namespace engine::render
