// SPDX-License-Identifier: MIT
#pragma once
// Inside the host APIs (ssam::gl, ssam::vk) an error travels as a Failure: the Status the public
// call returns and the message for the host's callback. Thrown inside the library only: every
// public entry point catches it (and anything else) through HostChannel::run, so nothing throws
// into host code.
#include <stdexcept>
#include <string>

#include "ssam/core/frame.hpp"
#include "ssam/core/status.hpp"

namespace ssam::core {

struct Failure : std::runtime_error {
    Status status;
    Failure(Status s, const std::string& message) : std::runtime_error(message), status(s) {}
};

// Runs the host's draw callback for `pass` (way a): whatever it throws becomes a Failure
// (CallbackFailed) naming `api` ("ssam::gl", ...), the pass and, for a std::exception, its what().
template <class Draw>
void runDrawCallback(const char* api, FoliagePass pass, Draw&& draw) {
    const std::string threw = std::string(api) + ": the draw callback threw in the " + foliagePassName(pass) + " pass";
    try {
        draw();
    } catch (const std::exception& e) {
        throw Failure(Status::CallbackFailed, threw + ": " + e.what());
    } catch (...) {
        throw Failure(Status::CallbackFailed, threw + " (not a std::exception)");
    }
}

}  // namespace ssam::core
