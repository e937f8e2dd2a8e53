// SPDX-License-Identifier: MIT
#include "simd_flag.hpp"

#include "engine/core/usage_error.hpp"

namespace racer {

void addSimdOption(CLI::App& app, std::string& value) {
    app.add_option("--simd", value,
                   "soft backend kernels' instruction set (auto: the widest this CPU runs); images are the same bits "
                   "with each")
        ->check(CLI::IsMember({"auto", "sse2", "avx2"}))
        ->capture_default_str();
}

std::optional<engine::render::soft::SimdIsa> simdFromFlag(const std::string& value) {
    const std::optional<engine::render::soft::SimdIsa> isa = engine::render::soft::parseSimdIsa(value);
    if (isa && !engine::render::soft::simdIsaSupported(*isa))
        throw engine::UsageError("--simd " + value + ": " + engine::render::soft::simdIsaRefusal(*isa));
    return isa;
}

}  // namespace racer
