// SPDX-License-Identifier: MIT
#include "gltf_draco.hpp"

#include <limits>

#include <draco/compression/decode.h>
#include <draco/core/decoder_buffer.h>

#include "gltf_accessor.hpp"

namespace engine::assets::detail {

namespace {

int integerValue(const tinygltf::Value& value) {
    if (value.IsInt()) return value.Get<int>();
    return -1;
}

// glTF normalisation of an integer that Draco stored without its normalised flag.
float normalizationScale(int componentType) {
    switch (componentType) {
        case TINYGLTF_COMPONENT_TYPE_BYTE: return 1.0f / 127.0f;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1.0f / 255.0f;
        case TINYGLTF_COMPONENT_TYPE_SHORT: return 1.0f / 32767.0f;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 1.0f / 65535.0f;
        default: return 1.0f;
    }
}

bool isIntegral(draco::DataType type) {
    return type != draco::DT_FLOAT32 && type != draco::DT_FLOAT64 && type != draco::DT_BOOL &&
           type != draco::DT_INVALID;
}

}  // namespace

DracoPrimitive decodeDraco(const LoadContext& ctx, const tinygltf::Model& model, const tinygltf::Primitive& primitive,
                           int indicesAccessor, const std::string& field) {
    const std::string ext = field + ".extensions." + kDracoExtension;
    const tinygltf::Value& value = primitive.extensions.at(kDracoExtension);
    if (!value.IsObject()) ctx.fail(ext, "must be an object");
    const int view = integerValue(value.Get("bufferView"));
    if (view < 0 || static_cast<std::size_t>(view) >= model.bufferViews.size())
        ctx.fail(ext + ".bufferView", "missing or out of range");
    const std::uint64_t length = model.bufferViews[static_cast<std::size_t>(view)].byteLength;
    const std::uint8_t* data = bufferViewBytes(ctx, model, view, 0, length, ext, nullptr);

    draco::DecoderBuffer buffer;
    buffer.Init(reinterpret_cast<const char*>(data), static_cast<std::size_t>(length));
    auto geometry = draco::Decoder::GetEncodedGeometryType(&buffer);
    if (!geometry.ok()) ctx.fail(ext, "not Draco data: " + geometry.status().error_msg_string());
    if (geometry.value() != draco::TRIANGULAR_MESH) ctx.fail(ext, "the Draco data is not a triangle mesh");
    draco::Decoder decoder;
    auto decoded = decoder.DecodeMeshFromBuffer(&buffer);
    if (!decoded.ok()) ctx.fail(ext, "Draco decoding failed: " + decoded.status().error_msg_string());
    const draco::Mesh& mesh = *decoded.value();

    DracoPrimitive out;
    out.vertexCount = mesh.num_points();
    const std::uint64_t maxVertices = ctx.options->maxVertices;
    if (out.vertexCount > maxVertices)
        ctx.fail(ext, "Draco decoded " + std::to_string(out.vertexCount) + " vertices, over the limit of " +
                          std::to_string(maxVertices));

    out.indices.reserve(static_cast<std::size_t>(mesh.num_faces()) * 3);
    for (draco::FaceIndex f(0); f < mesh.num_faces(); ++f)
        for (int corner = 0; corner < 3; ++corner) {
            const std::uint32_t index = mesh.face(f)[corner].value();
            if (index >= out.vertexCount)
                ctx.fail(ext, "Draco face " + std::to_string(f.value()) + " refers to vertex " + std::to_string(index) +
                                  " of " + std::to_string(out.vertexCount));
            out.indices.push_back(index);
        }
    if (indicesAccessor >= 0) {
        if (static_cast<std::size_t>(indicesAccessor) >= model.accessors.size())
            ctx.fail(field + ".indices", std::to_string(indicesAccessor) + " is out of range");
        const std::size_t declared = model.accessors[static_cast<std::size_t>(indicesAccessor)].count;
        if (declared != out.indices.size())
            ctx.fail(accessorField(indicesAccessor, field + ".indices") + ".count",
                     std::to_string(declared) + " does not match the " + std::to_string(out.indices.size()) +
                         " indices Draco decoded (count mismatch)");
    }

    const tinygltf::Value& attributes = value.Get("attributes");
    if (!attributes.IsObject()) ctx.fail(ext + ".attributes", "must be an object");
    for (const std::string& name : attributes.Keys()) {
        const std::string attrField = ext + ".attributes." + name;
        const int id = integerValue(attributes.Get(name));
        if (id < 0) ctx.fail(attrField, "must be a non-negative integer");
        const auto accessorIt = primitive.attributes.find(name);
        if (accessorIt == primitive.attributes.end())
            ctx.fail(attrField, "the primitive has no attribute '" + name + "' for it to decode into");
        const int accessorIndex = accessorIt->second;
        if (accessorIndex < 0 || static_cast<std::size_t>(accessorIndex) >= model.accessors.size())
            ctx.fail(field + ".attributes." + name, std::to_string(accessorIndex) + " is out of range");
        const tinygltf::Accessor& accessor = model.accessors[static_cast<std::size_t>(accessorIndex)];
        const std::string accField = accessorField(accessorIndex, field + ".attributes." + name);

        const draco::PointAttribute* attribute = mesh.GetAttributeByUniqueId(static_cast<std::uint32_t>(id));
        if (!attribute) ctx.fail(attrField, "the Draco data has no attribute with id " + std::to_string(id));
        const int components = componentCount(accessor.type);
        if (components == 0 || attribute->num_components() != components)
            ctx.fail(accField + ".type", "declares " + std::to_string(components) + " components, Draco decoded " +
                                             std::to_string(attribute->num_components()));
        if (accessor.count != out.vertexCount)
            ctx.fail(accField + ".count", std::to_string(accessor.count) + " does not match the " +
                                              std::to_string(out.vertexCount) +
                                              " vertices Draco decoded (count mismatch)");

        std::vector<float> values(out.vertexCount * static_cast<std::size_t>(components));
        const float scale = accessor.normalized && !attribute->normalized() && isIntegral(attribute->data_type())
                                ? normalizationScale(accessor.componentType)
                                : 1.0f;
        for (std::size_t i = 0; i < out.vertexCount; ++i) {
            const draco::AttributeValueIndex mapped =
                attribute->mapped_index(draco::PointIndex(static_cast<std::uint32_t>(i)));
            float* dst = values.data() + i * static_cast<std::size_t>(components);
            if (mapped.value() >= attribute->size() ||
                !attribute->ConvertValue<float>(mapped, static_cast<std::int8_t>(components), dst))
                ctx.fail(attrField, "Draco value of vertex " + std::to_string(i) + " cannot be read");
            for (int c = 0; c < components; ++c) dst[c] *= scale;
        }
        out.attributes.emplace(name, std::move(values));
    }
    return out;
}

}  // namespace engine::assets::detail
