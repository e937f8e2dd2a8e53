// SPDX-License-Identifier: MIT
#include "vk_functions.hpp"

#include <string>

#include "failure.hpp"
#include "ssam_vk_enum_names.hpp"  // generated from <vulkan/vulkan_core.h> (cmake/vk_enum_names.cmake)

namespace ssam::vk::detail {

const char* resultName(VkResult result) noexcept {
    switch (result) {
        case VK_SUCCESS: return "VK_SUCCESS";
        case VK_ERROR_OUT_OF_HOST_MEMORY: return "VK_ERROR_OUT_OF_HOST_MEMORY";
        case VK_ERROR_OUT_OF_DEVICE_MEMORY: return "VK_ERROR_OUT_OF_DEVICE_MEMORY";
        case VK_ERROR_INITIALIZATION_FAILED: return "VK_ERROR_INITIALIZATION_FAILED";
        case VK_ERROR_DEVICE_LOST: return "VK_ERROR_DEVICE_LOST";
        case VK_ERROR_FORMAT_NOT_SUPPORTED: return "VK_ERROR_FORMAT_NOT_SUPPORTED";
        case VK_ERROR_FRAGMENTED_POOL: return "VK_ERROR_FRAGMENTED_POOL";
        case VK_ERROR_OUT_OF_POOL_MEMORY: return "VK_ERROR_OUT_OF_POOL_MEMORY";
        case VK_ERROR_INVALID_SHADER_NV: return "VK_ERROR_INVALID_SHADER_NV";
        default: return "a VkResult";
    }
}

std::string formatName(VkFormat format) {
    const char* name = enumName(format);
    return name ? name : "VkFormat " + std::to_string(static_cast<int>(format));
}

void check(VkResult result, const char* what) {
    if (result == VK_SUCCESS) return;
    const bool memory = result == VK_ERROR_OUT_OF_HOST_MEMORY || result == VK_ERROR_OUT_OF_DEVICE_MEMORY;
    throw Failure(memory ? Status::OutOfMemory : Status::DeviceError,
                  std::string("ssam::vk: ") + what + " returned " + resultName(result) + " (" +
                      std::to_string(static_cast<int>(result)) + ")");
}

void check(VkResult result, const char* call, const char* what) {
    if (result != VK_SUCCESS) check(result, (std::string(call) + ", " + what).c_str());
}

void loadFunctions(VkFunctions& vk, const DeviceDesc& desc) {
    PFN_vkGetDeviceProcAddr getDevice = desc.getDeviceProcAddr;
    if (!getDevice)
        getDevice =
            reinterpret_cast<PFN_vkGetDeviceProcAddr>(desc.getInstanceProcAddr(desc.instance, "vkGetDeviceProcAddr"));
    if (!getDevice) throw Failure(Status::MissingEntryPoint, "ssam::vk: the loader has no vkGetDeviceProcAddr");
    const auto missing = [](const char* name) {
        return Failure(Status::MissingEntryPoint,
                       std::string("ssam::vk: the host's loader returned no address for vk") + name);
    };
#define SSAM_VK_LOAD_INSTANCE(name)                                                                \
    vk.name = reinterpret_cast<PFN_vk##name>(desc.getInstanceProcAddr(desc.instance, "vk" #name)); \
    if (!vk.name) throw missing(#name);
#define SSAM_VK_LOAD_DEVICE(name)                                                 \
    vk.name = reinterpret_cast<PFN_vk##name>(getDevice(desc.device, "vk" #name)); \
    if (!vk.name) throw missing(#name);
    SSAM_VK_INSTANCE_FUNCTIONS(SSAM_VK_LOAD_INSTANCE)
    SSAM_VK_DEVICE_FUNCTIONS(SSAM_VK_LOAD_DEVICE)
#undef SSAM_VK_LOAD_INSTANCE
#undef SSAM_VK_LOAD_DEVICE
    if (desc.renderingPath == RenderingPath::DynamicRendering) {
        const auto either = [&](const char* core, const char* khr) {
            PFN_vkVoidFunction f = getDevice(desc.device, core);
            return f ? f : getDevice(desc.device, khr);
        };
        vk.CmdBeginRendering =
            reinterpret_cast<PFN_vkCmdBeginRendering>(either("vkCmdBeginRendering", "vkCmdBeginRenderingKHR"));
        vk.CmdEndRendering =
            reinterpret_cast<PFN_vkCmdEndRendering>(either("vkCmdEndRendering", "vkCmdEndRenderingKHR"));
        if (!vk.CmdBeginRendering) throw missing("CmdBeginRendering (nor vkCmdBeginRenderingKHR)");
        if (!vk.CmdEndRendering) throw missing("CmdEndRendering (nor vkCmdEndRenderingKHR)");
    }
    vk.device = desc.device;
    vk.allocator = desc.allocationCallbacks;
}

}  // namespace ssam::vk::detail
