// SPDX-License-Identifier: MIT
#pragma once
// The programs every backend brings (ProgramRef::standard). Each is described like a
// module's program (program_desc.hpp); this is the backend-neutral half of the description
// (name, vertex input, parameter struct, GL uniform and texture layout, checks), which each
// backend completes with its own part (its GLSL, its CPU kernel).
#include "engine/render/program.hpp"
#include "engine/render/program_desc.hpp"

namespace engine::render {

ProgramDesc standardProgramDesc(ProgramKind kind);

inline constexpr int kStandardProgramCount = 4;

}  // namespace engine::render
