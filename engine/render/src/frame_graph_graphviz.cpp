// SPDX-License-Identifier: MIT
// FrameGraph::dumpGraphviz(): the graph as Graphviz dot, for looking at what compile()
// kept and why (`dot -Tsvg graph.dot`).
#include "engine/render/frame_graph.hpp"

#include <ostream>
#include <string>
#include <vector>

namespace engine::render {

using namespace frame_graph_detail;  // the graph's nodes (frame_graph/graph_nodes.hpp)

namespace {

std::string escaped(std::string_view text) {
    std::string out;
    for (char c : text) {
        if (c == '"' || c == '\\') out += '\\';
        out += c;
    }
    return out;
}

// Appended piece by piece: GCC 12's false -Wrestrict at -O3 on "P" + std::string (bug 105329).
std::string passId(std::uint32_t pass) {
    std::string id = "P";
    id += std::to_string(pass);
    return id;
}

std::string versionId(const VersionNode& node) {
    std::string id = "R";
    id += std::to_string(node.resource);
    id += '_';
    id += std::to_string(node.version);
    return id;
}

constexpr const char* kGrey = "color=gray, fontcolor=gray";

}  // namespace

void FrameGraph::dumpGraphviz(std::ostream& out, const TextureBytes& bytesOf) const {
    auto runs = [&](std::uint32_t pass) {
        return pass != kNone && (!compiled_ || passes_[pass].status == PassStatus::Executes);
    };

    out << "digraph frame_graph {\n"
        << "  rankdir=LR;\n"
        << "  node [fontname=\"Helvetica\"];\n";

    for (std::uint32_t p = 0; p < passes_.size(); ++p) {
        const PassNode& pass = passes_[p];
        out << "  " << passId(p) << " [label=\"" << escaped(pass.name);
        if (compiled_ && pass.status != PassStatus::Executes) out << "\\n(" << toString(pass.status) << ")";
        out << "\", shape=box";
        if (runs(p)) {
            out << ", style=filled, fillcolor=\"#cfe2f3\"";
        } else if (pass.status == PassStatus::Culled) {
            out << ", " << kGrey;
        } else {
            out << ", style=dashed, " << kGrey;
        }
        if (pass.sideEffect) out << ", penwidth=2";
        out << "];\n";
    }

    // A version is alive when a running pass writes or reads it.
    std::vector<bool> alive(nodes_.size(), false);
    for (std::uint32_t n = 0; n < nodes_.size(); ++n) alive[n] = runs(nodes_[n].writer);
    for (std::uint32_t p = 0; p < passes_.size(); ++p) {
        if (!runs(p)) continue;
        for (std::uint32_t read : passes_[p].reads) alive[read] = true;
    }

    for (std::uint32_t n = 0; n < nodes_.size(); ++n) {
        const VersionNode& node = nodes_[n];
        const VirtualResource& res = resources_[node.resource];
        // A created texture's version 0 has no contents and nothing may read it: no node.
        if (node.version == 0 && !res.imported) continue;
        out << "  " << versionId(node) << " [label=\"" << escaped(res.name) << " v" << node.version << "\\n"
            << res.desc.width << "x" << res.desc.height << "\", shape=ellipse";
        if (res.imported) out << ", peripheries=2";
        if (!alive[n]) out << ", " << kGrey;
        out << "];\n";
    }

    for (std::uint32_t p = 0; p < passes_.size(); ++p) {
        const char* style = runs(p) ? "" : " [color=gray]";
        for (std::uint32_t read : passes_[p].reads) {
            out << "  " << versionId(nodes_[read]) << " -> " << passId(p) << style << ";\n";
        }
        for (std::uint32_t written : passes_[p].writes) {
            out << "  " << passId(p) << " -> " << versionId(nodes_[written]) << style << ";\n";
        }
    }
    // Where a pass did not run, the version it nominally wrote still holds an older one's
    // contents: show which, since that is what its readers get.
    for (std::uint32_t n = 0; n < nodes_.size(); ++n) {
        const VersionNode& node = nodes_[n];
        if (!compiled_ || node.content == kNone || node.content == n) continue;
        out << "  " << versionId(nodes_[node.content]) << " -> " << versionId(node)
            << " [style=dotted, label=\"unchanged\"];\n";
    }
    if (compiled_) {
        // What the graph allocates, as the graph's label (left-aligned lines: "\l").
        out << "  labelloc=b;\n  labeljust=l;\n  label=\"transients (lifetime: first pass -> last pass):\\l";
        const std::vector<TransientInfo> list = transients();
        if (list.empty()) out << "  none\\l";
        for (const TransientInfo& t : list) {
            out << "  " << escaped(t.name) << " " << t.desc.width << "x" << t.desc.height << ": "
                << escaped(t.firstPass) << " -> " << escaped(t.lastPass);
            if (bytesOf) out << ", " << bytesOf(t.desc) << " bytes";
            out << "\\l";
        }
        if (bytesOf) out << "peak transient bytes: " << peakTransientBytes(bytesOf) << "\\l";
        for (const std::string& note : notes_) out << escaped(note) << "\\l";
        out << "\";\n";
    }
    out << "}\n";
}

}  // namespace engine::render
