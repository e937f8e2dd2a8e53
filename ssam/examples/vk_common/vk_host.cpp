// SPDX-License-Identifier: MIT
#include "vk_host.hpp"

#include <algorithm>
#include <cstdio>
#include <cstring>

#if defined(__SANITIZE_ADDRESS__)
#include <dlfcn.h>
#endif

namespace vk_example {

void check(VkResult result, const char* what) {
    if (result != VK_SUCCESS)
        throw std::runtime_error(std::string(what) + " returned VkResult " + std::to_string(result));
}

namespace {

// The loader's notice that the environment added a layer (VK_INSTANCE_LAYERS or
// VK_LOADER_LAYERS_ENABLE: a capture layer such as gfxreconstruct's, tests/capture/tools) is a
// warning of the loader's about its set-up, not a misuse of the API: it is printed, not counted.
bool isLayerFromTheEnvironment(VkDebugUtilsMessageTypeFlagsEXT type, const VkDebugUtilsMessengerCallbackDataEXT* data) {
    if (type != VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT || !data->pMessage || !data->pMessageIdName ||
        std::strcmp(data->pMessageIdName, "Loader Message") != 0)
        return false;
    return std::strstr(data->pMessage, "env var 'VK_INSTANCE_LAYERS' defined and adding layers") ||
           std::strstr(data->pMessage, "forced enabled due to env var 'VK_LOADER_LAYERS_ENABLE'");
}

VKAPI_ATTR VkBool32 VKAPI_CALL onValidation(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                            VkDebugUtilsMessageTypeFlagsEXT type,
                                            const VkDebugUtilsMessengerCallbackDataEXT* data, void* user) {
    if (severity < VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT) return VK_FALSE;
    if (isLayerFromTheEnvironment(type, data)) {
        std::printf("Vulkan loader: %s\n", data->pMessage);
        return VK_FALSE;
    }
    static_cast<VulkanHost*>(user)->validationMessages.push_back(data->pMessage ? data->pMessage : "");
    return VK_FALSE;
}

bool hasLayer(const char* name) {
    std::uint32_t count = 0;
    vkEnumerateInstanceLayerProperties(&count, nullptr);
    std::vector<VkLayerProperties> layers(count);
    vkEnumerateInstanceLayerProperties(&count, layers.data());
    return std::any_of(layers.begin(), layers.end(),
                       [&](const VkLayerProperties& l) { return std::strcmp(l.layerName, name) == 0; });
}

bool hasInstanceExtension(const char* name) {
    std::uint32_t count = 0;
    vkEnumerateInstanceExtensionProperties(nullptr, &count, nullptr);
    std::vector<VkExtensionProperties> extensions(count);
    vkEnumerateInstanceExtensionProperties(nullptr, &count, extensions.data());
    return std::any_of(extensions.begin(), extensions.end(),
                       [&](const VkExtensionProperties& e) { return std::strcmp(e.extensionName, name) == 0; });
}

// Only in a build with AddressSanitizer (CI's sanitizer pass builds the examples so): the Vulkan
// loader unloads the driver and the layer with the instance, and LeakSanitizer's exit scan then no
// longer sees their globals. The blocks lavapipe allocates once per load (240 bytes in 3) would read
// as leaks, and the layer's own could not be named by module (tests/lsan.supp). Pinned
// (RTLD_NODELETE), both stay mapped; an allocation of ours still has our frames in its stack.
void pinVulkanLibrariesForLeakSanitizer() {
#if defined(__SANITIZE_ADDRESS__)
    for (const char* library : {"libVkLayer_khronos_validation.so", "libvulkan_lvp.so"})
        dlopen(library, RTLD_NOW | RTLD_NODELETE);  // null where absent: nothing to pin
#endif
}

}  // namespace

VulkanHost::VulkanHost(bool withValidation, bool withDynamicRendering,
                       const std::vector<const char*>& surfaceExtensions, bool uniqueHandles)
    : validation(withValidation) {
    pinVulkanLibrariesForLeakSanitizer();
    std::uint32_t loaderVersion = VK_API_VERSION_1_0;
    if (vkEnumerateInstanceVersion(&loaderVersion) != VK_SUCCESS) throw NoVulkan("the Vulkan loader does not answer");
    constexpr const char* kLayer = "VK_LAYER_KHRONOS_validation";
    if (validation && !hasLayer(kLayer))
        throw NoVulkan("no VK_LAYER_KHRONOS_validation (Debian: vulkan-validationlayers)");
    VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
    app.pApplicationName = "ssam_vk_embedding";
    app.apiVersion = std::min<std::uint32_t>(loaderVersion, VK_API_VERSION_1_3);
    // Synchronization validation: the hazards a missing barrier leaves; messages of warning and
    // error severity, every type (performance warnings included).
    const VkValidationFeatureEnableEXT enables[] = {VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT};
    VkValidationFeaturesEXT features{VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT};
    features.enabledValidationFeatureCount = 1;
    features.pEnabledValidationFeatures = enables;
    const VkValidationFeatureDisableEXT disables[] = {VK_VALIDATION_FEATURE_DISABLE_UNIQUE_HANDLES_EXT};
    if (!uniqueHandles) {
        features.disabledValidationFeatureCount = 1;
        features.pDisabledValidationFeatures = disables;
    }
    VkDebugUtilsMessengerCreateInfoEXT messenger{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
    messenger.messageSeverity =
        VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
    messenger.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                            VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                            VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
    messenger.pfnUserCallback = onValidation;
    messenger.pUserData = this;
    std::vector<const char*> extensions;
    if (validation) extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
    for (const char* name : surfaceExtensions) {
        if (!hasInstanceExtension(name)) throw NoVulkan(std::string("no ") + name + " for --present");
        extensions.push_back(name);
    }
    VkInstanceCreateInfo ci{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
    ci.pApplicationInfo = &app;
    if (validation) {
        features.pNext = &messenger;
        ci.pNext = &features;
        ci.enabledLayerCount = 1;
        ci.ppEnabledLayerNames = &kLayer;
    }
    ci.enabledExtensionCount = std::uint32_t(extensions.size());
    ci.ppEnabledExtensionNames = extensions.data();
    if (vkCreateInstance(&ci, nullptr, &instance) != VK_SUCCESS) throw NoVulkan("vkCreateInstance failed");
    if (validation) {
        auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(instance, "vkCreateDebugUtilsMessengerEXT"));
        messenger.pNext = nullptr;
        check(create(instance, &messenger, nullptr, &messenger_), "vkCreateDebugUtilsMessengerEXT");
    }
    std::uint32_t count = 0;
    vkEnumeratePhysicalDevices(instance, &count, nullptr);
    std::vector<VkPhysicalDevice> devices(count);
    vkEnumeratePhysicalDevices(instance, &count, devices.data());
    for (VkPhysicalDevice d : devices) {
        std::uint32_t families = 0;
        vkGetPhysicalDeviceQueueFamilyProperties(d, &families, nullptr);
        std::vector<VkQueueFamilyProperties> props(families);
        vkGetPhysicalDeviceQueueFamilyProperties(d, &families, props.data());
        for (std::uint32_t i = 0; i < families && !physical; ++i)
            if (props[i].queueFlags & VK_QUEUE_GRAPHICS_BIT) physical = d, queueFamily = i;
        if (physical) break;
    }
    if (!physical) throw NoVulkan("no Vulkan device with a graphics queue (Debian: mesa-vulkan-drivers)");
    VkPhysicalDeviceProperties properties;
    vkGetPhysicalDeviceProperties(physical, &properties);
    deviceName = properties.deviceName;
    apiVersion = std::min(app.apiVersion, properties.apiVersion);
    const float priority = 1.0f;
    VkDeviceQueueCreateInfo queueInfo{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
    queueInfo.queueFamilyIndex = queueFamily;
    queueInfo.queueCount = 1;
    queueInfo.pQueuePriorities = &priority;
    VkDeviceCreateInfo di{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
    VkPhysicalDeviceVulkan13Features features13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
    if (withDynamicRendering) {
        if (apiVersion < VK_API_VERSION_1_3) throw NoVulkan("dynamic rendering asked for, but no Vulkan 1.3 here");
        VkPhysicalDeviceFeatures2 supported{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
        supported.pNext = &features13;
        vkGetPhysicalDeviceFeatures2(physical, &supported);
        if (!features13.dynamicRendering) throw NoVulkan("the device has no dynamicRendering feature");
        features13 = {VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
        features13.dynamicRendering = VK_TRUE;
        di.pNext = &features13;
        dynamicRendering = true;
    }
    // independentBlend where the device has it: SSAM's MaskPrecision::Rg16f needs it.
    VkPhysicalDeviceFeatures supported{}, enabled{};
    vkGetPhysicalDeviceFeatures(physical, &supported);
    enabled.independentBlend = supported.independentBlend;
    independentBlend = supported.independentBlend == VK_TRUE;
    di.pEnabledFeatures = &enabled;
    di.queueCreateInfoCount = 1;
    di.pQueueCreateInfos = &queueInfo;
    const char* swapchain = VK_KHR_SWAPCHAIN_EXTENSION_NAME;
    if (!surfaceExtensions.empty()) {
        std::uint32_t n = 0;
        vkEnumerateDeviceExtensionProperties(physical, nullptr, &n, nullptr);
        std::vector<VkExtensionProperties> available(n);
        vkEnumerateDeviceExtensionProperties(physical, nullptr, &n, available.data());
        if (std::none_of(available.begin(), available.end(),
                         [&](const VkExtensionProperties& e) { return std::strcmp(e.extensionName, swapchain) == 0; }))
            throw NoVulkan("the device has no VK_KHR_swapchain for --present");
        di.enabledExtensionCount = 1;
        di.ppEnabledExtensionNames = &swapchain;
    }
    check(vkCreateDevice(physical, &di, nullptr, &device), "vkCreateDevice");
    vkGetDeviceQueue(device, queueFamily, 0, &queue);
    VkCommandPoolCreateInfo pool{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    pool.queueFamilyIndex = queueFamily;
    check(vkCreateCommandPool(device, &pool, nullptr, &pool_), "vkCreateCommandPool");
}

VulkanHost::~VulkanHost() {
    if (device) {
        vkDeviceWaitIdle(device);
        for (const InFlight& f : inFlight_) vkDestroyFence(device, f.fence, nullptr);
        vkDestroyCommandPool(device, pool_, nullptr);
        vkDestroyDevice(device, nullptr);
    }
    if (messenger_) {
        auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(instance, "vkDestroyDebugUtilsMessengerEXT"));
        destroy(instance, messenger_, nullptr);
    }
    if (instance) vkDestroyInstance(instance, nullptr);
}

std::uint32_t VulkanHost::memoryType(std::uint32_t bits, VkMemoryPropertyFlags properties) const {
    VkPhysicalDeviceMemoryProperties memory;
    vkGetPhysicalDeviceMemoryProperties(physical, &memory);
    for (std::uint32_t i = 0; i < memory.memoryTypeCount; ++i)
        if ((bits & (1u << i)) && (memory.memoryTypes[i].propertyFlags & properties) == properties) return i;
    throw std::runtime_error("no suitable memory type");
}

VkDeviceMemory VulkanHost::allocate(const VkMemoryRequirements& requirements, VkMemoryPropertyFlags properties) const {
    VkMemoryAllocateInfo info{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    info.allocationSize = requirements.size;
    info.memoryTypeIndex = memoryType(requirements.memoryTypeBits, properties);
    VkDeviceMemory memory = VK_NULL_HANDLE;
    check(vkAllocateMemory(device, &info, nullptr, &memory), "vkAllocateMemory");
    return memory;
}

HostImage VulkanHost::createImage(VkFormat format, std::uint32_t width, std::uint32_t height, VkImageUsageFlags usage,
                                  VkImageAspectFlags aspect) {
    HostImage out;
    out.format = format;
    VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
    info.imageType = VK_IMAGE_TYPE_2D;
    info.format = format;
    info.extent = {width, height, 1};
    info.mipLevels = info.arrayLayers = 1;
    info.samples = VK_SAMPLE_COUNT_1_BIT;
    info.tiling = VK_IMAGE_TILING_OPTIMAL;
    info.usage = usage;
    check(vkCreateImage(device, &info, nullptr, &out.image), "vkCreateImage");
    VkMemoryRequirements requirements;
    vkGetImageMemoryRequirements(device, out.image, &requirements);
    out.memory = allocate(requirements, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
    check(vkBindImageMemory(device, out.image, out.memory, 0), "vkBindImageMemory");
    VkImageViewCreateInfo view{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    view.image = out.image;
    view.viewType = VK_IMAGE_VIEW_TYPE_2D;
    view.format = format;
    view.subresourceRange = {aspect, 0, 1, 0, 1};
    check(vkCreateImageView(device, &view, nullptr, &out.view), "vkCreateImageView");
    return out;
}

HostBuffer VulkanHost::createBuffer(VkDeviceSize size, VkBufferUsageFlags usage) {
    HostBuffer out;
    VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    info.size = size;
    info.usage = usage;
    check(vkCreateBuffer(device, &info, nullptr, &out.buffer), "vkCreateBuffer");
    VkMemoryRequirements requirements;
    vkGetBufferMemoryRequirements(device, out.buffer, &requirements);
    out.memory = allocate(requirements, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
    check(vkBindBufferMemory(device, out.buffer, out.memory, 0), "vkBindBufferMemory");
    check(vkMapMemory(device, out.memory, 0, VK_WHOLE_SIZE, 0, &out.mapped), "vkMapMemory");
    return out;
}

VkShaderModule VulkanHost::createShaderModule(const std::uint32_t* code, std::size_t bytes, const char* what) const {
    VkShaderModuleCreateInfo info{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
    info.codeSize = bytes;
    info.pCode = code;
    VkShaderModule module = VK_NULL_HANDLE;
    check(vkCreateShaderModule(device, &info, nullptr, &module), what);
    return module;
}

void imageBarrier(VkCommandBuffer cb, VkImage image, VkImageAspectFlags aspect, VkImageLayout from, VkImageLayout to,
                  VkPipelineStageFlags srcStages, VkAccessFlags srcAccess, VkPipelineStageFlags dstStages,
                  VkAccessFlags dstAccess) {
    VkImageMemoryBarrier b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
    b.srcAccessMask = srcAccess;
    b.dstAccessMask = dstAccess;
    b.oldLayout = from;
    b.newLayout = to;
    b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    b.image = image;
    b.subresourceRange = {aspect, 0, 1, 0, 1};
    vkCmdPipelineBarrier(cb, srcStages, dstStages, 0, 0, nullptr, 0, nullptr, 1, &b);
}

std::array<VkPipelineShaderStageCreateInfo, 2> shaderStages(VkShaderModule vertex, VkShaderModule fragment) {
    std::array<VkPipelineShaderStageCreateInfo, 2> stages{};
    for (VkPipelineShaderStageCreateInfo& stage : stages) {
        stage.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
        stage.pName = "main";
    }
    stages[0].stage = VK_SHADER_STAGE_VERTEX_BIT;
    stages[0].module = vertex;
    stages[1].stage = VK_SHADER_STAGE_FRAGMENT_BIT;
    stages[1].module = fragment;
    return stages;
}

void VulkanHost::destroy(HostImage& image) {
    vkDestroyImageView(device, image.view, nullptr);
    vkDestroyImage(device, image.image, nullptr);
    vkFreeMemory(device, image.memory, nullptr);
    image = {};
}

void VulkanHost::destroy(HostBuffer& buffer) {
    vkDestroyBuffer(device, buffer.buffer, nullptr);
    vkFreeMemory(device, buffer.memory, nullptr);
    buffer = {};
}

VkCommandBuffer VulkanHost::begin() {
    VkCommandBufferAllocateInfo allocate{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    allocate.commandPool = pool_;
    allocate.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    allocate.commandBufferCount = 1;
    VkCommandBuffer cb = VK_NULL_HANDLE;
    check(vkAllocateCommandBuffers(device, &allocate, &cb), "vkAllocateCommandBuffers");
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    check(vkBeginCommandBuffer(cb, &begin), "vkBeginCommandBuffer");
    return cb;
}

VkFence VulkanHost::submit(VkCommandBuffer cb, VkSemaphore signal) {
    check(vkEndCommandBuffer(cb), "vkEndCommandBuffer");
    VkFenceCreateInfo fenceInfo{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    VkFence fence = VK_NULL_HANDLE;
    check(vkCreateFence(device, &fenceInfo, nullptr, &fence), "vkCreateFence");
    VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &cb;
    if (signal) {
        submit.signalSemaphoreCount = 1;
        submit.pSignalSemaphores = &signal;
    }
    check(vkQueueSubmit(queue, 1, &submit, fence), "vkQueueSubmit");
    inFlight_.push_back({fence, cb});
    return fence;
}

void VulkanHost::wait(VkFence fence) {
    check(vkWaitForFences(device, 1, &fence, VK_TRUE, UINT64_MAX), "vkWaitForFences");
    for (auto it = inFlight_.begin(); it != inFlight_.end(); ++it)
        if (it->fence == fence) {
            vkFreeCommandBuffers(device, pool_, 1, &it->commandBuffer);
            vkDestroyFence(device, fence, nullptr);
            inFlight_.erase(it);
            return;
        }
}

}  // namespace vk_example
