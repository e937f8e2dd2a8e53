// SPDX-License-Identifier: MIT
#pragma once
// A mistake in how a tool was asked to work, found by the tool itself rather than by its
// argument parser: a value out of range ("--size 0x0"), a combination that means nothing, an
// output name no writer can produce. Tools exit 2 for it, as for a parse error, and 1 for any
// other engine::Error (engine/cli/command_line.hpp; game/README.md "Command-line contract").
#include "engine/core/error.hpp"

namespace engine {

class UsageError : public Error {
public:
    using Error::Error;
};

}  // namespace engine
