// SPDX-License-Identifier: MIT
// LightShaftKernel's row hook, one march per instruction set (light_shaft_march.inl). Only
// where the x86 lanes exist: elsewhere (WebAssembly, the scalar build) shadeRow marches each
// pixel with shade(), the same bits, and these are neither compiled nor called.
#include "light_shaft_kernel.hpp"

#if defined(__SSE2__) && !defined(SOFT_RASTER_SCALAR)
#include <algorithm>
#include <cstdint>

#include "engine/render/kernel/simd/lanes_avx2.hpp"
#include "engine/render/kernel/simd/lanes_sse2.hpp"

namespace lightshafts {

namespace sse2 {
using namespace engine::render::soft::simd::sse2;
#include "light_shaft_march.inl"
}  // namespace sse2

SOFT_AVX2_BEGIN
namespace avx2 {
using namespace engine::render::soft::simd::avx2;
// NOLINTNEXTLINE(readability-duplicate-include): the march is compiled once per instruction set
#include "light_shaft_march.inl"
}  // namespace avx2
SOFT_AVX2_END

}  // namespace lightshafts
#endif
