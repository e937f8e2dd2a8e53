// SPDX-License-Identifier: MIT
#pragma once
// A fresh directory per test under the system temp dir, removed afterwards, so tests
// never write into the repository and can run in parallel (ctest -j, one process per test).
#include <gtest/gtest.h>
#include <unistd.h>

#include <string>

#include "scratch_dir.hpp"

namespace ssam::testing {

// Named after the running test (and the process: ctest runs tests in parallel).
class TempDir : public ScratchDir {
public:
    // `prefix` names the test binary's area, e.g. "ssam_unit_capture".
    explicit TempDir(const std::string& prefix = "ssam_test") : ScratchDir(testName(prefix)) {}

private:
    static std::string testName(const std::string& prefix) {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        std::string name = prefix + "_" + std::to_string(::getpid());
        if (info) name += std::string("_") + info->test_suite_name() + "_" + info->name();
        for (char& c : name)
            if (c == '/') c = '_';  // parameterised test names contain '/'
        return name;
    }
};

}  // namespace ssam::testing
