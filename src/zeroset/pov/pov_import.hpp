// Importing POV-Ray scenes: the part of POV-Ray 3.7's scene description
// language that implicit-surface scenes use (docs/povray.md), read into a
// zeroset Scene — camera, lights, background, polynomial surfaces, blobs,
// isosurfaces, the simple solids, CSG, transforms and constant-colour
// textures. What the reader cannot reproduce exactly it reports: a located
// warning "… is not supported; rendered as …", or a SceneError when the
// geometry itself cannot be drawn. Parse errors are SceneErrors located as
// the scene language's are (file:line:column).
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "zeroset/scene/scene.hpp"
#include "zeroset/scene/scene_error.hpp"

namespace zeroset::pov {

struct PovOptions {
    /// The image size: POV-Ray takes it from the command line (+W, +H), and
    /// scenes read it as image_width and image_height.
    int width = 640;
    int height = 480;
    /// POV-Ray's `clock`.
    double clock = 0.0;
    /// Folders searched for #include after the scene's own (POV-Ray's +L).
    std::vector<std::filesystem::path> include_paths;
    /// #while and #for iterations in all, past which the scene is refused.
    std::uint64_t max_loop_iterations = 10'000'000;
    /// Whether #include also searches POV-Ray's installed include folders.
    bool search_installed_includes = true;
};

/// A scene read from POV-Ray's language. What of it zeroset draws
/// differently is in scene.warnings ("file:line:column: … is not supported;
/// rendered as …", once each).
struct PovImport {
    Scene scene;
    /// Settings zeroset does not need, e.g. "file:line:column: max_gradient
    /// is not needed: zeroset bounds the gradient itself …".
    std::vector<std::string> notes;
};

/// Reads a .pov file; #include files are searched in its folder, then
/// options.include_paths, then POV-Ray's installed include folders. Throws
/// SceneError for a file that cannot be read or parsed, or geometry that
/// cannot be reproduced.
PovImport read_pov_scene(const std::filesystem::path& file, const PovOptions& options = {});

/// Parses POV-Ray text; errors name `file_name`, and includes are searched
/// from `base_dir` first.
PovImport parse_pov_scene(std::string_view text, const std::string& file_name, const std::filesystem::path& base_dir,
                          const PovOptions& options = {});

/// POV-Ray's include folders installed on this machine (Debian's povray
/// package: /usr/share/povray-3.7/include), those that exist.
std::vector<std::filesystem::path> installed_pov_include_dirs();

/// Whether `file` names a POV-Ray scene (.pov, any case).
bool is_pov_file(const std::filesystem::path& file);

}  // namespace zeroset::pov
