// SPDX-License-Identifier: MIT
#include "engine/core/log.hpp"

#include <atomic>
#include <cstdio>
#include <mutex>

namespace engine::log {
namespace {
std::atomic<Level> g_level{Level::Info};
std::mutex g_write_mutex;  // whole lines, even when several threads log at once
constexpr const char* kTags[] = {"debug", "info", "warn", "error", ""};
}  // namespace

void setLevel(Level lvl) { g_level = lvl; }
Level level() { return g_level; }

void write(Level lvl, std::string_view message) {
    std::lock_guard lock(g_write_mutex);
    std::fprintf(stderr, "[%s] %.*s\n", kTags[static_cast<int>(lvl)], static_cast<int>(message.size()), message.data());
}

}  // namespace engine::log
