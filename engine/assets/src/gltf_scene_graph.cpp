// SPDX-License-Identifier: MIT
// glTF 2.0 cameras, the node hierarchy (world transforms; no cycles, no shared children) and
// the scene a load shows, with the world-space bounds of what it shows.
#include "gltf_scene_graph.hpp"

#include <string>
#include <vector>

#include <glm/gtc/quaternion.hpp>

#include "gltf_values.hpp"

namespace engine::assets::detail {
namespace {

glm::mat4 localTransform(const LoadContext& ctx, const tinygltf::Node& node, const std::string& field) {
    if (!node.matrix.empty()) {
        if (node.matrix.size() != 16) ctx.fail(field + ".matrix", "must have 16 numbers");
        glm::mat4 m;
        for (int i = 0; i < 16; ++i)  // column-major, as glTF stores it
            glm::value_ptr(m)[i] =
                finite(ctx, node.matrix[static_cast<std::size_t>(i)], field + ".matrix[" + std::to_string(i) + "]");
        return m;
    }
    glm::mat4 m(1.0f);
    if (!node.translation.empty()) {
        const glm::vec3 t = finiteVector<3>(ctx, node.translation, field + ".translation");
        m[3] = glm::vec4(t, 1.0f);
    }
    if (!node.rotation.empty()) {
        const glm::vec4 q = finiteVector<4>(ctx, node.rotation, field + ".rotation");  // x, y, z, w
        // In double: the squares of components near FLT_MAX overflow a float, and a length of
        // infinity would silently turn the rotation into the identity.
        const double length = glm::length(glm::dvec4(q));
        if (!(length > 1e-6)) ctx.fail(field + ".rotation", "is not a unit quaternion");
        const glm::dvec4 unit = glm::dvec4(q) / length;
        m = m * glm::mat4_cast(glm::quat(static_cast<float>(unit.w), static_cast<float>(unit.x),
                                         static_cast<float>(unit.y), static_cast<float>(unit.z)));
    }
    if (!node.scale.empty()) {
        const glm::vec3 s = finiteVector<3>(ctx, node.scale, field + ".scale");
        m = m *
            glm::mat4(glm::vec4(s.x, 0, 0, 0), glm::vec4(0, s.y, 0, 0), glm::vec4(0, 0, s.z, 0), glm::vec4(0, 0, 0, 1));
    }
    return m;
}

}  // namespace

std::vector<Camera> convertCameras(const LoadContext& ctx, const tinygltf::Model& model) {
    return convertEach<Camera>(model.cameras, "cameras", [&](const tinygltf::Camera& source, const std::string& field) {
        Camera c;
        c.name = source.name;
        if (source.type == "perspective") {
            const auto& p = source.perspective;
            const std::string pf = field + ".perspective";
            c.type = Camera::Type::Perspective;
            c.yfov = finite(ctx, p.yfov, pf + ".yfov");
            if (c.yfov <= 0.0f || c.yfov >= 3.14159265f)
                ctx.fail(pf + ".yfov", std::to_string(c.yfov) + ": must be in (0, pi)");
            c.aspectRatio = finite(ctx, p.aspectRatio, pf + ".aspectRatio");
            if (c.aspectRatio < 0.0f) ctx.fail(pf + ".aspectRatio", std::to_string(c.aspectRatio) + ": must be > 0");
            c.znear = finite(ctx, p.znear, pf + ".znear");
            if (c.znear <= 0.0f) ctx.fail(pf + ".znear", std::to_string(c.znear) + ": must be > 0");
            if (p.zfar != 0.0) {  // tinygltf's 0: absent, an infinite projection
                c.zfar = finite(ctx, p.zfar, pf + ".zfar");
                if (c.zfar <= c.znear) ctx.fail(pf + ".zfar", std::to_string(c.zfar) + ": must be greater than znear");
            }
        } else if (source.type == "orthographic") {
            const auto& o = source.orthographic;
            const std::string of = field + ".orthographic";
            c.type = Camera::Type::Orthographic;
            c.xmag = finite(ctx, o.xmag, of + ".xmag");
            c.ymag = finite(ctx, o.ymag, of + ".ymag");
            if (c.xmag == 0.0f || c.ymag == 0.0f) ctx.fail(of, "xmag and ymag must not be zero");
            c.znear = finite(ctx, o.znear, of + ".znear");
            c.zfar = finite(ctx, o.zfar, of + ".zfar");
            if (c.znear < 0.0f) ctx.fail(of + ".znear", std::to_string(c.znear) + ": must be >= 0");
            if (c.zfar <= c.znear) ctx.fail(of + ".zfar", std::to_string(c.zfar) + ": must be greater than znear");
        } else {
            ctx.fail(field + ".type", "'" + source.type + "': must be perspective or orthographic");
        }
        return c;
    });
}

std::vector<Node> convertNodes(const LoadContext& ctx, const tinygltf::Model& model) {
    const std::size_t count = model.nodes.size();
    std::vector<Node> nodes =
        convertEach<Node>(model.nodes, "nodes", [&](const tinygltf::Node& source, const std::string& field) {
            Node node;
            node.name = source.name;
            checkIndex(ctx, source.mesh, model.meshes.size(), field + ".mesh", "meshes");
            checkIndex(ctx, source.camera, model.cameras.size(), field + ".camera", "cameras");
            node.mesh = source.mesh;
            node.camera = source.camera;
            node.local = localTransform(ctx, source, field);
            node.children = source.children;
            return node;
        });
    // glTF 2.0 §3.5.3: the nodes form disjoint strict trees: every node has at most one
    // parent and there are no cycles.
    for (std::size_t i = 0; i < count; ++i)
        for (std::size_t c = 0; c < nodes[i].children.size(); ++c) {
            const int child = nodes[i].children[c];
            const std::string field = indexed("nodes", i) + "." + indexed("children", c);
            checkIndex(ctx, child, count, field, "nodes", false);
            Node& childNode = nodes[static_cast<std::size_t>(child)];
            if (childNode.parent != -1)
                ctx.fail(field, "node " + std::to_string(child) + " already has parent node " +
                                    std::to_string(childNode.parent) + " (nodes must form trees)");
            childNode.parent = static_cast<int>(i);
        }
    // World transforms from the roots down; a node never reached is on a cycle.
    std::vector<bool> reached(count, false);
    std::vector<int> stack;
    for (std::size_t i = 0; i < count; ++i)
        if (nodes[i].parent == -1) stack.push_back(static_cast<int>(i));
    while (!stack.empty()) {
        const auto n = static_cast<std::size_t>(stack.back());
        stack.pop_back();
        reached[n] = true;
        nodes[n].world = nodes[n].parent == -1
                             ? nodes[n].local
                             : nodes[static_cast<std::size_t>(nodes[n].parent)].world * nodes[n].local;
        // Finite local transforms can multiply to infinity (two nested scales of 1e30).
        if (!allFinite(nodes[n].world))
            ctx.fail(indexed("nodes", n),
                     "the world transform (the parents' transforms times this node's) "
                     "overflows the float range");
        for (int child : nodes[n].children) stack.push_back(child);
    }
    for (std::size_t i = 0; i < count; ++i)
        if (!reached[i]) ctx.fail(indexed("nodes", i), "is part of a cycle in the node hierarchy");
    return nodes;
}

void selectScene(const LoadContext& ctx, const tinygltf::Model& model, LoadedModel& out) {
    const int requested = ctx.options->scene;
    if (requested >= 0) {
        if (static_cast<std::size_t>(requested) >= model.scenes.size())
            ctx.fail("scene",
                     "LoadOptions::scene " + std::to_string(requested) + " is out of range: the file has " +
                         std::to_string(model.scenes.size()) + " scenes" +
                         (model.scenes.empty() ? std::string(" (it has none to choose)")
                                               : " (valid: 0.." + std::to_string(model.scenes.size() - 1) + ")"));
        out.scene = requested;
    } else if (model.defaultScene >= 0) {
        checkIndex(ctx, model.defaultScene, model.scenes.size(), "scene", "scenes", false);
        out.scene = model.defaultScene;
    } else if (!model.scenes.empty()) {
        out.scene = 0;
    }
    if (out.scene >= 0) {
        const tinygltf::Scene& scene = model.scenes[static_cast<std::size_t>(out.scene)];
        std::vector<bool> seen(out.nodes.size(), false);
        for (std::size_t k = 0; k < scene.nodes.size(); ++k) {
            const int node = scene.nodes[k];
            const std::string field =
                indexed("scenes", static_cast<std::size_t>(out.scene)) + "." + indexed("nodes", k);
            checkIndex(ctx, node, out.nodes.size(), field, "nodes", false);
            if (out.nodes[static_cast<std::size_t>(node)].parent != -1)
                ctx.fail(field, "node " + std::to_string(node) + " is not a root node");
            if (seen[static_cast<std::size_t>(node)])
                ctx.fail(field, "node " + std::to_string(node) + " is listed twice");
            seen[static_cast<std::size_t>(node)] = true;
            out.sceneRoots.push_back(node);
        }
    } else {
        for (std::size_t i = 0; i < out.nodes.size(); ++i)
            if (out.nodes[i].parent == -1) out.sceneRoots.push_back(static_cast<int>(i));
    }
    // Depth-first, parents before children, in file order.
    std::vector<int> stack(out.sceneRoots.rbegin(), out.sceneRoots.rend());
    while (!stack.empty()) {
        const int n = stack.back();
        stack.pop_back();
        out.sceneNodes.push_back(n);
        const auto& children = out.nodes[static_cast<std::size_t>(n)].children;
        stack.insert(stack.end(), children.rbegin(), children.rend());
    }
    for (int n : out.sceneNodes) {
        const Node& node = out.nodes[static_cast<std::size_t>(n)];
        if (node.mesh < 0) continue;
        for (const Primitive& primitive : out.meshes[static_cast<std::size_t>(node.mesh)].primitives)
            out.bounds.add(primitive.bounds, node.world);
        if (!out.bounds.empty() && !(allFinite(out.bounds.min) && allFinite(out.bounds.max)))
            ctx.fail(indexed("nodes", static_cast<std::size_t>(n)) + ".mesh",
                     "the mesh's bounds in world space overflow the float range");
    }
}

}  // namespace engine::assets::detail
