// SPDX-License-Identifier: MIT
// FrameGraph::compile(): which passes run (empty-pass propagation, then Filament's
// reference-count culling), in what order, and how long each transient texture lives.
// The three steps are described in frame_graph.hpp.
#include "engine/render/frame_graph.hpp"

#include "engine/core/log.hpp"

#include <vector>

namespace engine::render {

using namespace frame_graph_detail;  // the graph's nodes (frame_graph/graph_nodes.hpp)

void FrameGraph::compile() {
    if (compiled_) return;
    resolveEmptyPasses();
    cullUnreferencedPasses();
    orderPassesAndLifetimes();
    compiled_ = true;
}

void FrameGraph::resolveEmptyPasses() {
    for (const VirtualResource& res : resources_) {
        // Version 0 holds contents only if the texture existed before the graph.
        const std::uint32_t first = res.versions.front();
        nodes_[first].content = res.imported ? first : kNone;
    }
    // Declaration order is topological: every version a pass reads was written by an
    // earlier pass, whose contents are therefore already resolved.
    for (std::uint32_t p = 0; p < passes_.size(); ++p) {
        PassNode& pass = passes_[p];
        pass.status = pass.markedEmpty ? PassStatus::Empty : PassStatus::Executes;
        pass.missingInput = kNone;
        if (pass.status == PassStatus::Executes) {
            for (std::uint32_t read : pass.reads) {
                if (nodes_[read].content != kNone) continue;
                pass.status = PassStatus::InputEmpty;
                pass.missingInput = read;
                log::debug("frame graph: pass '", pass.name, "' skipped: its input '",
                           resources_[nodes_[read].resource].name, "' was only produced by empty passes");
                break;
            }
        }
        // A pass that does not run leaves its targets as they were.
        for (std::uint32_t written : pass.writes) {
            nodes_[written].content =
                pass.status == PassStatus::Executes ? written : nodes_[previousVersion(written)].content;
        }
    }
}

void FrameGraph::cullUnreferencedPasses() {
    auto runs = [&](std::uint32_t pass) { return pass != kNone && passes_[pass].status == PassStatus::Executes; };

    // A read references the version whose contents it gets, which skips over versions
    // that empty passes only nominally wrote.
    for (VersionNode& node : nodes_) node.refCount = 0;
    for (PassNode& pass : passes_) {
        pass.refCount = pass.writes.size();
        if (pass.status != PassStatus::Executes) continue;
        for (std::uint32_t read : pass.reads) ++nodes_[nodes_[read].content].refCount;
    }

    std::vector<std::uint32_t> unreferenced;  // versions written by running passes that nothing reads
    auto cull = [&](PassNode& pass) {
        pass.status = PassStatus::Culled;
        for (std::uint32_t read : pass.reads) {
            const std::uint32_t content = nodes_[read].content;
            if (--nodes_[content].refCount == 0 && runs(nodes_[content].writer)) unreferenced.push_back(content);
        }
    };

    // Collect the unread versions before culling write-less passes: that culling pushes the
    // versions it drops to zero, and pushing one twice would release its writer twice.
    for (std::uint32_t n = 0; n < nodes_.size(); ++n) {
        if (nodes_[n].refCount == 0 && runs(nodes_[n].writer)) unreferenced.push_back(n);
    }
    for (PassNode& pass : passes_) {
        if (pass.status == PassStatus::Executes && pass.writes.empty() && !pass.sideEffect) cull(pass);
    }
    while (!unreferenced.empty()) {
        const std::uint32_t node = unreferenced.back();
        unreferenced.pop_back();
        PassNode& writer = passes_[nodes_[node].writer];
        if (--writer.refCount == 0 && !writer.sideEffect) cull(writer);
    }
}

void FrameGraph::orderPassesAndLifetimes() {
    executionOrder_.clear();
    for (std::uint32_t p = 0; p < passes_.size(); ++p) {
        if (passes_[p].status == PassStatus::Executes) executionOrder_.push_back(p);
    }

    for (VirtualResource& res : resources_) res.lifetime.reset();
    auto use = [&](std::uint32_t node, std::size_t position) {
        auto& lifetime = resources_[nodes_[node].resource].lifetime;
        if (!lifetime) lifetime = ResourceLifetime{position, position};
        lifetime->last = position;
    };
    for (std::size_t position = 0; position < executionOrder_.size(); ++position) {
        const PassNode& pass = passes_[executionOrder_[position]];
        for (std::uint32_t read : pass.reads) use(read, position);
        for (std::uint32_t written : pass.writes) use(written, position);
    }

    allocateBefore_.assign(executionOrder_.size(), {});
    releaseAfter_.assign(executionOrder_.size(), {});
    for (std::uint32_t r = 0; r < resources_.size(); ++r) {
        const VirtualResource& res = resources_[r];
        if (res.imported || !res.lifetime) continue;
        allocateBefore_[res.lifetime->first].push_back(r);
        releaseAfter_[res.lifetime->last].push_back(r);
    }
}

}  // namespace engine::render
