// SPDX-License-Identifier: MIT
// A C++17 host of ssam::gl alone (tests/unit/install/component_only_consumer.cmake): compiles the public
// header as C++17, links libssam_gl and nothing of the engine, and calls it without a GL context
// (a loader that resolves nothing), which must give statuses, not a crash.
#include <cstdio>

#include <ssam/gl/ssam_gl.hpp>

static_assert(__cplusplus == 201703L, "built as C++17: the package must not raise the consumer's standard");

int main() {
    ssam::gl::ScreenSpaceAlphaMaskGl ssam;
    const ssam::gl::GetProcAddress nothing = [](const char*) -> void* { return nullptr; };
    const ssam::gl::Status status = ssam.initialize(nothing);
    std::printf("ssam %s; initialize without GL: %s (%s); release: %s\n", SSAM_VERSION_STRING,
                ssam::gl::statusName(status), ssam.lastMessage(), ssam::gl::statusName(ssam.release()));
    return status == ssam::gl::Status::MissingEntryPoint ? 0 : 1;
}
