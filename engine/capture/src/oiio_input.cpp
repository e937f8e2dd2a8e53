// SPDX-License-Identifier: MIT
#include "oiio_input.hpp"

#include "engine/capture/jpeg_metadata.hpp"
#include "exr_header_sizes.hpp"
#include "engine/core/error.hpp"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <initializer_list>
#include <limits>
#include <system_error>

namespace engine::capture::detail {
namespace {

std::string lowercase(std::string text) {
    std::transform(text.begin(), text.end(), text.begin(),
                   [](unsigned char ch) { return static_cast<char>(std::tolower(ch)); });
    return text;
}

// Integer formats are sRGB unless the file itself says its values are linear
// (a PNG gAMA of 1.0, for instance, makes OpenImageIO report "linear").
// Only 8- and 16-bit unsigned data is ever colour-encoded; wider integers (EXR UINT ids)
// and floats are taken as they are.
bool isSrgbEncoded(const OIIO::ImageSpec& spec) {
    if (spec.format != OIIO::TypeDesc::UINT8 && spec.format != OIIO::TypeDesc::UINT16) return false;
    const std::string space = lowercase(spec.get_string_attribute("oiio:ColorSpace"));
    return space.find("linear") == std::string::npos && space != "lin_srgb" && space != "raw";
}

// Formats whose files store straight colour; we ask OpenImageIO to leave it that way.
bool storesStraightAlpha(const std::string& formatName) {
    return formatName == "png" || formatName == "targa" || formatName == "jpeg";
}

// a * b * c * d without overflow: saturates at the maximum, which any cap then refuses.
std::uint64_t saturatingProduct(std::initializer_list<std::uint64_t> factors) {
    std::uint64_t product = 1;
    for (std::uint64_t f : factors) {
        if (f != 0 && product > std::numeric_limits<std::uint64_t>::max() / f)
            return std::numeric_limits<std::uint64_t>::max();
        product *= f;
    }
    return product;
}

void checkLimits(const std::filesystem::path& path, const OIIO::ImageSpec& spec, const ReadOptions& options,
                 std::size_t bytesPerValue) {
    const std::string size = std::to_string(spec.width) + "x" + std::to_string(spec.height);
    if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0)
        throwImageError(path, "zero-size image (" + size + ", " + std::to_string(spec.nchannels) + " channels)");
    if (spec.depth > 1)
        throwImageError(path, "volume images (depth " + std::to_string(spec.depth) + ") are not supported");
    if (spec.deep) throwImageError(path, "deep images are not supported");
    if (spec.width > options.maxWidth || spec.height > options.maxHeight)
        throwImageError(path, "image is " + size + ", over the size cap of " + std::to_string(options.maxWidth) + "x" +
                                  std::to_string(options.maxHeight));
    const std::uint64_t bytes =
        saturatingProduct({static_cast<std::uint64_t>(spec.width), static_cast<std::uint64_t>(spec.height),
                           static_cast<std::uint64_t>(spec.nchannels), bytesPerValue});
    if (bytes > options.maxDecodedBytes)
        throwImageError(path, "image is " + size + "x" + std::to_string(spec.nchannels) + " channels, " +
                                  std::to_string(bytes) + " bytes decoded, over the cap of " +
                                  std::to_string(options.maxDecodedBytes) + " bytes");
}

// The file's bytes when it is a JPEG (within the cap), else empty.
std::vector<std::uint8_t> jpegBytesOf(const std::filesystem::path& path, const ReadOptions& options) {
    std::ifstream in(path, std::ios::binary);
    std::uint8_t magic[3] = {};
    if (!in.read(reinterpret_cast<char*>(magic), sizeof magic) || !isJpeg(magic)) return {};
    std::error_code ec;
    const std::uintmax_t size = std::filesystem::file_size(path, ec);
    if (ec) throwImageError(path, "cannot read the file size: " + ec.message());
    if (size > options.maxDecodedBytes)
        throwImageError(path, "JPEG file of " + std::to_string(size) + " bytes, over the cap of " +
                                  std::to_string(options.maxDecodedBytes) + " bytes");
    std::vector<std::uint8_t> bytes(static_cast<std::size_t>(size));
    in.seekg(0);
    if (!in.read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(bytes.size())))
        throwImageError(path, "cannot read the file");
    return withoutJpegMetadata(bytes);
}

}  // namespace

void throwImageError(const std::filesystem::path& path, const std::string& what, const std::string& oiioMessage) {
    std::string message = "image '" + path.string() + "': " + what;
    // OpenImageIO's text may span lines and end in a newline; keep our message one block.
    std::string detail = oiioMessage;
    while (!detail.empty() && std::isspace(static_cast<unsigned char>(detail.back()))) detail.pop_back();
    if (!detail.empty()) message += ": " + detail;
    throw Error(message);
}

std::vector<std::string> channelNamesOf(const OIIO::ImageSpec& spec) {
    std::vector<std::string> names = spec.channelnames;
    const auto fallback = defaultChannelNames(spec.nchannels);
    names.resize(static_cast<std::size_t>(spec.nchannels));
    for (std::size_t c = 0; c < names.size(); ++c)
        if (names[c].empty()) names[c] = fallback[c];
    return names;
}

OpenedImage openImage(const std::filesystem::path& path, const ReadOptions& options, std::size_t bytesPerValue) {
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) throwImageError(path, "file does not exist");
    if (std::filesystem::is_directory(path, ec)) throwImageError(path, "is a directory, not an image file");

    // By default OpenImageIO premultiplies PNG/TGA alpha on read; this hint keeps the stored
    // straight colour, which is what we report and what a pixel with alpha 0 needs.
    OIIO::ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);

    OpenedImage opened;
    opened.jpegBytes = jpegBytesOf(path, options);
    if (!opened.jpegBytes.empty()) {
        opened.jpegReader =
            std::make_unique<OIIO::Filesystem::IOMemReader>(opened.jpegBytes.data(), opened.jpegBytes.size());
        // OpenImageIO 2.4 takes the proxy from the config once a config is given.
        void* proxy = opened.jpegReader.get();
        config.attribute("oiio:ioproxy", OIIO::TypeDesc::PTR, &proxy);
    }
    {
        std::ifstream exr(path, std::ios::binary);
        const std::string oversized = oversizedExrAttribute(exr, std::filesystem::file_size(path, ec));
        if (!oversized.empty()) throwImageError(path, "corrupt EXR: " + oversized);
    }
    opened.input = OIIO::ImageInput::open(path.string(), &config);
    if (!opened.input) throwImageError(path, "cannot open as an image", OIIO::geterror());
    opened.spec = opened.input->spec();
    checkLimits(path, opened.spec, options, bytesPerValue);

    const std::string format = opened.input->format_name();
    const bool straight =
        opened.spec.get_int_attribute("oiio:UnassociatedAlpha", 0) != 0 || storesStraightAlpha(format);
    opened.alpha = straight ? AlphaMode::Straight : AlphaMode::Premultiplied;
    opened.srgbEncoded = isSrgbEncoded(opened.spec);
    return opened;
}

void readPixels(const std::filesystem::path& path, OpenedImage& opened, const OIIO::TypeDesc& type, void* data) {
    if (!opened.input->read_image(0, 0, 0, opened.spec.nchannels, type, data)) {
        std::string message = opened.input->geterror();
        if (message.empty()) message = OIIO::geterror();
        throwImageError(path, "cannot read pixels (truncated or corrupt file?)", message);
    }
}

}  // namespace engine::capture::detail
