// SPDX-License-Identifier: MIT
#pragma once
// The render devices a program can ask for, in one table: what each is called on a command
// line (`--backend soft|gl|gles|vk`), how it is made and whether it can be made here. The racer, the
// benchmark, the scaling run and the tests all choose a device through here, so a new driver
// is one row (and its library), and no program compares backend names itself.
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "engine/render/device.hpp"
#include "engine/render/gl/gl_backend.hpp"
#include "engine/render/gles/gles_backend.hpp"
#include "engine/render/soft/soft_backend.hpp"
#include "engine/render/vk/vk_backend.hpp"

namespace engine::render {

enum class DeviceKind : std::uint8_t { Soft, Gl, Vulkan, Gles };

struct DeviceOptions;

struct DeviceKindInfo {
    DeviceKind kind;
    const char* name;     // as --backend spells it: "soft", "gl", "gles", "vk"
    const char* summary;  // one line for --help
    std::unique_ptr<Device> (*create)(const DeviceOptions& options);
    // Empty when a device of this kind can be made here, else why not (for test skips).
    std::string (*unavailableReason)(const DeviceOptions& options);
};

// Every kind, in the order help texts list them.
std::span<const DeviceKindInfo> deviceKinds();
const DeviceKindInfo& deviceKindInfo(DeviceKind kind);
std::optional<DeviceKind> parseDeviceKind(std::string_view name);
// "soft|gl|gles|vk", for help texts and messages.
std::string deviceKindNames();

// Each driver's own options; `threads` (0: all hardware threads) is the soft driver's thread
// count and, for GL, GLES and Vulkan, Mesa's LP_NUM_THREADS, which llvmpipe and lavapipe read when
// the context or device is made, so that a comparison gives every driver the same threads.
struct DeviceOptions {
    int threads = 0;
    soft::SoftOptions soft;
    gl::GlOptions gl;
    gles::GlesOptions gles;
    vk::VulkanOptions vulkan;
};

// Throws engine::Error when the kind cannot be made here (no EGL, no ES 3.0, no Vulkan 1.3 device), saying why.
std::unique_ptr<Device> createDevice(DeviceKind kind, const DeviceOptions& options = {});
std::string deviceUnavailableReason(DeviceKind kind, const DeviceOptions& options = {});

}  // namespace engine::render
