// SPDX-License-Identifier: MIT
#include "engine/render/kernel/simd_isa.hpp"

namespace engine::render::soft {

const char* simdIsaName(SimdIsa isa) {
    switch (isa) {
        case SimdIsa::Sse2: return "sse2";
        case SimdIsa::Avx2: return "avx2";
    }
    return "?";
}

std::optional<SimdIsa> parseSimdIsa(std::string_view name) {
    for (SimdIsa isa : {SimdIsa::Sse2, SimdIsa::Avx2})
        if (name == simdIsaName(isa)) return isa;
    return std::nullopt;
}

bool simdIsaSupported(SimdIsa isa) {
    switch (isa) {
        case SimdIsa::Sse2: return true;  // x86-64's baseline; a scalar build runs its portable code
        case SimdIsa::Avx2:
#if (defined(__x86_64__) || defined(__i386__)) && defined(__SSE2__) && !defined(SOFT_RASTER_SCALAR)
            return __builtin_cpu_supports("avx2");
#else
            return false;
#endif
    }
    return false;
}

std::string simdIsaRefusal(SimdIsa isa) {
    return std::string("this CPU does not run ") + simdIsaName(isa) + " (it runs " + simdIsaName(bestSimdIsa()) +
           " at most)";
}

SimdIsa bestSimdIsa() { return simdIsaSupported(SimdIsa::Avx2) ? SimdIsa::Avx2 : SimdIsa::Sse2; }

std::vector<SimdIsa> supportedSimdIsas() {
    std::vector<SimdIsa> isas;
    for (SimdIsa isa : {SimdIsa::Sse2, SimdIsa::Avx2})
        if (simdIsaSupported(isa)) isas.push_back(isa);
    return isas;
}

}  // namespace engine::render::soft
