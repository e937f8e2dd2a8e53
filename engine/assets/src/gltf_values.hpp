// SPDX-License-Identifier: MIT
#pragma once
// Private: small checked readers of tinygltf's parsed values, shared by the parts of the
// loader (gltf_loader.cpp, gltf_scene_graph.cpp). Each refuses what it cannot read with
// LoadContext::fail, naming the field.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <tiny_gltf.h>

#include "gltf_context.hpp"

namespace engine::assets::detail {

inline float finite(const LoadContext& ctx, double value, const std::string& field) {
    if (!std::isfinite(value)) ctx.fail(field, std::to_string(value) + " is not a finite number");
    const double limit = static_cast<double>(std::numeric_limits<float>::max());
    if (value > limit || value < -limit) ctx.fail(field, std::to_string(value) + " is out of the float range");
    return static_cast<float>(value);
}

inline bool allFinite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

inline bool allFinite(const glm::mat4& m) {
    const float* values = glm::value_ptr(m);
    return std::all_of(values, values + 16, [](float v) { return std::isfinite(v); });
}

template <int N>
glm::vec<N, float> finiteVector(const LoadContext& ctx, const std::vector<double>& values, const std::string& field) {
    if (values.size() != static_cast<std::size_t>(N))
        ctx.fail(field, "has " + std::to_string(values.size()) + " numbers, expected " + std::to_string(N));
    glm::vec<N, float> out;
    for (int i = 0; i < N; ++i)
        out[i] = finite(ctx, values[static_cast<std::size_t>(i)], indexed(field.c_str(), static_cast<std::size_t>(i)));
    return out;
}

inline void checkIndex(const LoadContext& ctx, int index, std::size_t count, const std::string& field, const char* what,
                       bool optional = true) {
    if (optional && index == -1) return;
    if (index < 0 || static_cast<std::size_t>(index) >= count)
        ctx.fail(field, std::to_string(index) + " is out of range: the file has " + std::to_string(count) + " " + what);
}

inline float valueNumber(const LoadContext& ctx, const tinygltf::Value& value, const std::string& field) {
    if (!value.IsNumber()) ctx.fail(field, "must be a number");
    return finite(ctx, value.GetNumberAsDouble(), field);
}

inline glm::vec2 valueVec2(const LoadContext& ctx, const tinygltf::Value& value, const std::string& field) {
    if (!value.IsArray() || value.ArrayLen() != 2) ctx.fail(field, "must be an array of 2 numbers");
    return {valueNumber(ctx, value.Get(0), field + "[0]"), valueNumber(ctx, value.Get(1), field + "[1]")};
}

}  // namespace engine::assets::detail
