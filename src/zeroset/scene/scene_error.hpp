// SceneError: what the scene loader throws for every problem in a scene — a
// syntax error, a bad value, a missing include, a malformed model. what() is
// `file:line:column: message`, the form editors and terminals link to the
// offending text.
#pragma once

#include <stdexcept>
#include <string>

#include "zeroset/scene/source_location.hpp"

namespace zeroset {

class SceneError : public std::runtime_error {
public:
    /// An error at a place in a file: what() is "file:line:column: message".
    SceneError(std::string file, SourceLocation where, std::string message);
    /// An error about a file as a whole (it cannot be read): what() is "file: message".
    SceneError(std::string file, std::string message);

    [[nodiscard]] const std::string& file() const { return file_; }
    /// 1-based; 0 when the error concerns the file as a whole.
    [[nodiscard]] int line() const { return where_.line; }
    [[nodiscard]] int column() const { return where_.column; }
    /// The message without the location.
    [[nodiscard]] const std::string& message() const { return message_; }

private:
    std::string file_;
    SourceLocation where_;
    std::string message_;
};

}  // namespace zeroset
