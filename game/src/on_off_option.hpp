// SPDX-License-Identifier: MIT
#pragma once
// The switches racer and ssam-bench take as on|off (--lod, --crossfade, --motion-vectors, ...):
// one place that says which words they accept and that --help shows the default.
#include <string>

#include <CLI/CLI.hpp>

namespace racer {

// --`name` on|off into `value`; returns the option for further conditions (needs, excludes).
inline CLI::Option* addOnOffOption(CLI::App& app, const std::string& name, std::string& value,
                                   const std::string& description) {
    return app.add_option(name, value, description)->check(CLI::IsMember({"on", "off"}))->capture_default_str();
}

}  // namespace racer
