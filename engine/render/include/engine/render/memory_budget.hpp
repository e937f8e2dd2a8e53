// SPDX-License-Identifier: MIT
#pragma once
// Whether a texture fits in the memory its backend can still give it, checked before it is
// allocated: a large target set (16384x16384 is an accepted size) is then refused with what it
// needs and what is available, instead of the kernel's out-of-memory killer ending the process
// halfway through allocating it (Linux overcommits: the allocation succeeds, the first write
// to its pages kills). validateTexture's fixed caps come first; this adds the machine's state.
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>

#include "engine/render/texture.hpp"

namespace engine::render {

// Memory a process can still allocate, and where the figure came from (for messages).
struct AvailableMemory {
    std::uint64_t bytes = 0;
    std::string source;  // e.g. "MemAvailable in /proc/meminfo"
};

// What a backend can still allocate right now; nullopt when it cannot tell (then nothing is
// refused for memory, and the allocation itself reports failure). Asked once per texture, so
// what earlier textures took is already subtracted.
using MemoryProbe = std::function<std::optional<AvailableMemory>()>;

// Bytes of every mip level and sample of a texture, as tightly packed texels.
std::uint64_t textureBytes(const TextureDesc& desc);
// "16384x16384 RGBA8_UNORM" (with " 4x" when multisampled), for messages.
std::string describeSize(const TextureDesc& desc);

// The host's memory: the least of /proc/meminfo's MemAvailable, what the cgroup (v2 or v1) the
// process runs in still allows, and the address space RLIMIT_AS still allows. nullopt where
// none of them can be read (not Linux).
std::optional<AvailableMemory> hostMemoryAvailable();

// Throws engine::Error, before anything is allocated, unless `probe` reports at least twice
// `bytes`: "<what> needs 1024 MiB and as much again free beside it, but 1500 MiB is available
// (MemAvailable in /proc/meminfo)". As much again, because a frame allocates beside its
// targets in proportion to them (a capture reads a target back into a float copy four times
// an RGBA8 target's size, then converts it; tile bins, draw lists), and a process left with
// nothing dies on its next page. `what` names the allocation ("texture 'x': 16384x16384
// RGBA8_UNORM"); `bytes` is the backend's own count (textureBytes plus what it keeps beside).
void checkFitsInMemory(std::uint64_t bytes, const std::string& what, const MemoryProbe& probe);

// The parsers behind hostMemoryAvailable, on the files' text (unit-tested).
// /proc/meminfo's MemAvailable in bytes.
std::optional<std::uint64_t> parseMemAvailable(std::string_view meminfo);
// A cgroup limit or usage file: a byte count, or nullopt for "max" (v2's no limit) and junk.
// v1 writes "no limit" as a huge number, which stays a (harmless) huge number.
std::optional<std::uint64_t> parseCgroupBytes(std::string_view text);
// /proc/self/status's VmSize in bytes (the address space RLIMIT_AS counts).
std::optional<std::uint64_t> parseVmSize(std::string_view status);

}  // namespace engine::render
