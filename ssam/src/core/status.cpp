// SPDX-License-Identifier: MIT
#include "ssam/core/frame.hpp"
#include "ssam/core/status.hpp"

namespace ssam {

const char* statusName(Status status) noexcept {
    switch (status) {
        case Status::Ok: return "ok";
        case Status::InvalidArgument: return "invalid argument";
        case Status::InvalidCall: return "invalid call";
        case Status::NoContext: return "no context";
        case Status::MissingEntryPoint: return "missing entry point";
        case Status::UnsupportedFeature: return "unsupported feature";
        case Status::InvalidTexture: return "invalid texture";
        case Status::IncompleteFramebuffer: return "incomplete framebuffer";
        case Status::ShaderFailed: return "shader failed";
        case Status::CallbackFailed: return "callback failed";
        case Status::OutOfMemory: return "out of memory";
        case Status::Internal: return "internal error";
        case Status::DeviceError: return "device error";
    }
    return "unknown status";
}

const char* severityName(Severity severity) noexcept {
    switch (severity) {
        case Severity::Info: return "info";
        case Severity::Warning: return "warning";
        case Severity::Error: return "error";
    }
    return "unknown severity";
}

const char* foliagePassName(FoliagePass pass) noexcept { return pass == FoliagePass::Mask ? "mask" : "colour"; }

}  // namespace ssam
