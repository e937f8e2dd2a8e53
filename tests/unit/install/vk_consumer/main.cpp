// SPDX-License-Identifier: MIT
// A C++17 host of ssam::vk alone (tests/unit/install/component_only_consumer.cmake): compiles the public
// header as C++17, links libssam_vk and nothing of the engine. An empty device description gives a
// status, not a crash; then, where this machine has a Vulkan device, SSAM is created from the
// host's instance and device through the host's vkGetInstanceProcAddr and released.
#include <cstdio>

#include <vulkan/vulkan.h>
#if defined(__SANITIZE_ADDRESS__)
#include <dlfcn.h>
#endif

#include <ssam/vk/ssam_vk.hpp>

static_assert(__cplusplus == 201703L, "built as C++17: the package must not raise the consumer's standard");

int main() {
#if defined(__SANITIZE_ADDRESS__)
    // Built by the sanitizer pass: lavapipe pinned, as in ssam/examples/vk_common/vk_host.cpp (why there).
    dlopen("libvulkan_lvp.so", RTLD_NOW | RTLD_NODELETE);
#endif
    ssam::vk::ScreenSpaceAlphaMaskVk ssam;
    const ssam::vk::Status empty = ssam.initialize(ssam::vk::DeviceDesc{});
    std::printf("initialize without a device: %s (%s)\n", ssam::vk::statusName(empty), ssam.lastMessage());
    if (empty != ssam::vk::Status::InvalidArgument) return 1;

    VkApplicationInfo app{
        VK_STRUCTURE_TYPE_APPLICATION_INFO, nullptr, "ssam_vk_consumer", 0, nullptr, 0, VK_API_VERSION_1_0};
    VkInstanceCreateInfo ci{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO, nullptr, 0, &app, 0, nullptr, 0, nullptr};
    VkInstance instance = VK_NULL_HANDLE;
    std::uint32_t count = 1;
    VkPhysicalDevice physical = VK_NULL_HANDLE;
    if (vkCreateInstance(&ci, nullptr, &instance) != VK_SUCCESS ||
        vkEnumeratePhysicalDevices(instance, &count, &physical) < 0 || count == 0) {
        std::printf("no Vulkan device here: the rest is skipped\n");
        if (instance) vkDestroyInstance(instance, nullptr);
        return 0;
    }
    const float priority = 1.0f;
    VkDeviceQueueCreateInfo queue{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO, nullptr, 0, 0, 1, &priority};
    VkDeviceCreateInfo di{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO, nullptr, 0, 1, &queue, 0, nullptr, 0, nullptr, nullptr};
    VkDevice device = VK_NULL_HANDLE;
    int rc = 1;
    if (vkCreateDevice(physical, &di, nullptr, &device) == VK_SUCCESS) {
        ssam::vk::DeviceDesc desc;
        desc.instance = instance;
        desc.physicalDevice = physical;
        desc.device = device;
        desc.apiVersion = VK_API_VERSION_1_0;
        desc.getInstanceProcAddr = vkGetInstanceProcAddr;
        const ssam::vk::Status status = ssam.initialize(desc);
        std::printf("initialize on the host's device: %s%s%s\n", ssam::vk::statusName(status),
                    status == ssam::vk::Status::Ok ? "" : ": ",
                    status == ssam::vk::Status::Ok ? "" : ssam.lastMessage());
        ssam.release();
        vkDestroyDevice(device, nullptr);
        rc = status == ssam::vk::Status::Ok ? 0 : 1;
    }
    vkDestroyInstance(instance, nullptr);
    return rc;
}
