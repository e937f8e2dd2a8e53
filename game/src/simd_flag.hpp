// SPDX-License-Identifier: MIT
#pragma once
// --simd, as racer and ssam-bench take it: the instruction set of the soft backend's wide
// kernels (engine/render/kernel/simd_isa.hpp). Images are the same bits with each.
#include <optional>
#include <string>

#include <CLI/CLI.hpp>

#include "engine/render/kernel/simd_isa.hpp"

namespace racer {

// --simd auto|sse2|avx2 into `value` (default auto).
void addSimdOption(CLI::App& app, std::string& value);

// The set the flag names; nothing for auto (the backend takes the widest the CPU runs). A set
// this CPU does not run is a usage error (engine::UsageError), refused before any work.
std::optional<engine::render::soft::SimdIsa> simdFromFlag(const std::string& value);

}  // namespace racer
