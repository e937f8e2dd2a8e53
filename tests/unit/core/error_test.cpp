// SPDX-License-Identifier: MIT
// engine::Error: what() carries the whole message, even one quoting input with a NUL in it.
#include <gtest/gtest.h>

#include <string>

#include "engine/core/error.hpp"

namespace {

TEST(Error, MessageIsKept) {
    EXPECT_STREQ(engine::Error("image 'x.png': truncated at row 12").what(), "image 'x.png': truncated at row 12");
}

TEST(Error, NulInAQuotedNameIsSpelledOut) {
    const std::string name("tr\0ee", 5);  // a glTF name "tr\u0000ee"
    const engine::Error e("node '" + name + "': bad transform");
    EXPECT_STREQ(e.what(), "node 'tr\\0ee': bad transform");
}

}  // namespace
