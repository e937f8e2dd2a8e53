// SPDX-License-Identifier: MIT
#pragma once
// The GPU backend of the techniques' soft-against-GPU tests (techniques_gpu_test.cpp,
// hashed_gpu_test.cpp, temporal_gpu_test.cpp): each is compiled twice, into gl_transparency (GL,
// suites named ...Gl) and into vk_transparency (SSAM_TEST_VK: Vulkan under validation, any
// message fails the test; suites named ...Vk). One source, one set of tolerances: lavapipe is
// llvmpipe's rasterizer and shader compiler behind Vulkan.
#include <memory>

#include "engine/render/backend.hpp"

#if defined(SSAM_TEST_VK)
#include "vk_validation.hpp"  // tests/support
#define SSAM_GPU_SUITE(name) name##Vk
#define SSAM_GPU_NAME(head, tail) head##Vk##tail
#else
#include "engine/render/gl/gl_backend.hpp"
#define SSAM_GPU_SUITE(name) name##Gl
#define SSAM_GPU_NAME(head, tail) head##Gl##tail
#endif

namespace transparency::testing {

#if defined(SSAM_TEST_VK)
inline constexpr const char* kGpuName = "Vulkan";
inline std::unique_ptr<engine::render::Backend> gpuBackend() { return ssam::testing::validatedVulkanBackend(); }
#else
inline constexpr const char* kGpuName = "GL";
inline std::unique_ptr<engine::render::Backend> gpuBackend() { return engine::render::gl::createGlBackend(); }
#endif

}  // namespace transparency::testing
