// SPDX-License-Identifier: MIT
#include "content_dir.hpp"

#include <system_error>

namespace racer {

std::filesystem::path defaultContentDir() {
    std::error_code error;
    const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", error);
    if (!error) {
        std::filesystem::path installed = (exe.parent_path() / SSAM_CONTENT_FROM_EXE).lexically_normal();
        if (std::filesystem::is_directory(installed / "models", error)) return installed;
    }
    return SSAM_CONTENT_DIR;
}

}  // namespace racer
