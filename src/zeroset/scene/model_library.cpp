// Model import through expr/vm_import, with errors moved into the scene's format.
#include "zeroset/scene/model_library.hpp"

#include <sstream>

#include "zeroset/expr/vm_import.hpp"
#include "zeroset/scene/file_text.hpp"
#include "zeroset/scene/scene_error.hpp"

namespace zeroset {

Expr ModelLibrary::load(const std::filesystem::path& path, const std::string& display_name) {
    const std::filesystem::path key = canonical_path(path);
    if (const auto it = models_.find(key); it != models_.end()) return it->second;
    std::istringstream in(read_text_file(path));
    try {
        return models_[key] = import_vm(in);
    } catch (const VmImportError& e) {
        throw SceneError(display_name, {e.line(), e.column()}, e.what());
    }
}

}  // namespace zeroset
