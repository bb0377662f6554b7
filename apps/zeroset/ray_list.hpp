// The ray list `zeroset ray --rays FILE` reads: one ray per line,
// `ox oy oz dx dy dz`, with blank lines and `#` comments allowed.
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "zeroset/math/ray.hpp"

namespace zeroset::cli {

/// A ray list that cannot be read or holds a malformed line; the message is
/// `FILE:LINE: what is wrong` (or `FILE: what is wrong`).
class RayListError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// Every ray of the file, in order. Throws RayListError for an unreadable
/// file, a line that is not six finite numbers, a zero direction, or a file
/// with no rays.
std::vector<Ray> read_ray_list(const std::filesystem::path& file);
/// The same for text already read; messages name `name` as the file.
std::vector<Ray> parse_ray_list(std::string_view text, const std::string& name);

}  // namespace zeroset::cli
