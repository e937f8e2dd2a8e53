// SPDX-License-Identifier: MIT
#pragma once
// The Vulkan tests' backend: validation on (VK_LAYER_KHRONOS_validation + synchronization
// validation) and every message it reports is a failure of the test that caused it.
#include <memory>
#include <string>

#include <gtest/gtest.h>

#include "engine/render/vk/vk_backend.hpp"

namespace ssam::testing {

inline engine::render::vk::VulkanOptions validatedVulkanOptions() {
    engine::render::vk::VulkanOptions options;
    options.validation = true;
    options.onValidation = [](const std::string& message) { ADD_FAILURE() << message; };
    return options;
}

inline std::unique_ptr<engine::render::Device> validatedVulkanBackend(
    engine::render::vk::VulkanOptions options = validatedVulkanOptions()) {
    return engine::render::vk::createVulkanBackend(options);
}

}  // namespace ssam::testing
