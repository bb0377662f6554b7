// load_scene and parse_scene: one SceneParser per scene.
#include "zeroset/scene/load_scene.hpp"

#include "zeroset/scene/file_text.hpp"
#include "zeroset/scene/scene_parser.hpp"

namespace zeroset {

Scene load_scene(const std::filesystem::path& file, const SceneLimits& limits, double clock) {
    std::string text;
    try {
        text = read_text_file(file);
    } catch (const FileReadError& e) {
        throw SceneError(file.string(), std::string("cannot open the scene file: ") + e.what());
    }
    SceneParser parser(limits, clock);
    parser.parse(file.string(), std::move(text), file.parent_path(), canonical_path(file));
    return parser.take_scene();
}

Scene parse_scene(std::string_view text, const std::string& file_name, const std::filesystem::path& base_dir,
                  const SceneLimits& limits, double clock) {
    SceneParser parser(limits, clock);
    parser.parse(file_name, std::string(text), base_dir);
    return parser.take_scene();
}

}  // namespace zeroset
