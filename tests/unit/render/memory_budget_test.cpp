// SPDX-License-Identifier: MIT
// memory_budget: what a texture needs, what the host has left (the /proc and cgroup parsers,
// RLIMIT_AS), and the refusal message that names both.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/resource.h>

#include <fstream>
#include <sstream>

#include "engine/render/memory_budget.hpp"
#include "expect_error.hpp"

namespace {

using namespace engine::render;
using ::testing::HasSubstr;
using ssam::testing::expectError;

constexpr std::uint64_t kMiB = std::uint64_t{1} << 20;

TextureDesc target(int width, int height, Format format = Format::RGBA8_UNORM, int samples = 1, int mips = 1) {
    TextureDesc d = renderTargetDesc("big", width, height, format, samples);
    d.mipLevels = mips;
    return d;
}

MemoryProbe fixed(std::uint64_t bytes) {
    return [bytes] { return std::optional<AvailableMemory>(AvailableMemory{bytes, "the test's figure"}); };
}

TEST(MemoryBudget, TextureBytesCountLevelsAndSamples) {
    EXPECT_EQ(textureBytes(target(16384, 16384)), 1024 * kMiB);
    EXPECT_EQ(textureBytes(target(16384, 16384, Format::D32F)), 1024 * kMiB);
    EXPECT_EQ(textureBytes(target(100, 50, Format::RGBA16F, 4)), 100u * 50 * 8 * 4);
    // 8x4, 4x2, 2x1, 1x1 texels of 1 byte.
    EXPECT_EQ(textureBytes(target(8, 4, Format::R8_UNORM, 1, 4)), 32u + 8 + 2 + 1);
}

TEST(MemoryBudget, DescribesSizes) {
    EXPECT_EQ(describeSize(target(16384, 16384)), "16384x16384 RGBA8_UNORM");
    EXPECT_EQ(describeSize(target(64, 32, Format::RGBA16F, 4)), "64x32 RGBA16F 4x");
}

TEST(MemoryBudget, RefusesWhatWouldLeaveLessThanItselfAndSaysWhy) {
    const std::uint64_t bytes = textureBytes(target(16384, 16384));
    EXPECT_NO_THROW(checkFitsInMemory(bytes, "texture 'big': 16384x16384 RGBA8_UNORM", fixed(2 * bytes)));
    try {
        checkFitsInMemory(bytes, "texture 'big': 16384x16384 RGBA8_UNORM", fixed(2 * bytes - 1));
        ADD_FAILURE() << "not refused";
    } catch (const engine::Error& e) {
        EXPECT_EQ(std::string(e.what()),
                  "texture 'big': 16384x16384 RGBA8_UNORM needs 1024 MiB and as much again free beside it, but 2047 "
                  "MiB is available (the test's figure)");
    }
    // Under a mebibyte, in KiB (rounded up).
    expectError([&] { checkFitsInMemory(64 * 1024, "texture 't'", fixed(100 * 1024)); },
                "texture 't' needs 64 KiB and as much again free beside it, but 100 KiB is available");
    EXPECT_NO_THROW(checkFitsInMemory(64 * 1024, "texture 't'", fixed(128 * 1024)));
}

TEST(MemoryBudget, NoFigureRefusesNothing) {
    EXPECT_NO_THROW(checkFitsInMemory(std::uint64_t{1} << 40, "t", MemoryProbe{}));
    EXPECT_NO_THROW(checkFitsInMemory(std::uint64_t{1} << 40, "t", [] { return std::optional<AvailableMemory>(); }));
}

TEST(MemoryBudget, ParsesProcAndCgroupFiles) {
    const std::string meminfo =
        "MemTotal:       24684096 kB\nMemFree:        23000000 kB\nMemAvailable:   22426368 kB\nBuffers: 1 kB\n";
    EXPECT_EQ(parseMemAvailable(meminfo), std::uint64_t{22426368} * 1024);
    EXPECT_EQ(parseMemAvailable("MemTotal: 5 kB\n"), std::nullopt);
    EXPECT_EQ(parseMemAvailable("MemAvailable: lots\n"), std::nullopt);
    EXPECT_EQ(parseVmSize("Name:\tracer\nVmPeak:\t 9000 kB\nVmSize:\t  8000 kB\n"), std::uint64_t{8000} * 1024);
    EXPECT_EQ(parseCgroupBytes("max\n"), std::nullopt);
    EXPECT_EQ(parseCgroupBytes("1073741824\n"), std::uint64_t{1} << 30);
    EXPECT_EQ(parseCgroupBytes("9223372036854771712\n"), std::uint64_t{9223372036854771712u});
    EXPECT_EQ(parseCgroupBytes(""), std::nullopt);
    EXPECT_EQ(parseCgroupBytes("12 34\n"), std::nullopt);
}

TEST(MemoryBudget, HostFigureIsReadOnLinux) {
    const std::optional<AvailableMemory> host = hostMemoryAvailable();
    ASSERT_TRUE(host.has_value());
    EXPECT_GT(host->bytes, 0u);
    EXPECT_FALSE(host->source.empty());
}

// In a child process, so the limit does not outlive the test: 0 when the figure is at most the
// 300 MiB the limit leaves and names RLIMIT_AS.
[[noreturn]] void exitWithFigureUnderAddressSpaceLimit() {
    std::ifstream in("/proc/self/status");
    std::stringstream text;
    text << in.rdbuf();
    const rlim_t limit = parseVmSize(text.str()).value() + 300 * kMiB;
    const rlimit as{limit, limit};
    if (::setrlimit(RLIMIT_AS, &as) != 0) std::_Exit(2);
    const std::optional<AvailableMemory> host = hostMemoryAvailable();
    const bool limited = host && host->bytes <= 300 * kMiB && host->source.find("RLIMIT_AS") != std::string::npos;
    std::_Exit(limited ? 0 : 1);
}

// An address-space limit lowers the figure to what it leaves.
TEST(MemoryBudget, AddressSpaceLimitCounts) {
    EXPECT_EXIT(exitWithFigureUnderAddressSpaceLimit(), ::testing::ExitedWithCode(0), "");
}

}  // namespace
