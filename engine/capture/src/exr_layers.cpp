// SPDX-License-Identifier: MIT
#include "engine/capture/exr_layers.hpp"

#include "engine/capture/image_convert.hpp"
#include "oiio_input.hpp"
#include "oiio_output.hpp"

#include <algorithm>
#include <set>

namespace engine::capture {
namespace {

// "diffuse.direct.R" -> {"diffuse.direct", "R"}; "R" -> {"", "R"}.
std::pair<std::string, std::string> splitChannelName(const std::string& channel) {
    const auto dot = channel.rfind('.');
    if (dot == std::string::npos) return {"", channel};
    return {channel.substr(0, dot), channel.substr(dot + 1)};
}

void checkLayers(const std::filesystem::path& path, const std::vector<Layer>& layers) {
    if (layers.empty()) detail::throwImageError(path, "no layers to write");
    std::set<std::string> seen;
    const Image& first = layers.front().image;
    for (const Layer& layer : layers) {
        const std::string label = "layer '" + layer.name + "'";
        if (layer.name.empty() && layers.size() > 1)
            detail::throwImageError(path, "every layer of a multi-layer EXR needs a name");
        if (!seen.insert(layer.name).second) detail::throwImageError(path, label + " appears twice");
        if (layer.image.empty()) detail::throwImageError(path, label + " is an empty image");
        if (layer.image.width != first.width || layer.image.height != first.height)
            detail::throwImageError(path, label + " is " + std::to_string(layer.image.width) + "x" +
                                              std::to_string(layer.image.height) + ", other layers are " +
                                              std::to_string(first.width) + "x" + std::to_string(first.height));
        if (layer.image.channelNames.size() != static_cast<std::size_t>(layer.image.channels))
            detail::throwImageError(path, label + " has " + std::to_string(layer.image.channelNames.size()) +
                                              " channel names for " + std::to_string(layer.image.channels) +
                                              " channels");
    }
}

OIIO::TypeDesc oiioType(ExrPixelType type) {
    return type == ExrPixelType::Half ? OIIO::TypeDesc::HALF : OIIO::TypeDesc::FLOAT;
}

std::vector<std::string> layerNamesOf(const std::vector<std::string>& channelNames) {
    std::vector<std::string> layers;
    for (const std::string& channel : channelNames) {
        std::string layer = splitChannelName(channel).first;
        if (std::find(layers.begin(), layers.end(), layer) == layers.end()) layers.push_back(std::move(layer));
    }
    return layers;
}

void requireExr(const std::filesystem::path& path, const detail::OpenedImage& opened) {
    const std::string format = opened.input->format_name();
    if (format != "openexr") detail::throwImageError(path, "is a " + format + " file, not an EXR with layers");
}

}  // namespace

void writeExrLayers(const std::filesystem::path& path, const std::vector<Layer>& layers) {
    checkLayers(path, layers);
    const int width = layers.front().image.width;
    const int height = layers.front().image.height;

    // Gather the layers' channels into one interleaved float buffer, prefixing names.
    std::vector<std::string> names;
    std::vector<OIIO::TypeDesc> formats;
    std::vector<Image> premultipliedLayers;
    premultipliedLayers.reserve(layers.size());
    for (const Layer& layer : layers) {
        Image copy = layer.image;
        premultiply(copy);
        for (const std::string& channel : copy.channelNames) {
            names.push_back(layer.name.empty() ? channel : layer.name + "." + channel);
            formats.push_back(oiioType(layer.pixelType));
        }
        premultipliedLayers.push_back(std::move(copy));
    }
    const auto total = names.size();
    std::vector<float> pixels(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * total);
    std::size_t offset = 0;
    for (const Image& image : premultipliedLayers) {
        const auto channels = static_cast<std::size_t>(image.channels);
        for (std::size_t p = 0; p < image.pixelCount(); ++p)
            std::copy_n(image.pixels.begin() + static_cast<std::ptrdiff_t>(p * channels), channels,
                        pixels.begin() + static_cast<std::ptrdiff_t>(p * total + offset));
        offset += channels;
    }

    const bool mixed = std::any_of(formats.begin(), formats.end(), [&](auto f) { return f != formats.front(); });
    OIIO::ImageSpec spec(width, height, static_cast<int>(total), mixed ? OIIO::TypeDesc::FLOAT : formats.front());
    spec.channelnames = names;
    if (mixed) spec.channelformats = formats;
    // ImageSpec guessed alpha from the channel count; only a plain single-layer file has one.
    spec.alpha_channel = layers.size() == 1 ? findAlphaChannel(names) : -1;
    spec.z_channel = -1;
    detail::writeWithOiio(path, spec, OIIO::TypeDesc::FLOAT, pixels.data());
}

std::vector<std::string> listExrLayers(const std::filesystem::path& path, const ReadOptions& options) {
    detail::OpenedImage opened = detail::openImage(path, options, sizeof(float));
    requireExr(path, opened);
    return layerNamesOf(detail::channelNamesOf(opened.spec));
}

Image readExrLayer(const std::filesystem::path& path, std::string_view layer, const ReadOptions& options) {
    detail::OpenedImage opened = detail::openImage(path, options, sizeof(float));
    requireExr(path, opened);
    const std::vector<std::string> fileChannels = detail::channelNamesOf(opened.spec);

    std::vector<int> picked;
    std::vector<std::string> shortNames;
    for (std::size_t c = 0; c < fileChannels.size(); ++c) {
        auto [layerName, shortName] = splitChannelName(fileChannels[c]);
        if (layerName != layer) continue;
        picked.push_back(static_cast<int>(c));
        shortNames.push_back(std::move(shortName));
    }
    if (picked.empty()) {
        std::string available;
        for (const std::string& name : layerNamesOf(fileChannels))
            available += (available.empty() ? "'" : ", '") + name + "'";
        detail::throwImageError(path, "has no layer '" + std::string(layer) + "' (layers: " + available + ")");
    }

    // Read everything once (the cap was checked against the whole file), then pick the layer.
    const OIIO::ImageSpec& spec = opened.spec;
    std::vector<float> all(static_cast<std::size_t>(spec.width) * static_cast<std::size_t>(spec.height) *
                           fileChannels.size());
    detail::readPixels(path, opened, OIIO::TypeDesc::FLOAT, all.data());

    Image image = Image::make(spec.width, spec.height, std::move(shortNames), AlphaMode::Premultiplied);
    const auto fileStride = fileChannels.size();
    const auto channels = picked.size();
    for (std::size_t p = 0; p < image.pixelCount(); ++p)
        for (std::size_t c = 0; c < channels; ++c)
            image.pixels[p * channels + c] = all[p * fileStride + static_cast<std::size_t>(picked[c])];
    return image;
}

}  // namespace engine::capture
