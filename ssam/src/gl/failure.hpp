// SPDX-License-Identifier: MIT
#pragma once
// ssam::gl's internals report an error as the core's Failure (core/failure.hpp): the Status the
// public call returns and the message for the host's callback.
#include "../core/failure.hpp"

namespace ssam::gl::detail {

using core::Failure;

}  // namespace ssam::gl::detail
