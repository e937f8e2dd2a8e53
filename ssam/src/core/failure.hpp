// SPDX-License-Identifier: MIT
#pragma once
// Inside the host APIs (ssam::gl, ssam::vk) an error travels as a Failure: the Status the public
// call returns and the message for the host's callback. Thrown inside the library only: every
// public entry point catches it (and anything else) through HostChannel::run, so nothing throws
// into host code.
#include <stdexcept>
#include <string>

#include "ssam/core/status.hpp"

namespace ssam::core {

struct Failure : std::runtime_error {
    Status status;
    Failure(Status s, const std::string& message) : std::runtime_error(message), status(s) {}
};

}  // namespace ssam::core
