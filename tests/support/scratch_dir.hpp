// SPDX-License-Identifier: MIT
#pragma once
// A directory of its own under the system temp dir: made empty when this object is made (what
// an earlier run left there goes) and removed with it, so that nothing is written into the
// repository. Needs no test framework (the fuzz targets use it as it is).
#include <filesystem>
#include <string>
#include <system_error>

namespace ssam::testing {

class ScratchDir {
public:
    explicit ScratchDir(const std::string& name) : path_(std::filesystem::temp_directory_path() / name) {
        std::filesystem::remove_all(path_);
        std::filesystem::create_directories(path_);
    }
    ~ScratchDir() {
        std::error_code ignored;
        std::filesystem::remove_all(path_, ignored);
    }
    ScratchDir(const ScratchDir&) = delete;
    ScratchDir& operator=(const ScratchDir&) = delete;

    std::filesystem::path operator/(const std::string& file) const { return path_ / file; }
    const std::filesystem::path& path() const { return path_; }

private:
    std::filesystem::path path_;
};

}  // namespace ssam::testing
