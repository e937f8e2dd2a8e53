// SPDX-License-Identifier: MIT
#pragma once
// SOFT_AVX2_BEGIN ... SOFT_AVX2_END: every function defined between them is compiled for AVX2
// (and for nothing more: no FMA, so no multiply and add is ever fused), whatever the rest of
// the translation unit targets. A wide kernel is written once, against the lane types of
// lanes_sse2.hpp / lanes_avx2.hpp, in a body file that a .cpp includes twice: once as is
// (namespace sse2) and once between these marks (namespace avx2); the backend calls the one
// its SimdIsa names (simd_isa.hpp). Functions defined elsewhere (glm, std) keep the
// baseline target, so no out-of-line copy of them ever holds an AVX2 instruction.
#if defined(__clang__)
#define SOFT_AVX2_BEGIN _Pragma("clang attribute push(__attribute__((target(\"avx2\"))), apply_to = function)")
#define SOFT_AVX2_END _Pragma("clang attribute pop")
#else
#define SOFT_AVX2_BEGIN _Pragma("GCC push_options") _Pragma("GCC target(\"avx2\")")
#define SOFT_AVX2_END _Pragma("GCC pop_options")
#endif
