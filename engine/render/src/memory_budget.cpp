// SPDX-License-Identifier: MIT
#include "engine/render/memory_budget.hpp"

#include <sys/resource.h>

#include <algorithm>
#include <charconv>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "engine/core/error.hpp"

namespace engine::render {

namespace {

std::optional<std::string> readText(const std::filesystem::path& path) {
    std::ifstream in(path);
    if (!in) return std::nullopt;
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

// The number after `key` on its line ("MemAvailable:   22426368 kB"), times 1024 for "kB".
std::optional<std::uint64_t> keyedBytes(std::string_view text, std::string_view key) {
    for (std::size_t at = 0; at < text.size();) {
        const std::size_t end = std::min(text.find('\n', at), text.size());
        std::string_view line = text.substr(at, end - at);
        at = end + 1;
        if (line.substr(0, key.size()) != key) continue;
        line.remove_prefix(key.size());
        const std::size_t digits = line.find_first_of("0123456789");
        if (digits == std::string_view::npos) return std::nullopt;
        std::uint64_t value = 0;
        const auto [rest, ec] = std::from_chars(line.data() + digits, line.data() + line.size(), value);
        if (ec != std::errc()) return std::nullopt;
        const std::string_view unit(rest, static_cast<std::size_t>(line.data() + line.size() - rest));
        const bool kib = unit.find("kB") != std::string_view::npos;
        if (kib && value > UINT64_MAX / 1024) return std::nullopt;
        return kib ? value * 1024 : value;
    }
    return std::nullopt;
}

std::string amount(std::uint64_t bytes) {
    return bytes >= (std::uint64_t{1} << 20) ? std::to_string(bytes >> 20) + " MiB"
                                             : std::to_string((bytes + 1023) >> 10) + " KiB";
}

void keepLeast(std::optional<AvailableMemory>& least, std::uint64_t bytes, std::string source) {
    if (!least || bytes < least->bytes) least = AvailableMemory{bytes, std::move(source)};
}

// What a cgroup and its ancestors still allow: limit - usage + inactive page cache at each
// level (the kernel reclaims that cache before it kills: the "working set" container
// runtimes count), the least over the levels. v2 files are memory.max / memory.current;
// v1's are memory.limit_in_bytes / memory.usage_in_bytes under the memory controller.
void cgroupRemaining(std::optional<AvailableMemory>& least) {
    const std::optional<std::string> membership = readText("/proc/self/cgroup");
    if (!membership) return;
    std::istringstream lines(*membership);
    for (std::string line; std::getline(lines, line);) {
        // "hierarchy-id:controllers:path": v2 is "0::/path", v1's memory line names "memory".
        const std::size_t first = line.find(':'), second = line.find(':', first + 1);
        if (first == std::string::npos || second == std::string::npos) continue;
        const std::string controllers = line.substr(first + 1, second - first - 1);
        const bool v2 = line.substr(0, first) == "0" && controllers.empty();
        const bool v1 = ("," + controllers + ",").find(",memory,") != std::string::npos;
        if (!v2 && !v1) continue;
        const std::filesystem::path root = v2 ? "/sys/fs/cgroup" : "/sys/fs/cgroup/memory";
        const char* limitFile = v2 ? "memory.max" : "memory.limit_in_bytes";
        const char* usageFile = v2 ? "memory.current" : "memory.usage_in_bytes";
        const char* inactiveKey = v2 ? "inactive_file " : "total_inactive_file ";
        for (std::filesystem::path dir = root / line.substr(second + 1).erase(0, 1);; dir = dir.parent_path()) {
            const auto limit = readText(dir / limitFile);
            const auto usage = readText(dir / usageFile);
            const std::optional<std::uint64_t> limitBytes = limit ? parseCgroupBytes(*limit) : std::nullopt;
            const std::optional<std::uint64_t> usageBytes = usage ? parseCgroupBytes(*usage) : std::nullopt;
            if (limitBytes && usageBytes) {
                const auto stat = readText(dir / "memory.stat");
                const std::uint64_t inactive = stat ? keyedBytes(*stat, inactiveKey).value_or(0) : 0;
                const std::uint64_t used = *usageBytes - std::min(*usageBytes, inactive);
                keepLeast(least, *limitBytes - std::min(*limitBytes, used), "the cgroup's " + std::string(limitFile));
            }
            if (dir == root || dir == dir.parent_path() || dir.string().size() <= root.string().size()) break;
        }
    }
}

}  // namespace

std::uint64_t textureBytes(const TextureDesc& desc) {
    const std::uint64_t perTexel = std::uint64_t(formatInfo(desc.format).bytesPerPixel) * std::max(desc.samples, 1);
    std::uint64_t bytes = 0;
    for (int level = 0; level < std::max(desc.mipLevels, 1); ++level)
        bytes += std::uint64_t(std::max(1, desc.width >> level)) * std::uint64_t(std::max(1, desc.height >> level)) *
                 perTexel;
    return bytes;
}

std::string describeSize(const TextureDesc& desc) {
    return std::to_string(desc.width) + "x" + std::to_string(desc.height) + " " + std::string(formatName(desc.format)) +
           (desc.samples > 1 ? " " + std::to_string(desc.samples) + "x" : "");
}

std::optional<std::uint64_t> parseMemAvailable(std::string_view meminfo) {
    return keyedBytes(meminfo, "MemAvailable:");
}

std::optional<std::uint64_t> parseVmSize(std::string_view status) { return keyedBytes(status, "VmSize:"); }

std::optional<std::uint64_t> parseCgroupBytes(std::string_view text) {
    while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.remove_suffix(1);
    std::uint64_t value = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (ec != std::errc() || end != text.data() + text.size() || text.empty()) return std::nullopt;
    return value;
}

std::optional<AvailableMemory> hostMemoryAvailable() {
    std::optional<AvailableMemory> least;
    if (const auto meminfo = readText("/proc/meminfo"))
        if (const auto bytes = parseMemAvailable(*meminfo)) keepLeast(least, *bytes, "MemAvailable in /proc/meminfo");
    cgroupRemaining(least);
    // An address-space limit (ulimit -v) makes an allocation fail rather than the process be
    // killed, but the frame is lost all the same.
    rlimit limit{};
    if (::getrlimit(RLIMIT_AS, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY)
        if (const auto status = readText("/proc/self/status"))
            if (const auto used = parseVmSize(*status))
                keepLeast(least, std::uint64_t(limit.rlim_cur) - std::min<std::uint64_t>(limit.rlim_cur, *used),
                          "address space left under RLIMIT_AS (ulimit -v)");
    return least;
}

void checkFitsInMemory(std::uint64_t bytes, const std::string& what, const MemoryProbe& probe) {
    const std::optional<AvailableMemory> available = probe ? probe() : std::nullopt;
    if (!available || bytes <= available->bytes / 2) return;
    throw Error(what + " needs " + amount(bytes) + " and as much again free beside it, but " +
                amount(available->bytes) + " is available (" + available->source + ")");
}

}  // namespace engine::render
