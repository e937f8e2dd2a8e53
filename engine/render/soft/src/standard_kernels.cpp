// SPDX-License-Identifier: MIT
#include "standard_kernels.hpp"

#include <string>

#include "engine/core/error.hpp"
#include "engine/render/kernel/programs.hpp"

namespace engine::render::soft {

std::shared_ptr<const ProgramKernel> standardKernel(ProgramKind kind) {
    switch (kind) {
        case ProgramKind::Flat: return makeKernel<FlatProgram, FlatParams>();
        case ProgramKind::OpaqueLit: return makeKernel<OpaqueLitProgram, SurfaceParams>();
        case ProgramKind::MaskedLit: return makeKernel<MaskedLitProgram, SurfaceParams>();
        case ProgramKind::AlphaOnly: return makeKernel<AlphaOnlyProgram, AlphaOnlyParams>();
    }
    throw Error("unknown standard program " + std::to_string(int(kind)));
}

}  // namespace engine::render::soft
