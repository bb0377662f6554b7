// SourceLocation: a 1-based line and column in a scene file. Every token
// carries one, so every error can point at the text that caused it.
#pragma once

#include <string>

namespace zeroset {

struct SourceLocation {
    int line = 0;    // 1-based; 0 stands for the file as a whole
    int column = 0;  // 1-based, in characters (UTF-8 code points), a tab counting as one
};

/// `file:line:column`, or just `file` for the file as a whole.
inline std::string format_location(const std::string& file, SourceLocation where) {
    if (where.line <= 0) return file;
    return file + ":" + std::to_string(where.line) + ":" + std::to_string(where.column);
}

}  // namespace zeroset
