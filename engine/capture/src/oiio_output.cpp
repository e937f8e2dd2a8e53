// SPDX-License-Identifier: MIT
#include "oiio_output.hpp"

#include "engine/core/output_file.hpp"
#include "oiio_input.hpp"

namespace engine::capture::detail {

void writeWithOiio(const std::filesystem::path& path, const OIIO::ImageSpec& spec, const OIIO::TypeDesc& dataType,
                   const void* data) {
    // The writer is chosen by the target's name; the pixels go to a temporary file beside it
    // that replaces the target only once closed, so a failed write leaves no partial image
    // (engine/core/output_file.hpp).
    auto out = OIIO::ImageOutput::create(path.string());
    if (!out) throwImageError(path, "no writer for this file type", OIIO::geterror());
    PendingFile file(path);
    if (!out->open(file.path().string(), spec)) throwImageError(path, "cannot open for writing", out->geterror());
    if (!out->write_image(dataType, data)) throwImageError(path, "cannot write pixels", out->geterror());
    if (!out->close()) throwImageError(path, "cannot finish writing", out->geterror());
    file.commit();
}

bool hasWriterFor(const std::filesystem::path& path) {
    const bool found = OIIO::ImageOutput::create(path.string()) != nullptr;
    if (!found) OIIO::geterror();  // clear the message of the failed lookup
    return found;
}

}  // namespace engine::capture::detail
