// SPDX-License-Identifier: MIT
// X11's <X11/Xlib.h> defines `Status` as a macro (for int); a host that includes it (through
// <epoxy/glx.h>, <GL/glx.h>, <vulkan/vulkan_xlib.h>, ...) before SSAM's headers must still compile
// them, and the macro must be X11's again afterwards.
#include <gtest/gtest.h>

#define Status int  // Xlib's own definition
#include "ssam/core/frame.hpp"
#include "ssam/core/settings.hpp"
#include "ssam/core/status.hpp"

namespace {

TEST(SsamCore, X11StatusMacroBeforeTheHeadersCompiles) {
    Status x11 = 3;  // still X11's int
    EXPECT_EQ(x11, 3);
    EXPECT_STREQ(ssam::statusName(ssam::StatusCode::InvalidCall), "invalid call");
}

}  // namespace
