// content-generator: writes the committed content (textures/*.png, models/*.glb) under --out.
// Run explicitly (`make content`), never as part of a build; unit_content checks that the
// committed files are exactly what this program writes.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <exception>
#include <filesystem>

#include "content.hpp"

int main(int argc, char** argv) {
    CLI::App app{"Generates ssam's committed content (deterministic: fixed seeds)"};
    std::filesystem::path out;
    app.add_option("--out", out, "output directory (the repository's content/ to update the committed files)")->required();
    CLI11_PARSE(app, argc, argv);
    try {
        std::uintmax_t total = 0;
        for (const auto& file : content::generateContent(out)) {
            const std::uintmax_t size = std::filesystem::file_size(out / file);
            total += size;
            std::printf("%8ju  %s\n", size, (out / file).string().c_str());
        }
        std::printf("%8ju  total\n", total);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "content-generator: %s\n", e.what());
        return 1;
    }
    return 0;
}
