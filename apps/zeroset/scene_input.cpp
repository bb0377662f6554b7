// load_scene_file: .zs scenes through load_scene, .pov ones through the importer.
#include "scene_input.hpp"

#include <cstdio>

#include "zeroset/pov/pov_import.hpp"
#include "zeroset/scene/load_scene.hpp"

namespace zeroset::cli {

Scene load_scene_file(const std::filesystem::path& file, const Options& options, double clock, bool quiet) {
    if (!pov::is_pov_file(file)) return load_scene(file, {}, clock);
    pov::PovOptions p;
    p.width = options.integer("--width").value_or(p.width);
    p.height = options.integer("--height").value_or(p.height);
    p.clock = clock;
    if (const auto paths = options.value("--include-path")) {
        std::size_t start = 0;
        while (start <= paths->size()) {
            const std::size_t end = std::min(paths->find(':', start), paths->size());
            if (end > start) p.include_paths.emplace_back(paths->substr(start, end - start));
            start = end + 1;
        }
    }
    pov::PovImport imported = pov::read_pov_scene(file, p);
    if (!quiet)
        for (const std::string& note : imported.notes) std::fprintf(stderr, "zeroset: note: %s\n", note.c_str());
    return std::move(imported.scene);
}

std::string scene_input_help() {
    return "  --include-path DIRS POV-Ray scenes (.pov): more folders to search for\n"
           "                      #include files, separated by ':' (after the scene's\n"
           "                      own folder, before POV-Ray's installed ones)\n";
}

}  // namespace zeroset::cli
