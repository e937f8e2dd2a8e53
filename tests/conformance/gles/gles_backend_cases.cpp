// SPDX-License-Identifier: MIT
// Instantiates the backend-agnostic conformance suites (tests/conformance/suites) for the GLES
// driver on a headless EGL OpenGL ES 3.0 context (llvmpipe on CI), held to the same tolerances
// as the GL 4.5 driver.
#include "../backend_fixture.hpp"

#include "engine/render/devices/create_device.hpp"

namespace ssam::test {
namespace {

SSAM_INSTANTIATE_CONFORMANCE_SUITES(Gles, ::testing::Values(uncountedCase("headless", [] {
                                        return render::createDevice(render::DeviceKind::Gles);
                                    })));

}  // namespace
}  // namespace ssam::test
