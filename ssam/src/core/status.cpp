// SPDX-License-Identifier: MIT
#include "ssam/core/frame.hpp"
#include "ssam/core/status.hpp"

#include "enum_names.hpp"

namespace ssam {

const char* statusName(Status status) noexcept {
    static constexpr const char* kNames[] = {"ok",
                                             "invalid argument",
                                             "invalid call",
                                             "no context",
                                             "missing entry point",
                                             "unsupported feature",
                                             "invalid texture",
                                             "incomplete framebuffer",
                                             "shader failed",
                                             "callback failed",
                                             "out of memory",
                                             "internal error",
                                             "device error"};
    return core::enumName<Status::DeviceError>(status, kNames, "unknown status");
}

const char* severityName(Severity severity) noexcept {
    static constexpr const char* kNames[] = {"info", "warning", "error"};
    return core::enumName<Severity::Error>(severity, kNames, "unknown severity");
}

const char* foliagePassName(FoliagePass pass) noexcept { return pass == FoliagePass::Mask ? "mask" : "colour"; }

}  // namespace ssam
