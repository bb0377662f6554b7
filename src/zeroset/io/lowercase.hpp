// Names and extensions as the writers compare them: lower case, ASCII only
// (".PNG", "png" and ".png" name the same format).
#pragma once

#include <string>

namespace zeroset {

inline std::string lowercase_ascii(std::string text) {
    for (char& c : text)
        if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
    return text;
}

}  // namespace zeroset
