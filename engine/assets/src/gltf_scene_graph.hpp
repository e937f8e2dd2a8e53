// SPDX-License-Identifier: MIT
#pragma once
// Private: the scene-graph half of a glTF load (gltf_scene_graph.cpp).
#include <vector>

#include <tiny_gltf.h>

#include "engine/assets/gltf.hpp"
#include "gltf_context.hpp"

namespace engine::assets::detail {

std::vector<Camera> convertCameras(const LoadContext& ctx, const tinygltf::Model& model);
std::vector<Node> convertNodes(const LoadContext& ctx, const tinygltf::Model& model);
// Picks LoadOptions::scene, else the file's default scene, else the first (else every root
// node), fills out.sceneRoots and out.sceneNodes (parents first) and out.bounds.
void selectScene(const LoadContext& ctx, const tinygltf::Model& model, LoadedModel& out);

}  // namespace engine::assets::detail
