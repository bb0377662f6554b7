// SceneError's message formatting.
#include "zeroset/scene/scene_error.hpp"

#include <utility>

namespace zeroset {

SceneError::SceneError(std::string file, SourceLocation where, std::string message)
    : std::runtime_error(format_location(file, where) + ": " + message),
      file_(std::move(file)),
      where_(where),
      message_(std::move(message)) {}

SceneError::SceneError(std::string file, std::string message)
    : SceneError(std::move(file), SourceLocation{}, std::move(message)) {}

}  // namespace zeroset
