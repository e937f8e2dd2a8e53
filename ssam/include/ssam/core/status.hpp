// SPDX-License-Identifier: MIT
#pragma once
// What every SSAM entry point answers (ssam::gl, ssam::vk; the engine-hosted ScreenSpaceAlphaMask
// throws instead, with the same messages): one set of status codes, their names, and the message
// callback. Host-neutral core: standard C++17 only.
//
// X11's <X11/Xlib.h> (pulled in by <epoxy/glx.h>, <GL/glx.h>, <vulkan/vulkan_xlib.h>, ...)
// defines `Status` as a macro for int. Included before this header it would turn
// SSAM's status enum into an enum named int; the macro is set aside while SSAM declares its
// types and put back after. Code that sees the macro spells the type ssam::StatusCode (the same
// type under a name X11 does not take).
#pragma push_macro("Status")
#undef Status

namespace ssam {

enum class Status : int {
    Ok = 0,
    InvalidArgument,        // a bad setting, frame, device description or callback (the message names it)
    InvalidCall,            // out of order: not initialised, a pass not begun, a frame still open
    NoContext,              // ssam::gl: no GL context current, or not OpenGL 3.3 or newer
    MissingEntryPoint,      // the host's loader returned no address for a function SSAM needs (named)
    UnsupportedFeature,     // the context or device lacks what a setting needs (named)
    InvalidTexture,         // ssam::gl: not a 2D texture (or renderbuffer), an unsupported format, the wrong size
    IncompleteFramebuffer,  // ssam::gl: the driver refused SSAM's framebuffer with the host's textures
    ShaderFailed,           // ssam::gl: one of SSAM's programs does not compile or link here
    CallbackFailed,         // the host's draw callback threw (the exception is not rethrown)
    OutOfMemory,            // host or device memory
    Internal,               // an unexpected error inside SSAM (a bug: the message says what)
    DeviceError,            // ssam::vk: a Vulkan call failed (the message names it and its VkResult)
};
using StatusCode = Status;
const char* statusName(Status status) noexcept;  // "ok", "invalid argument", ...

enum class Severity : int { Info, Warning, Error };
const char* severityName(Severity severity) noexcept;  // "info", "warning", "error"

// Called for every error (Status other than Ok), for warnings and once with what was initialised
// (Info). `message` is valid during the call only. A callback that throws is ignored.
using MessageCallback = void (*)(void* user, Severity severity, const char* message);

}  // namespace ssam

#pragma pop_macro("Status")
