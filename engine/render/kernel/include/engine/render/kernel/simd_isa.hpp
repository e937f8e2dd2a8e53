// SPDX-License-Identifier: MIT
#pragma once
// Which instruction set the soft backend's wide kernels run: chosen once per
// backend at run time, never at build time, so one binary runs on any x86-64 and uses the
// widest vectors the CPU has. Every choice gives the same images, bit for bit: each lane does
// the IEEE single-precision operations of the scalar code in the same order, and nothing is
// fused (no FMA: the AVX2 kernels are compiled for AVX2 alone, the project with
// -ffp-contract=off); SoftGoldenHash.EveryInstructionSetDrawsTheSameBits forces each one this
// CPU runs.
//
// Not AVX-512: the rasterizer shades 8-pixel block rows, which AVX2's 8 lanes fill; 16 lanes
// would need two rows in flight, and the CPUs this was measured on execute 512-bit
// operations as two 256-bit halves.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace engine::render::soft {

enum class SimdIsa {
    Sse2,  // 4 lanes: every x86-64 (the baseline the project is built for)
    Avx2,  // 8 lanes
};

const char* simdIsaName(SimdIsa isa);  // "sse2", "avx2"
// "sse2" or "avx2"; nothing for any other text.
std::optional<SimdIsa> parseSimdIsa(std::string_view name);
// Whether this CPU runs it (and this build has its kernels: a SOFT_RASTER_SCALAR build runs
// its portable code whatever is chosen, and reports only sse2).
bool simdIsaSupported(SimdIsa isa);
// Why `isa` cannot be used here: "this CPU does not run avx2 (it runs sse2 at most)".
std::string simdIsaRefusal(SimdIsa isa);
// The widest one this CPU runs: the soft backend's default.
SimdIsa bestSimdIsa();
// Every one this CPU runs, narrowest first.
std::vector<SimdIsa> supportedSimdIsas();

}  // namespace engine::render::soft
