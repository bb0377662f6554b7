// ModelLibrary: the .vm models a scene imports with model("file.vm"), each
// read and parsed once per scene however often the scene uses it.
#pragma once

#include <filesystem>
#include <map>
#include <string>

#include "zeroset/expr/expr.hpp"

namespace zeroset {

class ModelLibrary {
public:
    /// The model stored at `path`, named `display_name` in messages. Throws
    /// FileReadError when the file cannot be read, and SceneError located in
    /// the .vm file (`display_name:line:column: …`) when it is malformed.
    Expr load(const std::filesystem::path& path, const std::string& display_name);

private:
    std::map<std::filesystem::path, Expr> models_;  // by canonical path
};

}  // namespace zeroset
