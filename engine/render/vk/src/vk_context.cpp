// SPDX-License-Identifier: MIT
#include "vk_context.hpp"

#include <cstring>
#include <memory>
#include <vector>

#include "engine/core/error.hpp"
#include "engine/core/log.hpp"
#include "engine/render/vk/vk_results.hpp"
#include "engine/render/vk/vk_window.hpp"

#define GLFW_INCLUDE_NONE
#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>

namespace engine::render::vk {
namespace {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

VKAPI_ATTR VkBool32 VKAPI_CALL onMessage(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                         VkDebugUtilsMessageTypeFlagsEXT,
                                         const VkDebugUtilsMessengerCallbackDataEXT* data, void* user) {
    if (severity < VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT) return VK_FALSE;
    auto* context = static_cast<VulkanContext*>(user);
    ++context->validationMessages;
    const std::string message = std::string("Vulkan validation: ") + (data->pMessage ? data->pMessage : "");
    if (context->onValidation) context->onValidation(message);
    else log::warn(message);
    return VK_FALSE;  // the call goes on: validation observes, it does not change behaviour
}

bool hasLayer(const char* name) {
    std::uint32_t count = 0;
    vkEnumerateInstanceLayerProperties(&count, nullptr);
    std::vector<VkLayerProperties> layers(count);
    vkEnumerateInstanceLayerProperties(&count, layers.data());
    for (const VkLayerProperties& l : layers)
        if (std::strcmp(l.layerName, name) == 0) return true;
    return false;
}

bool hasDeviceExtension(VkPhysicalDevice device, const char* name) {
    std::uint32_t count = 0;
    vkEnumerateDeviceExtensionProperties(device, nullptr, &count, nullptr);
    std::vector<VkExtensionProperties> extensions(count);
    vkEnumerateDeviceExtensionProperties(device, nullptr, &count, extensions.data());
    for (const VkExtensionProperties& e : extensions)
        if (std::strcmp(e.extensionName, name) == 0) return true;
    return false;
}

int graphicsFamily(VkPhysicalDevice device) {
    std::uint32_t count = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(device, &count, nullptr);
    std::vector<VkQueueFamilyProperties> families(count);
    vkGetPhysicalDeviceQueueFamilyProperties(device, &count, families.data());
    for (std::uint32_t i = 0; i < count; ++i)
        if (families[i].queueFlags & VK_QUEUE_GRAPHICS_BIT) return int(i);
    return -1;
}

std::string versionName(std::uint32_t v) {
    return std::to_string(VK_API_VERSION_MAJOR(v)) + "." + std::to_string(VK_API_VERSION_MINOR(v)) + "." +
           std::to_string(VK_API_VERSION_PATCH(v));
}

}  // namespace

const char* resultName(VkResult result) {
    switch (result) {
        case VK_SUCCESS: return "VK_SUCCESS";
        case VK_NOT_READY: return "VK_NOT_READY";
        case VK_TIMEOUT: return "VK_TIMEOUT";
        case VK_ERROR_OUT_OF_HOST_MEMORY: return "VK_ERROR_OUT_OF_HOST_MEMORY";
        case VK_ERROR_OUT_OF_DEVICE_MEMORY: return "VK_ERROR_OUT_OF_DEVICE_MEMORY";
        case VK_ERROR_INITIALIZATION_FAILED: return "VK_ERROR_INITIALIZATION_FAILED";
        case VK_ERROR_DEVICE_LOST: return "VK_ERROR_DEVICE_LOST";
        case VK_ERROR_MEMORY_MAP_FAILED: return "VK_ERROR_MEMORY_MAP_FAILED";
        case VK_ERROR_LAYER_NOT_PRESENT: return "VK_ERROR_LAYER_NOT_PRESENT";
        case VK_ERROR_EXTENSION_NOT_PRESENT: return "VK_ERROR_EXTENSION_NOT_PRESENT";
        case VK_ERROR_FEATURE_NOT_PRESENT: return "VK_ERROR_FEATURE_NOT_PRESENT";
        case VK_ERROR_INCOMPATIBLE_DRIVER: return "VK_ERROR_INCOMPATIBLE_DRIVER";
        case VK_ERROR_TOO_MANY_OBJECTS: return "VK_ERROR_TOO_MANY_OBJECTS";
        case VK_ERROR_FORMAT_NOT_SUPPORTED: return "VK_ERROR_FORMAT_NOT_SUPPORTED";
        case VK_ERROR_OUT_OF_POOL_MEMORY: return "VK_ERROR_OUT_OF_POOL_MEMORY";
        case VK_ERROR_SURFACE_LOST_KHR: return "VK_ERROR_SURFACE_LOST_KHR";
        case VK_ERROR_OUT_OF_DATE_KHR: return "VK_ERROR_OUT_OF_DATE_KHR";
        case VK_SUBOPTIMAL_KHR: return "VK_SUBOPTIMAL_KHR";
        default: return "VkResult";
    }
}

std::string vulkanResultMessage(int result, const std::string& what) {
    std::string message = what + ": " + resultName(VkResult(result)) + " (" + std::to_string(result) + ")";
    switch (VkResult(result)) {
        case VK_ERROR_DEVICE_LOST:
            return message +
                   ": the Vulkan device was lost (a driver reset, hang or crash); nothing made on it can "
                   "be used again: make a new backend";
        case VK_ERROR_OUT_OF_DEVICE_MEMORY: return message + ": out of device memory";
        case VK_ERROR_OUT_OF_HOST_MEMORY: return message + ": out of host memory";
        default: return message;
    }
}

double timestampMilliseconds(std::uint64_t begin, std::uint64_t end, std::uint32_t validBits, double periodNs) {
    const std::uint64_t mask = validBits >= 64 ? ~std::uint64_t(0) : (std::uint64_t(1) << validBits) - 1;
    const std::uint64_t ticks = ((end & mask) - (begin & mask)) & mask;  // modulo 2^validBits
    return double(ticks) * periodNs / 1.0e6;
}

void check(VkResult result, const std::string& what) {
    if (result == VK_SUCCESS) return;
    throw Error(vulkanResultMessage(int(result), what));
}

std::unique_ptr<VulkanContext> VulkanContext::create(const VulkanOptions& options) {
    auto c = std::make_unique<VulkanContext>();
    c->onValidation = options.onValidation;
    std::uint32_t loaderVersion = 0;
    if (vkEnumerateInstanceVersion(&loaderVersion) != VK_SUCCESS || loaderVersion < VK_API_VERSION_1_3)
        throw Error("Vulkan backend: the Vulkan loader offers " + versionName(loaderVersion) + ", 1.3 is needed");
    if (options.validation && !hasLayer(kValidationLayer))
        throw Error(std::string("Vulkan backend: validation asked for, but ") + kValidationLayer +
                    " is not installed (Debian: vulkan-validationlayers)");

    VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
    app.pApplicationName = "ssam";
    app.pEngineName = "ssam";
    app.apiVersion = VK_API_VERSION_1_3;
    std::vector<const char*> layers, extensions;
    std::vector<std::string> windowExtensions;
    if (options.window) windowExtensions = VulkanWindow::instanceExtensions();
    for (const std::string& e : windowExtensions) extensions.push_back(e.c_str());
    // Synchronization validation: the hazards a missing barrier leaves ([Khronos validation]).
    const VkValidationFeatureEnableEXT enables[] = {VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT};
    VkValidationFeaturesEXT features{VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT};
    features.enabledValidationFeatureCount = 1;
    features.pEnabledValidationFeatures = enables;
    VkDebugUtilsMessengerCreateInfoEXT messenger{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
    messenger.messageSeverity =
        VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
    messenger.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                            VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                            VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
    messenger.pfnUserCallback = onMessage;
    messenger.pUserData = c.get();
    VkInstanceCreateInfo ci{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
    ci.pApplicationInfo = &app;
    if (options.validation) {
        layers.push_back(kValidationLayer);
        extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
        features.pNext = &messenger;  // instance creation and destruction are validated too
        ci.pNext = &features;
    }
    ci.enabledLayerCount = std::uint32_t(layers.size());
    ci.ppEnabledLayerNames = layers.data();
    ci.enabledExtensionCount = std::uint32_t(extensions.size());
    ci.ppEnabledExtensionNames = extensions.data();
    check(vkCreateInstance(&ci, nullptr, &c->instance), "Vulkan backend: vkCreateInstance");
    if (options.validation) {
        auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(c->instance, "vkCreateDebugUtilsMessengerEXT"));
        if (!create) throw Error("Vulkan backend: vkCreateDebugUtilsMessengerEXT is missing");
        messenger.pNext = nullptr;
        check(create(c->instance, &messenger, nullptr, &c->messenger), "Vulkan backend: creating the debug messenger");
    }

    if (options.window)
        check(glfwCreateWindowSurface(c->instance, options.window->window(), nullptr, &c->surface),
              "Vulkan backend: glfwCreateWindowSurface");

    std::uint32_t count = 0;
    vkEnumeratePhysicalDevices(c->instance, &count, nullptr);
    std::vector<VkPhysicalDevice> devices(count);
    vkEnumeratePhysicalDevices(c->instance, &count, devices.data());
    std::string list;
    int chosen = -1;
    for (std::uint32_t i = 0; i < count; ++i) {
        VkPhysicalDeviceProperties p;
        vkGetPhysicalDeviceProperties(devices[i], &p);
        const bool usable = p.apiVersion >= VK_API_VERSION_1_3 && graphicsFamily(devices[i]) >= 0;
        list += std::string(list.empty() ? "" : "; ") + std::to_string(i) + ": " + p.deviceName + " (Vulkan " +
                versionName(p.apiVersion) + (usable ? "" : ", unusable: needs 1.3 and a graphics queue") + ")";
        if (options.device < 0 && chosen < 0 && usable) chosen = int(i);
        if (options.device == int(i)) {
            if (!usable)
                throw Error("Vulkan backend: device " + std::to_string(i) + " cannot be used; devices: " + list);
            chosen = int(i);
        }
    }
    if (count == 0) throw Error("Vulkan backend: no Vulkan device (Debian: mesa-vulkan-drivers for lavapipe)");
    if (chosen < 0) {
        if (options.device >= 0)
            throw Error("Vulkan backend: no device " + std::to_string(options.device) + "; devices: " + list);
        throw Error("Vulkan backend: no device with Vulkan 1.3 and a graphics queue; devices: " + list);
    }
    c->physical = devices[std::size_t(chosen)];
    c->queueFamily = std::uint32_t(graphicsFamily(c->physical));
    {
        std::uint32_t families = 0;
        vkGetPhysicalDeviceQueueFamilyProperties(c->physical, &families, nullptr);
        std::vector<VkQueueFamilyProperties> properties(families);
        vkGetPhysicalDeviceQueueFamilyProperties(c->physical, &families, properties.data());
        c->timestampValidBits = properties[c->queueFamily].timestampValidBits;
    }
    vkGetPhysicalDeviceProperties(c->physical, &c->properties);
    vkGetPhysicalDeviceMemoryProperties(c->physical, &c->memory);

    VkPhysicalDeviceDriverProperties driver{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES};
    VkPhysicalDeviceProperties2 properties2{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2};
    properties2.pNext = &driver;
    vkGetPhysicalDeviceProperties2(c->physical, &properties2);
    c->info.device = c->properties.deviceName;
    c->info.driver = std::string(driver.driverName) + " " + driver.driverInfo;
    c->info.apiVersion = c->properties.apiVersion;
    c->info.deviceIndex = chosen;
    c->info.validation = options.validation;

    const float priority = 1.0f;
    VkDeviceQueueCreateInfo queue{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
    queue.queueFamilyIndex = c->queueFamily;
    queue.queueCount = 1;
    queue.pQueuePriorities = &priority;
    std::vector<const char*> deviceExtensions;
    if (c->surface) {
        VkBool32 presents = VK_FALSE;
        vkGetPhysicalDeviceSurfaceSupportKHR(c->physical, c->queueFamily, c->surface, &presents);
        if (!presents || !hasDeviceExtension(c->physical, VK_KHR_SWAPCHAIN_EXTENSION_NAME))
            throw Error(std::string("Vulkan backend: ") + c->properties.deviceName +
                        "'s graphics queue cannot present to the window");
        deviceExtensions.push_back(VK_KHR_SWAPCHAIN_EXTENSION_NAME);
    }
    VkPhysicalDeviceConditionalRenderingFeaturesEXT conditional{
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_CONDITIONAL_RENDERING_FEATURES_EXT};
    VkPhysicalDeviceFeatures2 supported{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
    if (hasDeviceExtension(c->physical, VK_EXT_CONDITIONAL_RENDERING_EXTENSION_NAME)) {
        supported.pNext = &conditional;
        vkGetPhysicalDeviceFeatures2(c->physical, &supported);
        if (conditional.conditionalRendering) {
            deviceExtensions.push_back(VK_EXT_CONDITIONAL_RENDERING_EXTENSION_NAME);
            c->conditionalRendering = true;
        }
    } else {
        vkGetPhysicalDeviceFeatures2(c->physical, &supported);
    }
    // Independent blending per target and dual... only what the interface needs.
    VkPhysicalDeviceFeatures2 enabled{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
    if (!supported.features.independentBlend)
        throw Error(std::string("Vulkan backend: ") + c->properties.deviceName + " lacks independentBlend");
    enabled.features.independentBlend = VK_TRUE;
    VkPhysicalDeviceConditionalRenderingFeaturesEXT conditionalOn{
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_CONDITIONAL_RENDERING_FEATURES_EXT};
    conditionalOn.conditionalRendering = VK_TRUE;
    if (c->conditionalRendering) enabled.pNext = &conditionalOn;
    VkDeviceCreateInfo dci{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
    dci.pNext = &enabled;
    dci.queueCreateInfoCount = 1;
    dci.pQueueCreateInfos = &queue;
    dci.enabledExtensionCount = std::uint32_t(deviceExtensions.size());
    dci.ppEnabledExtensionNames = deviceExtensions.data();
    check(vkCreateDevice(c->physical, &dci, nullptr, &c->device),
          std::string("Vulkan backend: creating a device on ") + c->properties.deviceName);
    vkGetDeviceQueue(c->device, c->queueFamily, 0, &c->queue);
    return c;
}

VulkanContext::~VulkanContext() {
    if (device) vkDestroyDevice(device, nullptr);
    if (surface) vkDestroySurfaceKHR(instance, surface, nullptr);
    if (messenger) {
        auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(instance, "vkDestroyDebugUtilsMessengerEXT"));
        if (destroy) destroy(instance, messenger, nullptr);
    }
    if (instance) vkDestroyInstance(instance, nullptr);
}

std::uint32_t VulkanContext::memoryType(std::uint32_t typeBits, VkMemoryPropertyFlags wanted,
                                        const std::string& what) const {
    for (std::uint32_t i = 0; i < memory.memoryTypeCount; ++i)
        if ((typeBits & (1u << i)) && (memory.memoryTypes[i].propertyFlags & wanted) == wanted) return i;
    throw Error(what + ": no memory type with the properties needed on " + info.device);
}

}  // namespace engine::render::vk
