// SPDX-License-Identifier: MIT
#pragma once
// The soft backend's CPU kernels of the standard programs (standard_programs.hpp).
#include <memory>

#include "engine/render/program.hpp"
#include "engine/render/kernel/program_kernel.hpp"

namespace engine::render::soft {

std::shared_ptr<const ProgramKernel> standardKernel(ProgramKind kind);

}  // namespace engine::render::soft
