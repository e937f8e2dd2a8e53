// SPDX-License-Identifier: MIT
#include "gltf_accessor.hpp"

#include <algorithm>
#include <concepts>
#include <cstring>
#include <limits>
#include <type_traits>

namespace engine::assets::detail {

const char* componentTypeName(int componentType) {
    switch (componentType) {
        case TINYGLTF_COMPONENT_TYPE_BYTE: return "BYTE";
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return "UNSIGNED_BYTE";
        case TINYGLTF_COMPONENT_TYPE_SHORT: return "SHORT";
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return "UNSIGNED_SHORT";
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: return "UNSIGNED_INT";
        case TINYGLTF_COMPONENT_TYPE_FLOAT: return "FLOAT";
        default: return "unknown";
    }
}

int componentSize(int componentType) {
    switch (componentType) {
        case TINYGLTF_COMPONENT_TYPE_BYTE:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
        case TINYGLTF_COMPONENT_TYPE_SHORT:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
        case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
        default: return 0;  // INT and DOUBLE exist in tinygltf, not in glTF 2.0
    }
}

int componentCount(int type) {
    switch (type) {
        case TINYGLTF_TYPE_SCALAR: return 1;
        case TINYGLTF_TYPE_VEC2: return 2;
        case TINYGLTF_TYPE_VEC3: return 3;
        case TINYGLTF_TYPE_VEC4:
        case TINYGLTF_TYPE_MAT2: return 4;
        case TINYGLTF_TYPE_MAT3: return 9;
        case TINYGLTF_TYPE_MAT4: return 16;
        default: return 0;
    }
}

namespace {

const char* typeName(int type) {
    switch (type) {
        case TINYGLTF_TYPE_SCALAR: return "SCALAR";
        case TINYGLTF_TYPE_VEC2: return "VEC2";
        case TINYGLTF_TYPE_VEC3: return "VEC3";
        case TINYGLTF_TYPE_VEC4: return "VEC4";
        case TINYGLTF_TYPE_MAT2: return "MAT2";
        case TINYGLTF_TYPE_MAT3: return "MAT3";
        case TINYGLTF_TYPE_MAT4: return "MAT4";
        default: return "unknown";
    }
}

template <typename T>
T load(const std::uint8_t* p) {
    T value;
    std::memcpy(&value, p, sizeof value);
    return value;
}

// glTF 2.0 §3.11 "Animations" / KHR_mesh_quantization: normalised signed integers map to
// max(c / MAX, -1), unsigned to c / MAX.
float integerToFloat(std::integral auto c, bool normalized) {
    using Integer = decltype(c);
    const float v = c;
    if (!normalized) return v;
    constexpr float kMax = std::numeric_limits<Integer>::max();
    if constexpr (std::is_signed_v<Integer>) return std::max(v / kMax, -1.0f);
    return v / kMax;
}

float toFloat(const std::uint8_t* p, int componentType, bool normalized) {
    switch (componentType) {
        case TINYGLTF_COMPONENT_TYPE_BYTE: return integerToFloat(load<std::int8_t>(p), normalized);
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return integerToFloat(load<std::uint8_t>(p), normalized);
        case TINYGLTF_COMPONENT_TYPE_SHORT: return integerToFloat(load<std::int16_t>(p), normalized);
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return integerToFloat(load<std::uint16_t>(p), normalized);
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: return static_cast<float>(load<std::uint32_t>(p));
        default: return load<float>(p);
    }
}

std::uint32_t toUint(const std::uint8_t* p, int componentType) {
    switch (componentType) {
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return load<std::uint8_t>(p);
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return load<std::uint16_t>(p);
        default: return load<std::uint32_t>(p);
    }
}

struct Layout {
    const tinygltf::Accessor* accessor = nullptr;
    std::string field;
    const std::uint8_t* base = nullptr;  // null: no bufferView, all zeros
    std::uint64_t stride = 0;
    int components = 0;
    int size = 0;  // of one component
};

Layout checkAccessor(const LoadContext& ctx, const tinygltf::Model& model, int index, const std::string& usage,
                     std::initializer_list<int> types, std::uint32_t componentTypes, std::uint64_t maxCount) {
    if (index < 0 || static_cast<std::size_t>(index) >= model.accessors.size())
        ctx.fail(usage, "accessor " + std::to_string(index) + " is out of range: the file has " +
                            std::to_string(model.accessors.size()) + " accessors");
    Layout layout;
    layout.accessor = &model.accessors[static_cast<std::size_t>(index)];
    layout.field = accessorField(index, usage);
    const tinygltf::Accessor& a = *layout.accessor;
    const std::string& field = layout.field;

    if (std::find(types.begin(), types.end(), a.type) == types.end()) {
        std::string expected;
        for (int t : types) expected += (expected.empty() ? "" : " or ") + std::string(typeName(t));
        ctx.fail(field + ".type", std::string(typeName(a.type)) + ": expected " + expected);
    }
    layout.components = componentCount(a.type);
    layout.size = componentSize(a.componentType);
    if (layout.size == 0)
        ctx.fail(field + ".componentType", std::to_string(a.componentType) + " is not a glTF 2.0 component type");
    if ((componentTypes & componentBit(a.componentType)) == 0)
        ctx.fail(field + ".componentType", std::string(componentTypeName(a.componentType)) + " is not allowed here");
    if (a.normalized &&
        (a.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT || a.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT))
        ctx.fail(field + ".normalized", std::string("true is not allowed for ") + componentTypeName(a.componentType));
    if (a.count == 0) ctx.fail(field + ".count", "0: an accessor must have at least one element");
    if (a.count > maxCount)
        ctx.fail(field + ".count", std::to_string(a.count) + " is over the limit of " + std::to_string(maxCount));

    const std::uint64_t element =
        static_cast<std::uint64_t>(layout.size) * static_cast<std::uint64_t>(layout.components);
    layout.stride = element;
    if (a.bufferView >= 0) {
        if (static_cast<std::size_t>(a.bufferView) >= model.bufferViews.size())
            ctx.fail(field + ".bufferView", std::to_string(a.bufferView) + " is out of range: the file has " +
                                                std::to_string(model.bufferViews.size()) + " bufferViews");
        const tinygltf::BufferView& bv = model.bufferViews[static_cast<std::size_t>(a.bufferView)];
        const std::string viewField = indexed("bufferViews", static_cast<std::size_t>(a.bufferView));
        if (bv.byteStride != 0) {
            if (bv.byteStride < element)
                ctx.fail(viewField + ".byteStride", std::to_string(bv.byteStride) + " is smaller than the " +
                                                        std::to_string(element) + "-byte elements of " + field);
            layout.stride = bv.byteStride;
        }
        if (a.byteOffset % static_cast<std::size_t>(layout.size) != 0 ||
            (bv.byteOffset + a.byteOffset) % static_cast<std::size_t>(layout.size) != 0)
            ctx.fail(field + ".byteOffset", std::to_string(a.byteOffset) + " is not aligned to its " +
                                                std::to_string(layout.size) + "-byte components");
        // byteOffset + (count - 1) * stride + element <= bufferView.byteLength, in 64 bits.
        std::uint64_t span = 0;
        if (!checkedMul(a.count - 1, layout.stride, span) || !checkedAdd(span, element, span) ||
            !checkedAdd(span, a.byteOffset, span) || span > bv.byteLength)
            ctx.fail(field, "byteOffset " + std::to_string(a.byteOffset) + " + (count " + std::to_string(a.count) +
                                " - 1) * stride " + std::to_string(layout.stride) + " + element size " +
                                std::to_string(element) + " exceeds " + viewField + ".byteLength " +
                                std::to_string(bv.byteLength));
        layout.base = bufferViewBytes(ctx, model, a.bufferView, a.byteOffset, span - a.byteOffset, field, nullptr);
    }
    return layout;
}

// Sparse substitution (glTF 2.0 §3.6.2.3): `apply(target, valueBytes)` for each stored index.
template <typename Apply>
void forEachSparse(const LoadContext& ctx, const tinygltf::Model& model, const Layout& layout, Apply apply) {
    const tinygltf::Accessor& a = *layout.accessor;
    if (!a.sparse.isSparse) return;
    const std::string field = layout.field + ".sparse";
    const int count = a.sparse.count;
    if (count < 1 || static_cast<std::size_t>(count) > a.count)
        ctx.fail(field + ".count",
                 std::to_string(count) + ": must be in [1, accessor count " + std::to_string(a.count) + "]");
    const int indexType = a.sparse.indices.componentType;
    if (indexType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE && indexType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
        indexType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
        ctx.fail(field + ".indices.componentType", std::to_string(indexType) + ": must be an unsigned integer type");
    if (a.sparse.indices.byteOffset < 0 || a.sparse.values.byteOffset < 0) ctx.fail(field, "negative byteOffset");
    const std::uint64_t n = static_cast<std::uint64_t>(count);
    const std::uint64_t indexSize = static_cast<std::uint64_t>(componentSize(indexType));
    const std::uint64_t element =
        static_cast<std::uint64_t>(layout.size) * static_cast<std::uint64_t>(layout.components);
    const std::uint8_t* indices = bufferViewBytes(ctx, model, a.sparse.indices.bufferView,
                                                  static_cast<std::uint64_t>(a.sparse.indices.byteOffset),
                                                  n * indexSize, field + ".indices", nullptr);
    const std::uint8_t* values =
        bufferViewBytes(ctx, model, a.sparse.values.bufferView, static_cast<std::uint64_t>(a.sparse.values.byteOffset),
                        n * element, field + ".values", nullptr);
    for (std::uint64_t i = 0; i < n; ++i) {
        const std::uint32_t target = toUint(indices + i * indexSize, indexType);
        if (target >= a.count)
            ctx.fail(field + ".indices", "index " + std::to_string(target) + " at position " + std::to_string(i) +
                                             " is out of range for count " + std::to_string(a.count));
        apply(target, values + i * element);
    }
}

}  // namespace

// The bytes [offset, offset + length) of a bufferView, after checking the view against its
// buffer's actual data. `field` names what refers to the view.
const std::uint8_t* bufferViewBytes(const LoadContext& ctx, const tinygltf::Model& model, int view,
                                    std::uint64_t offset, std::uint64_t length, const std::string& field,
                                    const tinygltf::BufferView** viewOut) {
    if (view < 0 || static_cast<std::size_t>(view) >= model.bufferViews.size())
        ctx.fail(field + ".bufferView", std::to_string(view) + " is out of range: the file has " +
                                            std::to_string(model.bufferViews.size()) + " bufferViews");
    const tinygltf::BufferView& bv = model.bufferViews[static_cast<std::size_t>(view)];
    const std::string viewField = indexed("bufferViews", static_cast<std::size_t>(view));
    if (bv.buffer < 0 || static_cast<std::size_t>(bv.buffer) >= model.buffers.size())
        ctx.fail(viewField + ".buffer", std::to_string(bv.buffer) + " is out of range");
    const auto& data = model.buffers[static_cast<std::size_t>(bv.buffer)].data;
    std::uint64_t viewEnd = 0;
    if (!checkedAdd(bv.byteOffset, bv.byteLength, viewEnd) || viewEnd > data.size())
        ctx.fail(viewField, "byteOffset " + std::to_string(bv.byteOffset) + " + byteLength " +
                                std::to_string(bv.byteLength) + " exceeds the " + std::to_string(data.size()) +
                                " bytes of " + indexed("buffers", static_cast<std::size_t>(bv.buffer)));
    std::uint64_t end = 0;
    if (!checkedAdd(offset, length, end) || end > bv.byteLength)
        ctx.fail(field, "byteOffset " + std::to_string(offset) + " + " + std::to_string(length) + " bytes exceeds " +
                            viewField + ".byteLength " + std::to_string(bv.byteLength));
    if (viewOut) *viewOut = &bv;
    return data.data() + bv.byteOffset + offset;
}

std::string accessorField(int accessor, const std::string& usage) {
    return "accessors[" + std::to_string(accessor) + "] (" + usage + ")";
}

std::vector<float> readFloats(const LoadContext& ctx, const tinygltf::Model& model, int accessor,
                              const AccessorRequest& request) {
    const Layout layout =
        checkAccessor(ctx, model, accessor, request.usage, request.types, request.componentTypes, request.maxCount);
    const tinygltf::Accessor& a = *layout.accessor;
    const std::size_t comps = static_cast<std::size_t>(layout.components);
    std::vector<float> out(a.count * comps, 0.0f);
    if (layout.base) {
        for (std::size_t e = 0; e < a.count; ++e) {
            const std::uint8_t* p = layout.base + e * layout.stride;
            for (std::size_t c = 0; c < comps; ++c)
                out[e * comps + c] =
                    toFloat(p + c * static_cast<std::size_t>(layout.size), a.componentType, a.normalized);
        }
    }
    forEachSparse(ctx, model, layout, [&](std::uint32_t target, const std::uint8_t* p) {
        for (std::size_t c = 0; c < comps; ++c)
            out[target * comps + c] =
                toFloat(p + c * static_cast<std::size_t>(layout.size), a.componentType, a.normalized);
    });
    return out;
}

std::vector<std::uint32_t> readIndices(const LoadContext& ctx, const tinygltf::Model& model, int accessor,
                                       const std::string& usage, std::uint64_t maxCount) {
    const std::uint32_t types = componentBit(TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE) |
                                componentBit(TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT) |
                                componentBit(TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT);
    const Layout layout = checkAccessor(ctx, model, accessor, usage, {TINYGLTF_TYPE_SCALAR}, types, maxCount);
    const tinygltf::Accessor& a = *layout.accessor;
    if (a.normalized) ctx.fail(layout.field + ".normalized", "true is not allowed for indices");
    std::vector<std::uint32_t> out(a.count, 0u);
    if (layout.base)
        for (std::size_t e = 0; e < a.count; ++e) out[e] = toUint(layout.base + e * layout.stride, a.componentType);
    forEachSparse(ctx, model, layout,
                  [&](std::uint32_t target, const std::uint8_t* p) { out[target] = toUint(p, a.componentType); });
    return out;
}

}  // namespace engine::assets::detail
