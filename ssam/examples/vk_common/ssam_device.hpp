// SPDX-License-Identifier: MIT
#pragma once
// ssam::vk's description of the examples' Vulkan host (what the examples and ssam::vk's tests
// initialise SSAM with): the host's objects and its loader's vkGetInstanceProcAddr, no optional
// feature (a caller enables what its host enabled).
#include <ssam/vk/ssam_vk.hpp>

#include "vk_host.hpp"

namespace vk_example {

inline ssam::vk::DeviceDesc ssamDevice(const VulkanHost& host) {
    ssam::vk::DeviceDesc d;
    d.instance = host.instance;
    d.physicalDevice = host.physical;
    d.device = host.device;
    d.queueFamily = host.queueFamily;
    d.apiVersion = host.apiVersion;
    d.getInstanceProcAddr = vkGetInstanceProcAddr;
    return d;
}

}  // namespace vk_example
