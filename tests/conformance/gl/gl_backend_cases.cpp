// SPDX-License-Identifier: MIT
// Instantiates the backend-agnostic conformance suites (tests/conformance/suites) for the GL
// backend on a headless EGL context (llvmpipe on CI). The suites' tolerances are the API's
// (one UNORM code, one half ULP), which is what the GL backend is held to as well.
#include "../backend_fixture.hpp"

#include "engine/render/devices/create_device.hpp"

namespace ssam::test {
namespace {

SSAM_INSTANTIATE_CONFORMANCE_SUITES(Gl, ::testing::Values(uncountedCase("headless", [] {
                                        return render::createDevice(render::DeviceKind::Gl);
                                    })));

}  // namespace
}  // namespace ssam::test
