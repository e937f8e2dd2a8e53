// SPDX-License-Identifier: MIT
#pragma once
// The side-by-side compare (racer --compare A,B; key V in the window): the frame renders
// with technique A as usual and, by a second FrameRenderer, with B; two passes at the end of
// A's frame graph then compose them (compare_layout.hpp): "compare: keep left" copies A's
// finished frame aside, and "compare" draws B's right half over A's frame, the zoomed insets
// of the crop where the two differ most (found from both frames, read back), their frames
// and the labels. The left half is A's frame untouched; the right half is B's, copied
// texel for texel.
#include <memory>
#include <string>
#include <vector>

#include "engine/core/non_copyable.hpp"
#include "engine/render/backend.hpp"
#include "engine/render/frame_graph.hpp"
#include "engine/render/owned.hpp"
#include "engine/scene/mesh_library.hpp"
#include "hud/overlay.hpp"

namespace racer {

class FrameRenderer;
struct RendererOptions;

class CompareView : engine::NonCopyable {
public:
    // `right` is made from `options` (its technique is B). Throws engine::Error when B
    // cannot run on this backend.
    CompareView(engine::render::Backend& backend, const engine::scene::MeshLibrary& library,
                const RendererOptions& options);
    ~CompareView();

    FrameRenderer& right() { return *right_; }

    // Into A's `graph`: the two compose passes over `color` (the latest version of `target`,
    // A's width x height colour). Returns the colour's new version.
    engine::render::FrameGraphTexture addPasses(engine::render::FrameGraph& graph,
                                                engine::render::FrameGraphTexture color,
                                                engine::render::TextureHandle target, int width, int height,
                                                const std::string& leftName, hud::Overlay& overlay);

    // The last frame's overlay rectangles outside the plain halves (compare_layout.hpp).
    const std::vector<hud::PixelRect>& marks() const { return marks_; }
    hud::PixelRect crop() const { return crop_; }

private:
    engine::render::Backend& backend_;
    std::unique_ptr<FrameRenderer> right_;
    engine::render::Owned<engine::render::TextureHandle> leftCopy_;
    std::vector<hud::PixelRect> marks_;
    hud::PixelRect crop_;
};

}  // namespace racer
