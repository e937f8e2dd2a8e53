// SPDX-License-Identifier: MIT
// Headless EGL: Mesa's surfaceless platform (llvmpipe or a DRM driver), then the EGL device
// platform (NVIDIA's headless path). A core 4.5 context without any surface or config
// (EGL_KHR_surfaceless_context + EGL_KHR_no_config_context); the backend renders into FBOs.
#include <cstring>
#include <dlfcn.h>
#include <vector>

#include <epoxy/egl.h>
#include <epoxy/gl.h>

#include "engine/core/error.hpp"
#include "engine/core/log.hpp"
#include "engine/render/gl/gl_context.hpp"

namespace engine::render::gl {
namespace {

std::string hex(EGLint v) {
    char buf[16];
    std::snprintf(buf, sizeof buf, "0x%04x", unsigned(v));
    return buf;
}

bool hasExtension(const char* list, const char* name) {
    if (!list) return false;
    const std::size_t n = std::strlen(name);
    for (const char* p = list; (p = std::strstr(p, name)) != nullptr; p += n)
        if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return true;
    return false;
}

struct Candidate {
    std::string name;
    EGLDisplay display = EGL_NO_DISPLAY;
};

}  // namespace

struct HeadlessEglContext::Impl {
    EGLDisplay display = EGL_NO_DISPLAY;
    EGLContext context = EGL_NO_CONTEXT;
    std::string description;

    ~Impl() {
        if (context != EGL_NO_CONTEXT) {
            if (eglGetCurrentContext() == context)
                eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
            eglDestroyContext(display, context);
        }
    }
};

namespace {

// Tries to make a surfaceless core context on one display; returns "" on success.
std::string tryDisplay(const Candidate& c, const HeadlessEglOptions& options, HeadlessEglContext::Impl& out) {
    EGLint major = 0, minor = 0;
    if (c.display == EGL_NO_DISPLAY) return c.name + ": no display";
    if (!eglInitialize(c.display, &major, &minor))
        return c.name + ": eglInitialize failed (" + hex(eglGetError()) + ")";
    // Displays stay initialized for the life of the process (never eglTerminate): displays of
    // one platform and native display are shared, so terminating would pull them from under
    // other contexts, and Mesa would unload its driver, leaving what the driver keeps for good
    // to leak checkers as leaks from an unknown module. Initializing again is a no-op.
    auto fail = [&](const std::string& why) { return c.name + ": " + why; };
    const char* extensions = eglQueryString(c.display, EGL_EXTENSIONS);
    if (!hasExtension(extensions, "EGL_KHR_surfaceless_context")) return fail("no EGL_KHR_surfaceless_context");
    const EGLenum api = options.es ? EGL_OPENGL_ES_API : EGL_OPENGL_API;
    if (!eglBindAPI(api))
        return fail(options.es ? "eglBindAPI(EGL_OPENGL_ES_API) failed" : "eglBindAPI(EGL_OPENGL_API) failed");

    EGLConfig config = EGL_NO_CONFIG_KHR;
    if (!hasExtension(extensions, "EGL_KHR_no_config_context") &&
        !hasExtension(extensions, "EGL_MESA_configless_context")) {
        const EGLint wanted[] = {EGL_RENDERABLE_TYPE, options.es ? EGL_OPENGL_ES3_BIT : EGL_OPENGL_BIT, EGL_NONE};
        EGLint count = 0;
        if (!eglChooseConfig(c.display, wanted, &config, 1, &count) || count == 0)
            return fail(options.es ? "no configless contexts and no OpenGL ES 3 config"
                                   : "no configless contexts and no OpenGL config");
    }
    std::vector<EGLint> attributes = {EGL_CONTEXT_MAJOR_VERSION, options.major, EGL_CONTEXT_MINOR_VERSION,
                                      options.minor};
    // ES has no profiles.
    if (!options.es)
        attributes.insert(attributes.end(), {EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT});
    if (options.debug) attributes.insert(attributes.end(), {EGL_CONTEXT_OPENGL_DEBUG, EGL_TRUE});
    attributes.push_back(EGL_NONE);
    const EGLContext context = eglCreateContext(c.display, config, EGL_NO_CONTEXT, attributes.data());
    if (context == EGL_NO_CONTEXT)
        return fail(std::string(options.es ? "no OpenGL ES " : "no OpenGL ") + std::to_string(options.major) + "." +
                    std::to_string(options.minor) + (options.es ? " context (" : " core context (") +
                    hex(eglGetError()) + ")");
    if (!eglMakeCurrent(c.display, EGL_NO_SURFACE, EGL_NO_SURFACE, context)) {
        const EGLint error = eglGetError();
        eglDestroyContext(c.display, context);
        return fail("eglMakeCurrent without surface failed (" + hex(error) + ")");
    }
    out.display = c.display;
    out.context = context;
    const char* vendor = eglQueryString(c.display, EGL_VENDOR);
    out.description = "EGL " + std::to_string(major) + "." + std::to_string(minor) + " " + c.name + " (" +
                      (vendor ? vendor : "?") + "), " + reinterpret_cast<const char*>(glGetString(GL_RENDERER)) + ", " +
                      reinterpret_cast<const char*>(glGetString(GL_VERSION));
    return {};
}

std::vector<Candidate> candidates(const HeadlessEglOptions& options, std::string& why) {
    std::vector<Candidate> out;
    // libepoxy aborts the process when it cannot load libEGL: look for it first.
    static const bool haveEgl = [] {
        void* lib = dlopen("libEGL.so.1", RTLD_LAZY | RTLD_LOCAL);
        return lib != nullptr;  // kept loaded: epoxy will use it
    }();
    if (!haveEgl) {
        why = "libEGL.so.1 cannot be loaded (install libegl1 and a driver, e.g. Mesa's libegl1-mesa)";
        return out;
    }
    const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    if (!client) {
        why = "EGL client extensions unavailable (EGL 1.5 / EGL_EXT_client_extensions missing)";
        return out;
    }
    if (!hasExtension(client, "EGL_EXT_platform_base") && !hasExtension(client, "EGL_KHR_platform_base")) {
        why = "EGL has no platform_base extension";
        return out;
    }
    if (options.device < 0 && hasExtension(client, "EGL_MESA_platform_surfaceless"))
        out.push_back({"surfaceless platform",
                       eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr)});
    if (hasExtension(client, "EGL_EXT_platform_device") && hasExtension(client, "EGL_EXT_device_enumeration")) {
        EGLint count = 0;
        eglQueryDevicesEXT(0, nullptr, &count);
        std::vector<EGLDeviceEXT> devices(std::size_t(std::max(count, 0)));
        if (count > 0) eglQueryDevicesEXT(count, devices.data(), &count);
        for (EGLint i = 0; i < count; ++i) {
            if (options.device >= 0 && i != options.device) continue;
            const char* deviceExtensions = eglQueryDeviceStringEXT(devices[i], EGL_EXTENSIONS);
            std::string name = "device " + std::to_string(i);
            if (hasExtension(deviceExtensions, "EGL_EXT_device_drm")) {
                const char* file = eglQueryDeviceStringEXT(devices[i], EGL_DRM_DEVICE_FILE_EXT);
                if (file) name += std::string(" (") + file + ")";
            }
            out.push_back({name, eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr)});
        }
        if (options.device >= 0 && out.empty())
            why = "EGL device " + std::to_string(options.device) + " does not exist (" + std::to_string(count) +
                  " devices)";
    } else if (options.device >= 0) {
        why =
            "EGL_EXT_platform_device is unavailable, so device " + std::to_string(options.device) + " cannot be chosen";
    }
    if (out.empty() && why.empty())
        why = "neither EGL_MESA_platform_surfaceless nor EGL_EXT_platform_device is available";
    return out;
}

}  // namespace

