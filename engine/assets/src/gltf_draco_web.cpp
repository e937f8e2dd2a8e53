// SPDX-License-Identifier: MIT
// KHR_draco_mesh_compression in the web page's build, which has no Draco library for WebAssembly:
// a Draco-compressed primitive is refused by name (the page's content is generated without
// Draco: game/web). The native decoder is gltf_draco.cpp.
#include "gltf_draco.hpp"

namespace engine::assets::detail {

DracoPrimitive decodeDraco(const LoadContext& ctx, const tinygltf::Model&, const tinygltf::Primitive&, int,
                           const std::string& field) {
    ctx.fail(field, std::string(kDracoExtension) +
                        " compression cannot be read by this build (WebAssembly, no Draco decoder): use content "
                        "generated without Draco");
}

}  // namespace engine::assets::detail
