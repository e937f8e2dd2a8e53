// SPDX-License-Identifier: MIT
#pragma once
// A fresh directory per test under the system temp dir, removed afterwards, so tests
// never write into the repository and can run in parallel (ctest -j, one process per test).
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <string>

namespace ssam::testing {

class TempDir {
public:
    // `prefix` names the test binary's area, e.g. "ssam_unit_capture".
    explicit TempDir(const std::string& prefix = "ssam_test") {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        std::string name = prefix + "_" + std::to_string(::getpid());
        if (info) name += std::string("_") + info->test_suite_name() + "_" + info->name();
        for (char& c : name)
            if (c == '/') c = '_';  // parameterised test names contain '/'
        path_ = std::filesystem::temp_directory_path() / name;
        std::filesystem::remove_all(path_);
        std::filesystem::create_directories(path_);
    }
    ~TempDir() {
        std::error_code ignored;
        std::filesystem::remove_all(path_, ignored);
    }
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;

    std::filesystem::path operator/(const std::string& file) const { return path_ / file; }
    const std::filesystem::path& path() const { return path_; }

private:
    std::filesystem::path path_;
};

}  // namespace ssam::testing