HeadlessEglContext::HeadlessEglContext(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
HeadlessEglContext::~HeadlessEglContext() = default;

std::unique_ptr<HeadlessEglContext> HeadlessEglContext::create(const HeadlessEglOptions& options) {
    std::string why;
    const std::vector<Candidate> list = candidates(options, why);
    std::string tried;
    for (const Candidate& c : list) {
        auto impl = std::make_unique<Impl>();
        const std::string failure = tryDisplay(c, options, *impl);
        if (failure.empty()) {
            log::debug("GL: ", impl->description);
            return std::unique_ptr<HeadlessEglContext>(new HeadlessEglContext(std::move(impl)));
        }
        tried += (tried.empty() ? "" : "; ") + failure;
    }
    throw Error("headless EGL context: " + (tried.empty() ? why : tried));
}

std::string HeadlessEglContext::unavailableReason(const HeadlessEglOptions& options) {
    try {
        create(options);
        return {};
    } catch (const Error& e) {
        return e.what();
    }
}

void HeadlessEglContext::makeCurrent() {
    if (eglGetCurrentContext() == impl_->context) return;
    if (!eglMakeCurrent(impl_->display, EGL_NO_SURFACE, EGL_NO_SURFACE, impl_->context))
        throw Error("headless EGL context: eglMakeCurrent failed (" + hex(eglGetError()) + ")");
}

std::string HeadlessEglContext::describe() const { return impl_->description; }

}  // namespace engine::render::gl
