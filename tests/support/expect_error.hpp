// SPDX-License-Identifier: MIT
#pragma once
// Expects `fn` to throw engine::Error whose message contains `substring` (bad input must be
// refused with a message that says what was wrong), or returns the message for a test to
// examine itself.
#include <gtest/gtest.h>

#include <exception>
#include <string>

#include "engine/core/error.hpp"

namespace ssam::testing {

template <typename Fn>
void expectError(Fn&& fn, const std::string& substring) {
    try {
        fn();
        ADD_FAILURE() << "expected engine::Error containing \"" << substring << "\", nothing was thrown";
    } catch (const engine::Error& e) {
        EXPECT_NE(std::string(e.what()).find(substring), std::string::npos)
            << "message \"" << e.what() << "\" lacks \"" << substring << "\"";
    } catch (const std::exception& e) {
        ADD_FAILURE() << "expected engine::Error, got another exception: " << e.what();
    }
}

// The message of the engine::Error `fn` throws; a test failure (and "") when it throws
// nothing or another exception.
template <typename Fn>
std::string errorOf(Fn&& fn) {
    try {
        fn();
    } catch (const engine::Error& e) {
        return e.what();
    } catch (const std::exception& e) {
        ADD_FAILURE() << "expected engine::Error, got another exception: " << e.what();
        return {};
    }
    ADD_FAILURE() << "expected engine::Error, nothing was thrown";
    return {};
}

}  // namespace ssam::testing
