// SPDX-License-Identifier: MIT
// Building the frame graph: declaring passes and textures, checking each declaration as it
// is made, and the queries on the result. compile(), execute() and dumpGraphviz() live in
// frame_graph_compile.cpp, frame_graph_execute.cpp and frame_graph_graphviz.cpp.
#include "engine/render/frame_graph.hpp"

#include "engine/core/error.hpp"

#include <algorithm>
#include <string>

namespace engine::render {

using namespace frame_graph_detail;  // the graph's nodes (frame_graph/graph_nodes.hpp)

namespace {

// Appended piece by piece: GCC 12 raises a false -Wrestrict at -O3 on "'" + std::string
// (GCC bug 105329).
std::string quoted(std::string_view text) {
    std::string out;
    out.reserve(text.size() + 2);
    out += '\'';
    out += text;
    out += '\'';
    return out;
}

}  // namespace

FrameGraph::FrameGraph() = default;
FrameGraph::~FrameGraph() = default;
FrameGraph::FrameGraph(FrameGraph&&) noexcept = default;
FrameGraph& FrameGraph::operator=(FrameGraph&&) noexcept = default;

void FrameGraph::requireNotCompiled(std::string_view what) const {
    if (compiled_) throw Error("frame graph: cannot " + std::string(what) + " after compile()");
}

void FrameGraph::requireCompiled(std::string_view what) const {
    if (!compiled_) throw Error("frame graph: " + std::string(what) + " is only known after compile()");
}

FrameGraph::DeclarationMark FrameGraph::beginPass(std::string name,
                                                  std::unique_ptr<frame_graph_detail::PassExecutor> executor) {
    requireNotCompiled("add pass " + quoted(name));
    if (name.empty()) throw Error("frame graph: a pass needs a name");
    const bool taken = std::any_of(passes_.begin(), passes_.end(), [&](const PassNode& p) { return p.name == name; });
    if (taken) throw Error("frame graph: there is already a pass named " + quoted(name));

    const DeclarationMark mark{static_cast<std::uint32_t>(passes_.size()), resources_.size(), nodes_.size()};
    PassNode pass;
    pass.name = std::move(name);
    pass.executor = std::move(executor);
    passes_.push_back(std::move(pass));
    return mark;
}

void FrameGraph::rollBack(const DeclarationMark& mark) {
    // Reads only append to the failing pass itself, so dropping it, the textures it
    // created and the versions it wrote restores everything.
    passes_.resize(mark.pass);
    resources_.resize(mark.resourceCount);
    nodes_.resize(mark.nodeCount);
    for (VirtualResource& resource : resources_) {
        while (!resource.versions.empty() && resource.versions.back() >= mark.nodeCount) resource.versions.pop_back();
    }
}

FrameGraphTexture FrameGraph::importTexture(std::string name, const FrameGraphTextureDesc& desc,
                                            ConcreteTexture texture) {
    requireNotCompiled("import " + quoted(name));
    const auto index = static_cast<std::uint32_t>(resources_.size());
    VirtualResource resource;
    resource.name = std::move(name);
    resource.desc = desc;
    resource.imported = true;
    resource.importedTexture = texture;
    resource.versions.push_back(static_cast<std::uint32_t>(nodes_.size()));
    resources_.push_back(std::move(resource));
    nodes_.push_back(VersionNode{.resource = index, .version = 0});
    return handle(index, 0);
}

FrameGraphTexture FrameGraph::createTexture(std::string name, const FrameGraphTextureDesc& desc) {
    const auto index = static_cast<std::uint32_t>(resources_.size());
    VirtualResource resource;
    resource.name = std::move(name);
    resource.desc = desc;
    resource.versions.push_back(static_cast<std::uint32_t>(nodes_.size()));
    resources_.push_back(std::move(resource));
    nodes_.push_back(VersionNode{.resource = index, .version = 0});
    return handle(index, 0);
}

const VirtualResource& FrameGraph::resource(FrameGraphTexture texture, std::string_view who) const {
    if (!texture.isValid()) {
        throw Error("frame graph: " + std::string(who) + " used an invalid (default) texture handle");
    }
    if (texture.resource() >= resources_.size()) {
        throw Error("frame graph: " + std::string(who) + " used texture #" + std::to_string(texture.resource()) +
                    ", which this graph does not have");
    }
    return resources_[texture.resource()];
}

std::uint32_t FrameGraph::versionNode(FrameGraphTexture texture, std::string_view who, std::string_view verb) const {
    const VirtualResource& res = resource(texture, who);
    const auto latest = static_cast<std::uint32_t>(res.versions.size() - 1);
    if (texture.version() > latest) {
        throw Error("frame graph: " + std::string(who) + " " + std::string(verb) + " " + quoted(res.name) +
                    " version " + std::to_string(texture.version()) + ", which does not exist (the latest is " +
                    std::to_string(latest) + ")");
    }
    if (texture.version() < latest) {
        // Every version lives in the same physical texture, so by the time this pass ran
        // the later writer would have overwritten what it wants.
        const VersionNode& newer = nodes_[res.versions[latest]];
        throw Error("frame graph: " + std::string(who) + " " + std::string(verb) + " " + quoted(res.name) +
                    " version " + std::to_string(texture.version()) + ", but pass " +
                    quoted(passes_[newer.writer].name) + " has since written version " + std::to_string(latest) +
                    "; use the handle that write() returned");
    }
    return res.versions[latest];
}

std::uint32_t FrameGraph::previousVersion(std::uint32_t node) const {
    const VersionNode& version = nodes_[node];
    return resources_[version.resource].versions[version.version - 1];
}

FrameGraphTexture FrameGraph::readTexture(std::uint32_t pass, FrameGraphTexture texture) {
    PassNode& reader = passes_[pass];
    const std::string who = "pass " + quoted(reader.name);
    const VirtualResource& res = resource(texture, who);
    const VersionNode& latest = nodes_[res.versions.back()];
    if (latest.writer == pass) {
        throw Error("frame graph: " + who + " reads " + quoted(res.name) +
                    " after writing it, which would make the pass depend on itself (a cycle); "
                    "declare the read before the write");
    }
    const std::uint32_t node = versionNode(texture, who, "reads");
    if (texture.version() == 0 && !res.imported) {
        throw Error("frame graph: " + who + " reads " + quoted(res.name) +
                    ", which no pass has written and which is not imported");
    }
    if (std::find(reader.reads.begin(), reader.reads.end(), node) == reader.reads.end()) reader.reads.push_back(node);
    return texture;
}

FrameGraphTexture FrameGraph::writeTexture(std::uint32_t pass, FrameGraphTexture texture) {
    PassNode& writer = passes_[pass];
    const std::string who = "pass " + quoted(writer.name);
    resource(texture, who);  // throws on a handle that is not this graph's
    VirtualResource& res = resources_[texture.resource()];
    const auto latest = static_cast<std::uint32_t>(res.versions.size() - 1);
    // A second write from the same pass (with either handle) is the same write.
    if (nodes_[res.versions[latest]].writer == pass) return handle(texture.resource(), latest);

    versionNode(texture, who, "writes");
    const auto node = static_cast<std::uint32_t>(nodes_.size());
    nodes_.push_back(VersionNode{.resource = texture.resource(), .version = latest + 1, .writer = pass});
    res.versions.push_back(node);
    writer.writes.push_back(node);
    return handle(texture.resource(), latest + 1);
}

const FrameGraphTextureDesc& FrameGraph::desc(FrameGraphTexture texture) const {
    return resource(texture, "desc()").desc;
}

std::string_view FrameGraph::name(FrameGraphTexture texture) const { return resource(texture, "name()").name; }

std::uint32_t FrameGraph::passIndex(std::string_view pass) const {
    const auto found = std::find_if(passes_.begin(), passes_.end(), [&](const PassNode& p) { return p.name == pass; });
    if (found == passes_.end()) throw Error("frame graph: there is no pass named " + quoted(pass));
    return static_cast<std::uint32_t>(found - passes_.begin());
}

PassStatus FrameGraph::passStatus(std::string_view pass) const {
    const std::uint32_t index = passIndex(pass);
    requireCompiled("the status of pass " + quoted(pass));
    return passes_[index].status;
}

std::vector<std::string> FrameGraph::executionOrder() const {
    requireCompiled("the execution order");
    std::vector<std::string> names;
    names.reserve(executionOrder_.size());
    for (std::uint32_t pass : executionOrder_) names.push_back(passes_[pass].name);
    return names;
}

std::optional<ResourceLifetime> FrameGraph::lifetime(FrameGraphTexture texture) const {
    const VirtualResource& res = resource(texture, "lifetime()");
    requireCompiled("the lifetime of " + quoted(res.name));
    return res.lifetime;
}

// Builder: thin forwards, so all the checking stays next to the data it checks.

FrameGraphTexture FrameGraphBuilder::create(std::string name, const FrameGraphTextureDesc& desc) {
    return graph_.createTexture(std::move(name), desc);
}
FrameGraphTexture FrameGraphBuilder::read(FrameGraphTexture texture) { return graph_.readTexture(pass_, texture); }
FrameGraphTexture FrameGraphBuilder::write(FrameGraphTexture texture) { return graph_.writeTexture(pass_, texture); }
void FrameGraphBuilder::sideEffect() { graph_.passes_[pass_].sideEffect = true; }
void FrameGraphBuilder::markEmpty() { graph_.passes_[pass_].markedEmpty = true; }
const FrameGraphTextureDesc& FrameGraphBuilder::desc(FrameGraphTexture texture) const {
    return graph_.resource(texture, "pass " + quoted(graph_.passes_[pass_].name)).desc;
}

}  // namespace engine::render
