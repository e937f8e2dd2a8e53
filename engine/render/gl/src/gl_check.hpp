// SPDX-License-Identifier: MIT
#pragma once
// GL error checks. glGetError stalls a threaded driver, so the backend calls checkGl after
// operations that allocate or can fail on input, per draw only in debug builds
// (kCheckEveryDraw) or with debug output on.
#include <string>

namespace engine::render::gl {

#ifdef NDEBUG
inline constexpr bool kCheckEveryDraw = false;
#else
inline constexpr bool kCheckEveryDraw = true;
#endif

// "0x0505": how GL enums and codes appear in messages.
std::string hex(unsigned value);

// Drops errors left by a host (or an earlier, already reported failure) before an operation
// whose own errors are checked.
void drainGlErrors();

// Throws engine::Error "<what>: GL_OUT_OF_MEMORY (0x0505)" when GL has an error pending.
void checkGl(const std::string& what);

}  // namespace engine::render::gl
