// SPDX-License-Identifier: MIT
#pragma once
// A CPU program for the soft backend (ProgramDesc::soft), written against the
// program-authoring headers beside this one. A program is a plain struct:
//   - constructible as Program(const Params&, const TextureLookup&), resolving the texture
//     handles its parameters name;
//   - `static constexpr ProgramNeeds kNeeds`: the interpolants it reads (the rasterizer
//     skips the others, [Hathaway 2010] §3.5.2's dead-code stripping done by hand);
//   - `glm::vec4 shade(const Fragment&) const`: straight-alpha colour of one pixel;
//   - optionally `static constexpr bool kReadsPixels = true` when shade() reads textures
//     at the fragment's pixel (full-screen programs) or otherwise depends on the pixel (a
//     screen-space dither): the output then varies across a triangle even when every
//     interpolant is constant;
//   - optionally fast-path hooks, each taken by the rasterizer for any program that declares
//     it (rasterizer/rasterizer_class.hpp defines each contract; the built-in programs of
//     kernel/programs.hpp use the same): the composite hooks (compositeColor, compositeFactor,
//     compositeFactorRow, and compositeColorRow where the colour is computed from those texels),
//     sampled rows (rowSampler, shadeSampled, shadeSampled4), four-lane alpha (hasAlpha4,
//     alpha4), alpha-first rows (those plus alphaTestFactor) and replicated-alpha mask rows
//     (kShadesReplicatedAlpha, alpha);
//   - optionally the row hook `void shadeRow(SimdIsa, int bx, int py, std::uint32_t live,
//     glm::vec4* out) const`: shade() of the live pixels of an 8-pixel block row at once, for
//     programs whose per-pixel work is worth vectorising across pixels (raster::hasRowShader;
//     kernel/simd/ has the lane types and the way to build one kernel for each SimdIsa).
// makeKernel<Program, Params>() instantiates the tile rasterizer for it in the calling
// translation unit: one virtual call per run of a draw's triangles in a tile, none per pixel.
#include <memory>
#include <span>

#include <glm/glm.hpp>

#include "engine/render/draw_params.hpp"
#include "engine/render/kernel/texture_lookup.hpp"
#include "engine/render/kernel/detail/triangle_rasterizer.hpp"

namespace engine::render::soft {

// One draw's program, its parameters and textures resolved.
class BoundProgram {
public:
    virtual ~BoundProgram() = default;
    // Mesh programs: the matrix the vertex stage transforms by (identity for full-screen ones).
    virtual glm::mat4 viewProj() const = 0;
    // Rasterizes a run of the draw's triangles binned to one tile, in submission order.
    virtual void rasterize(const DrawState& draw, std::span<const SetupTriangle* const> triangles, const Rect& tile,
                           TileCounters& counters) const = 0;
};

class ProgramKernel {
public:
    virtual ~ProgramKernel() = default;
    // `params` holds the program's Params (the backend checked the type).
    virtual std::unique_ptr<BoundProgram> bind(const DrawParams& params, const TextureLookup& textures) const = 0;
};

template <typename Program, typename Params>
class KernelOf final : public ProgramKernel {
    class Bound final : public BoundProgram {
    public:
        Bound(const Params& params, const TextureLookup& textures) : params_(params), program_(params_, textures) {}
        glm::mat4 viewProj() const override {
            if constexpr (requires { params_.viewProj; }) return params_.viewProj;
            else return glm::mat4(1.0f);
        }
        void rasterize(const DrawState& draw, std::span<const SetupTriangle* const> triangles, const Rect& tile,
                       TileCounters& counters) const override {
            raster::TriangleRasterizer<Program> rasterizer(draw, program_, counters);
            for (const SetupTriangle* t : triangles) rasterizer.rasterize(*t, tile);
        }

    private:
        Params params_;
        Program program_;
    };

public:
    std::unique_ptr<BoundProgram> bind(const DrawParams& params, const TextureLookup& textures) const override {
        return std::make_unique<Bound>(*params.get<Params>(), textures);
    }
};

template <typename Program, typename Params>
std::shared_ptr<const ProgramKernel> makeKernel() {
    return std::make_shared<KernelOf<Program, Params>>();
}

}  // namespace engine::render::soft
