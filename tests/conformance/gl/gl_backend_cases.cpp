// SPDX-License-Identifier: MIT
// Instantiates the backend-agnostic conformance suites (tests/conformance/suites) for the GL
// backend on a headless EGL context (llvmpipe on CI). The suites' tolerances are the API's
// (one UNORM code, one half ULP), which is what the GL backend is held to as well.
#include "../backend_fixture.hpp"

#include "engine/render/gl/gl_backend.hpp"

namespace ssam::test {
namespace {

BackendCase glCase(std::string name, engine::render::gl::GlOptions options) {
    return {std::move(name),
            [options] { return std::unique_ptr<render::Backend>(engine::render::gl::createGlBackend(options)); },
            {}};  // GL does not count dropped triangles
}

SSAM_INSTANTIATE_CONFORMANCE_SUITES(Gl, ::testing::Values(glCase("headless", {})));

}  // namespace
}  // namespace ssam::test
