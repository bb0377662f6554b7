// load_model_input: models through ModelLibrary, scenes through load_scene.
#include "model_input.hpp"

#include "scene_input.hpp"

#include <string>

#include "ray_options.hpp"
#include "zeroset/scene/file_text.hpp"
#include "zeroset/scene/load_scene.hpp"
#include "zeroset/scene/model_library.hpp"

namespace zeroset::cli {

ModelInput load_model_input(const std::filesystem::path& path, const Options& options) {
    if (path.extension() == ".vm") {
        if (options.value("--object")) throw UsageError("--object needs a scene file, not a .vm model");
        try {
            ModelLibrary library;
            return {library.load(path, path.string()), std::nullopt, Mat4::identity()};
        } catch (const FileReadError& e) {
            throw SceneError(path.string(), std::string("cannot open the model file: ") + e.what());
        }
    }
    const Scene scene = load_scene_file(path, options);
    const PlacedObject object = find_object(scene, options.value("--object"));
    const Bounds& bounds = object.object().bounds;
    return {surface_of(object.object()),
            bounds.kind == Bounds::Kind::None ? std::nullopt : std::optional(bounds.enclosing_box()), object.to_scene};
}

}  // namespace zeroset::cli
