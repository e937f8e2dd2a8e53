#include "oiio_output.hpp"

#include "oiio_input.hpp"

namespace engine::capture::detail {

void writeWithOiio(const std::filesystem::path& path, const OIIO::ImageSpec& spec, OIIO::TypeDesc dataType,
                   const void* data) {
    auto out = OIIO::ImageOutput::create(path.string());
    if (!out) throwImageError(path, "no writer for this file type", OIIO::geterror());
    if (!out->open(path.string(), spec)) throwImageError(path, "cannot open for writing", out->geterror());
    if (!out->write_image(dataType, data)) throwImageError(path, "cannot write pixels", out->geterror());
    if (!out->close()) throwImageError(path, "cannot finish writing", out->geterror());
}

}  // namespace engine::capture::detail
