// SPDX-License-Identifier: MIT
#pragma once
// Private: opening a file through OpenImageIO with the checks every reader needs
// (file present, header sane, size under the cap) done before pixels are allocated.
#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <filesystem>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "engine/capture/image.hpp"
#include "engine/capture/image_read.hpp"

namespace engine::capture::detail {

// Throws engine::Error("image '<path>': <what>[: <oiio message>]").
[[noreturn]] void throwImageError(const std::filesystem::path& path, const std::string& what,
                                  const std::string& oiioMessage = {});

struct OpenedImage {
    // JPEG files are read through memory, without their metadata (jpeg_metadata.hpp); the
    // bytes and the reader outlive `input`, which is declared after them.
    std::vector<std::uint8_t> jpegBytes;
    std::unique_ptr<OIIO::Filesystem::IOMemReader> jpegReader;
    std::unique_ptr<OIIO::ImageInput> input;
    OIIO::ImageSpec spec;
    AlphaMode alpha = AlphaMode::Straight;
    bool srgbEncoded = false;  // integer data carrying sRGB-encoded colour
};

// Opens the first subimage, asking for straight (unassociated) alpha, and refuses zero-size,
// volume, deep and over-cap images. bytesPerValue is the size of one channel value in the
// buffer the caller will allocate, for the decoded-bytes cap.
OpenedImage openImage(const std::filesystem::path& path, const ReadOptions& options, std::size_t bytesPerValue);

// Reads all channels of the open subimage as `type` into `data`; throws on a read error
// (for example a truncated file).
void readPixels(const std::filesystem::path& path, OpenedImage& opened, const OIIO::TypeDesc& type, void* data);

std::vector<std::string> channelNamesOf(const OIIO::ImageSpec& spec);

}  // namespace engine::capture::detail
