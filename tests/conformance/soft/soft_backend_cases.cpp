// SPDX-License-Identifier: MIT
// Instantiates the backend-agnostic conformance suites (tests/conformance/suites) for the
// soft backend: once with the default options and once single-threaded with small tiles,
// so tile-boundary and threading paths both run the whole suite.
#include "../backend_fixture.hpp"

#include "engine/render/devices/create_device.hpp"

namespace ssam::test {
namespace {

BackendCase softCase(std::string name, engine::render::soft::SoftOptions options) {
    render::DeviceOptions device;
    device.soft = options;
    return {
        std::move(name),
        [device] { return std::unique_ptr<render::Backend>(render::createDevice(render::DeviceKind::Soft, device)); },
        [](const render::Backend& backend) -> std::optional<std::uint64_t> {
            return render::soft::softDriver(dynamic_cast<const render::Device&>(backend)).stats().trianglesDropped;
        }};
}

SSAM_INSTANTIATE_CONFORMANCE_SUITES(Soft, ::testing::Values(softCase("default", {}),
                                                            softCase("oneThreadTile8", {.threads = 1, .tileSize = 8})));

}  // namespace
}  // namespace ssam::test
