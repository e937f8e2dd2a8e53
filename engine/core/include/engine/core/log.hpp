// SPDX-License-Identifier: MIT
#pragma once
// Minimal levelled logging to stderr. Messages are built with operator<< so any
// streamable value can be logged without a formatting library.
#include <sstream>
#include <string_view>

namespace engine::log {

enum class Level { Debug, Info, Warn, Error, Off };

void setLevel(Level level);
Level level();
void write(Level level, std::string_view message);

template <typename... Args>
void print(Level lvl, const Args&... args) {
    if (lvl < level()) return;
    std::ostringstream out;
    (out << ... << args);
    write(lvl, out.str());
}

// log::debug(...), log::info(...), log::warn(...), log::error(...): print at a fixed level, one
// callable per level rather than four copies of the same forwarding function.
template <Level L>
struct AtLevel {
    template <typename... Args>
    void operator()(const Args&... args) const {
        print(L, args...);
    }
};
inline constexpr AtLevel<Level::Debug> debug{};
inline constexpr AtLevel<Level::Info> info{};
inline constexpr AtLevel<Level::Warn> warn{};
inline constexpr AtLevel<Level::Error> error{};

}  // namespace engine::log
