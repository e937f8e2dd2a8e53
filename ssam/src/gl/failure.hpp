// SPDX-License-Identifier: MIT
#pragma once
// How ssam::gl's internals report an error: a Failure carries the Status the public call returns
// and the message for the host's callback. Thrown inside the library only: every public entry
// point catches it (and anything else) and returns the Status, so nothing throws into host code.
#include <stdexcept>
#include <string>

#include "ssam/gl/ssam_gl.hpp"

namespace ssam::gl::detail {

struct Failure : std::runtime_error {
    Status status;
    Failure(Status s, const std::string& message) : std::runtime_error(message), status(s) {}
};

}  // namespace ssam::gl::detail
