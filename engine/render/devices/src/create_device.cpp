// SPDX-License-Identifier: MIT
#include "engine/render/devices/create_device.hpp"

#include <array>
#include <cstdlib>

#include "engine/core/error.hpp"

namespace engine::render {
namespace {

// llvmpipe and lavapipe read their thread count when the context or device is made.
void setMesaThreads(const DeviceOptions& o) {
    if (o.threads > 0) setenv("LP_NUM_THREADS", std::to_string(o.threads).c_str(), 1);
}

std::unique_ptr<Device> makeSoft(const DeviceOptions& o) {
    soft::SoftOptions options = o.soft;
    if (options.threads == 0) options.threads = o.threads;
    return soft::createSoftBackend(options);
}

std::unique_ptr<Device> makeGl(const DeviceOptions& o) {
    setMesaThreads(o);
    return gl::createGlBackend(o.gl);
}

std::unique_ptr<Device> makeGles(const DeviceOptions& o) {
    setMesaThreads(o);
    return gles::createGlesBackend(o.gles);
}

std::unique_ptr<Device> makeVulkan(const DeviceOptions& o) {
    setMesaThreads(o);
    return vk::createVulkanBackend(o.vulkan);
}

std::string softAvailable(const DeviceOptions&) { return {}; }

std::string glAvailable(const DeviceOptions& o) {
    if (o.gl.context || o.gl.useCurrentContext) return {};  // the caller brings the context
    return gl::HeadlessEglContext::unavailableReason(o.gl.headless);
}

std::string glesAvailable(const DeviceOptions& o) {
    if (o.gles.context) return {};  // the caller brings the context
    return gles::glesUnavailableReason(o.gles);
}

std::string vulkanAvailable(const DeviceOptions& o) { return vk::vulkanUnavailableReason(o.vulkan); }

constexpr std::array kKinds{
    DeviceKindInfo{DeviceKind::Soft, "soft", "the CPU tile rasterizer (the reference; goldens come from it)", makeSoft,
                   softAvailable},
    DeviceKindInfo{DeviceKind::Gl, "gl", "OpenGL 4.5 core through EGL or the window's context (Mesa llvmpipe here)",
                   makeGl, glAvailable},
    DeviceKindInfo{DeviceKind::Gles, "gles",
                   "OpenGL ES 3.0 (WebGL2's API) through an EGL ES context (Mesa llvmpipe here)", makeGles,
                   glesAvailable},
    DeviceKindInfo{DeviceKind::Vulkan, "vk", "Vulkan 1.3, headless or presenting to a window (Mesa lavapipe here)",
                   makeVulkan, vulkanAvailable},
};

}  // namespace

std::span<const DeviceKindInfo> deviceKinds() { return kKinds; }

const DeviceKindInfo& deviceKindInfo(DeviceKind kind) {
    for (const DeviceKindInfo& k : kKinds)
        if (k.kind == kind) return k;
    throw Error("unknown render device kind " + std::to_string(int(kind)));
}

std::optional<DeviceKind> parseDeviceKind(std::string_view name) {
    for (const DeviceKindInfo& k : kKinds)
        if (name == k.name) return k.kind;
    return std::nullopt;
}

std::string deviceKindNames() {
    std::string names;
    for (const DeviceKindInfo& k : kKinds) names += (names.empty() ? "" : "|") + std::string(k.name);
    return names;
}

std::unique_ptr<Device> createDevice(DeviceKind kind, const DeviceOptions& options) {
    return deviceKindInfo(kind).create(options);
}

std::string deviceUnavailableReason(DeviceKind kind, const DeviceOptions& options) {
    return deviceKindInfo(kind).unavailableReason(options);
}

}  // namespace engine::render
