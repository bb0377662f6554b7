// Reading a ray list, line by line, with FILE:LINE errors.
#include "ray_list.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <string>
#include <string_view>

#include "zeroset/scene/file_text.hpp"

namespace zeroset::cli {

namespace {

/// The line's words, after a `#` comment is cut off.
std::vector<std::string> words(std::string line) {
    if (const auto hash = line.find('#'); hash != std::string::npos) line.resize(hash);
    std::vector<std::string> result;
    std::size_t i = 0;
    while (true) {
        i = line.find_first_not_of(" \t\r", i);
        if (i == std::string::npos) return result;
        const std::size_t end = std::min(line.find_first_of(" \t\r", i), line.size());
        result.push_back(line.substr(i, end - i));
        i = end;
    }
}

/// `word` as a finite number; `problem` says why not.
bool parse_number(const std::string& word, double& value, std::string& problem) {
    const char* begin = word.data() + (word.starts_with('+') ? 1 : 0);
    const char* const end = word.data() + word.size();
    const auto [next, error] = std::from_chars(begin, end, value);
    if (error == std::errc::result_out_of_range || (error == std::errc() && next == end && !std::isfinite(value))) {
        problem = "'" + word + "' is not a finite number";
        return false;
    }
    if (error != std::errc() || next != end) {
        problem = "'" + word + "' is not a number";
        return false;
    }
    return true;
}

}  // namespace

std::vector<Ray> parse_ray_list(std::string_view text, const std::string& name) {
    std::vector<Ray> rays;
    int number = 0;
    for (std::size_t begin = 0; begin < text.size();) {
        // A line ends at LF, CR LF or a lone CR.
        std::size_t end = text.find_first_of("\r\n", begin);
        if (end == std::string_view::npos) end = text.size();
        const std::vector<std::string> w = words(std::string(text.substr(begin, end - begin)));
        begin = end + (text.substr(end, 2) == "\r\n" ? 2 : 1);
        ++number;
        if (w.empty()) continue;
        const std::string where = name + ":" + std::to_string(number) + ": ";
        if (w.size() != 6)
            throw RayListError(where + "expected six numbers 'ox oy oz dx dy dz', got " + std::to_string(w.size()) +
                               (w.size() == 1 ? " word" : " words"));
        double v[6];
        std::string problem;
        for (std::size_t i = 0; i < 6; ++i)
            if (!parse_number(w[i], v[i], problem)) throw RayListError(where + problem);
        const Ray ray{{v[0], v[1], v[2]}, {v[3], v[4], v[5]}};
        if (ray.dir == Vec3d{}) throw RayListError(where + "the direction is zero");
        rays.push_back(ray);
    }
    if (rays.empty()) throw RayListError(name + ": the ray list holds no rays");
    return rays;
}

std::vector<Ray> read_ray_list(const std::filesystem::path& file) {
    std::string text;
    try {
        text = read_text_file(file);
    } catch (const FileReadError& e) {
        throw RayListError(file.string() + ": cannot open the ray list: " + e.what());
    }
    return parse_ray_list(text, file.string());
}

}  // namespace zeroset::cli
