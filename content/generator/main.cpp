// SPDX-License-Identifier: MIT
// content-generator: writes the committed content (textures/*.png, models/*.glb) under --out.
// Run explicitly (`make content`), never as part of a build; unit_content checks that the
// committed files are exactly what this program writes. Keeps the command-line contract
// (engine/cli/command_line.hpp): every place it writes is proven writable before anything is
// generated, and the set of files is replaced whole or not at all.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <filesystem>

#include "content.hpp"
#include "engine/cli/command_line.hpp"
#include "engine/core/output_file.hpp"

namespace {

int generate(const std::filesystem::path& out, bool draco) {
    for (const std::filesystem::path& file : content::contentFiles())
        engine::requireWritableFile(out / file, /*createDirectory=*/true);
    std::uintmax_t total = 0;
    for (const auto& file : content::generateContent(out, draco)) {
        const std::uintmax_t size = std::filesystem::file_size(out / file);
        total += size;
        std::printf("%8ju  %s\n", size, (out / file).string().c_str());
    }
    std::printf("%8ju  total\n", total);
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"Generates ssam's committed content (deterministic: fixed seeds)"};
    std::filesystem::path out;
    app.add_option("--out", out,
                   "output directory, created if missing (the repository's content/ to update the committed files)")
        ->required();
    bool noDraco = false;
    app.add_flag("--no-draco", noDraco,
                 "plants' meshes without Draco compression (the web page's content: make web; its WebAssembly "
                 "build has no Draco decoder)");
    app.footer(engine::cli::contractHelpFooter());
    return engine::cli::runTool("content-generator", app, argc, argv, [&] { return generate(out, !noDraco); });
}
