// SPDX-License-Identifier: MIT
#pragma once
// Private: where a glTF load reports problems. Every refusal names the file and the field
// ("scene.gltf: accessors[3].count: ...") so a user knows what to fix.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "engine/assets/gltf.hpp"

namespace engine::assets::detail {

struct LoadContext {
    std::filesystem::path file;     // as given by the caller
    std::filesystem::path baseDir;  // the directory relative URIs resolve against
    const LoadOptions* options = nullptr;
    std::vector<std::string>* warnings = nullptr;

    // Throws engine::Error("<file>: <field>: <problem>").
    [[noreturn]] void fail(const std::string& field, const std::string& problem) const;
    void warn(const std::string& field, const std::string& problem) const;
};

// "buffers[3]"
inline std::string indexed(const char* array, std::size_t index) {
    return std::string(array) + "[" + std::to_string(index) + "]";
}

// One converted element per element of the glTF array `array` (`sources`), in order:
// `convert(source, field)`, where `field` names the element in errors ("materials[2]").
template <typename Converted, typename Source, typename Convert>
std::vector<Converted> convertEach(const std::vector<Source>& sources, const char* array, Convert&& convert) {
    std::vector<Converted> converted;
    converted.reserve(sources.size());
    for (std::size_t i = 0; i < sources.size(); ++i) converted.push_back(convert(sources[i], indexed(array, i)));
    return converted;
}

// a + b and a * b on 64-bit unsigned values; false on overflow.
inline bool checkedAdd(std::uint64_t a, std::uint64_t b, std::uint64_t& out) {
    return !__builtin_add_overflow(a, b, &out);
}
inline bool checkedMul(std::uint64_t a, std::uint64_t b, std::uint64_t& out) {
    return !__builtin_mul_overflow(a, b, &out);
}

// Reads a whole file, refusing a missing file, a directory and anything over maxBytes
// (before allocating). `field` names what referred to the file ("" for the glTF itself).
std::vector<std::uint8_t> readWholeFile(const LoadContext& ctx, const std::filesystem::path& path,
                                        const std::string& field);

}  // namespace engine::assets::detail
