// `zeroset import`: a POV-Ray scene (.pov) read by the importer and written
// as the equivalent zeroset scene (.zs), with the importer's warnings as
// comments at its top — to see what zeroset made of it, or to go on
// editing it in zeroset's language. The file is written atomically.
#include <cstdio>
#include <filesystem>
#include <span>
#include <string>

#include "commands.hpp"
#include "options.hpp"
#include "scene_input.hpp"
#include "zeroset/io/atomic_file.hpp"
#include "zeroset/pov/pov_import.hpp"
#include "zeroset/scene/scene_writer.hpp"

namespace zeroset::cli {

namespace {

std::string import_usage() {
    return R"(Usage: zeroset import SCENE.pov [-o OUT.zs] [options]

Reads a POV-Ray scene (docs/povray.md) and writes the zeroset scene it
becomes: camera, lights, objects with their expressions, blobs by their
components, materials and transforms. What zeroset draws differently from
POV-Ray is listed at the top of the file (and on stderr).

Options:
  -o, --output FILE   the scene to write (default: SCENE's name with .zs, in
                      the current directory; - for standard output)
  --width W           the image size the scene is read for (POV-Ray scenes
  --height H          may use image_width and image_height; default 640×480)
)" + scene_input_help() + R"(  -q, --quiet         no notes and no summary line
  -h, --help          this text
)";
}

}  // namespace

int import_command(const std::vector<std::string>& args) {
    std::vector<std::string> valued{"-o", "--output", "--width", "--height"};
    valued.insert(valued.end(), scene_input_options.begin(), scene_input_options.end());
    const Options options(args, valued, {"-h", "--help", "-q", "--quiet"});
    if (options.has("-h") || options.has("--help")) {
        std::fputs(import_usage().c_str(), stdout);
        return 0;
    }
    if (options.positional().size() != 1) throw UsageError("import takes one POV-Ray scene file (try zeroset import --help)");
    const std::filesystem::path input = options.positional()[0];
    if (!pov::is_pov_file(input)) throw UsageError("import reads POV-Ray scenes (.pov), not '" + input.string() + "'");
    const std::string output = options.value("-o").value_or(options.value("--output").value_or(input.stem().string() + ".zs"));
    const bool quiet = options.has("-q") || options.has("--quiet");
    const Scene scene = load_scene_file(input, options, 0.0, quiet);
    const std::string text = write_scene(scene, "Imported from " + input.filename().string() +
                                                    " by zeroset import (docs/povray.md).");
    if (output == "-") {
        std::fwrite(text.data(), 1, text.size(), stdout);
    } else {
        write_file_atomically(output, std::span(reinterpret_cast<const std::uint8_t*>(text.data()), text.size()));
    }
    for (const std::string& w : scene.warnings) std::fprintf(stderr, "zeroset: warning: %s\n", w.c_str());
    if (!quiet && output != "-")
        std::fprintf(stderr, "zeroset: wrote %s — %zu objects, %zu lights\n", output.c_str(), scene.nodes.size(), scene.lights.size());
    return 0;
}

}  // namespace zeroset::cli
