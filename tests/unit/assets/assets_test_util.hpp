// SPDX-License-Identifier: MIT
#pragma once
// Shared helpers of unit_assets: fixture paths, a per-test temporary directory, and a
// matcher-friendly way to capture the engine::Error a load throws.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include "engine/core/error.hpp"
#include "expect_error.hpp"  // tests/support
#include "temp_dir.hpp"      // tests/support

namespace assets_test {

using ssam::testing::errorOf;
using ssam::testing::TempDir;

inline std::filesystem::path fixture(const std::string& name) {
    return std::filesystem::path(SSAM_SOURCE_DIR) / "tests" / "data" / "gltf" / name;
}

inline void writeFile(const std::filesystem::path& path, const void* data, std::size_t size) {
    std::ofstream out(path, std::ios::binary);
    out.write(static_cast<const char*>(data), static_cast<std::streamsize>(size));
}
inline void writeFile(const std::filesystem::path& path, const std::string& text) {
    writeFile(path, text.data(), text.size());
}

}  // namespace assets_test
