// SPDX-License-Identifier: MIT
#include "png_writer.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include <png.h>

namespace gl_example {

namespace {

// Creates an empty, new file beside `path` (O_EXCL: ours alone) and names it in `temporary`.
std::string createTemporaryBeside(const std::string& path, std::string& temporary) {
    const std::filesystem::path target(path);
    const std::filesystem::path directory = target.has_parent_path() ? target.parent_path() : ".";
    for (unsigned attempt = 0; attempt < 100; ++attempt) {
        const std::filesystem::path candidate =
            target.parent_path() / ("." + target.stem().string() + ".tmp-" + std::to_string(::getpid()) + "-" +
                                    std::to_string(attempt) + target.extension().string());
        const int fd = ::open(candidate.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (fd >= 0) {
            ::close(fd);
            temporary = candidate.string();
            return {};
        }
        if (errno != EEXIST) return "cannot create files in '" + directory.string() + "': " + std::strerror(errno);
    }
    return "cannot create files in '" + directory.string() + "': no free temporary name";
}

}  // namespace

std::string writePng(const std::string& path, int width, int height, const std::vector<std::uint8_t>& rgba) {
    if (width <= 0 || height <= 0 || rgba.size() != std::size_t(width) * std::size_t(height) * 4)
        return "writePng: " + std::to_string(rgba.size()) + " bytes for " + std::to_string(width) + "x" +
               std::to_string(height) + " RGBA";
    // A temporary file beside the target, renamed into place when complete: a failure leaves
    // no partial file. libpng's simplified API writes it deflate-compressed, 8-bit straight RGBA.
    std::string temporary;
    if (std::string why = createTemporaryBeside(path, temporary); !why.empty()) return why;
    png_image image{};
    image.version = PNG_IMAGE_VERSION;
    image.width = static_cast<png_uint_32>(width);
    image.height = static_cast<png_uint_32>(height);
    image.format = PNG_FORMAT_RGBA;
    const bool written = png_image_write_to_file(&image, temporary.c_str(), 0, rgba.data(), 0, nullptr) != 0;
    const std::string libpngMessage = image.message;
    png_image_free(&image);
    if (!written) {
        std::remove(temporary.c_str());
        return "cannot write '" + path + "': libpng: " + libpngMessage;
    }
    if (std::rename(temporary.c_str(), path.c_str()) != 0) {
        std::string why = std::string("cannot write '") + path + "': " + std::strerror(errno);
        std::remove(temporary.c_str());
        return why;
    }
    return {};
}

std::string checkWritable(const std::string& path) {
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) return "'" + path + "' is a directory";
    std::string temporary;
    if (std::string why = createTemporaryBeside(path, temporary); !why.empty()) return why;
    std::remove(temporary.c_str());
    return {};
}

std::string checkWritable(std::initializer_list<std::string> paths) {
    for (const std::string& path : paths)
        if (!path.empty())
            if (std::string why = checkWritable(path); !why.empty()) return why;
    return {};
}

}  // namespace gl_example
