// SPDX-License-Identifier: MIT
#pragma once
// Private: one place that creates, opens, writes and closes an OpenImageIO output and
// turns each failure into an engine::Error naming the file. The file is written whole or
// not at all (a temporary name, renamed on success).
#include <OpenImageIO/imageio.h>

#include <filesystem>

namespace engine::capture::detail {

// `data` holds spec.width * spec.height * spec.nchannels interleaved values of `dataType`.
void writeWithOiio(const std::filesystem::path& path, const OIIO::ImageSpec& spec, const OIIO::TypeDesc& dataType,
                   const void* data);

// True when OpenImageIO has a writer for `path`'s extension.
bool hasWriterFor(const std::filesystem::path& path);

}  // namespace engine::capture::detail
