// SPDX-License-Identifier: MIT
#pragma once
// Where racer and ssam-bench find the committed content (models/, textures/) when no
// --content is given.
#include <filesystem>

namespace racer {

// An installed executable's own content: <its directory>/SSAM_CONTENT_FROM_EXE (by default
// ../share/ssam, as `cmake --install` lays it out), found through /proc/self/exe so it runs
// from any working directory. Otherwise (a build tree) the content/ of the sources it was
// built from, SSAM_CONTENT_DIR.
std::filesystem::path defaultContentDir();

}  // namespace racer
