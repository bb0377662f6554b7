// ImageOutput: -o/--output and --format read and checked in one place for
// render, slice and basins.
#include "image_output.hpp"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <string>

namespace zeroset::cli {

std::string image_output_help(const std::string& default_name) {
    return "  -o, --output FILE   the image to write; the format follows the extension:\n"
           "                      .png (8-bit sRGB), .ppm (8-bit sRGB), .pfm (linear\n"
           "                      float) or .exr (linear float; renders add depth Z and\n"
           "                      normals N.x, N.y, N.z). '-' writes to standard output.\n"
           "                      Default: " +
           default_name +
           "\n"
           "  --format F          png, ppm, pfm or exr: the format for '-o -' (default png)\n";
}

ImageOutput::ImageOutput(const Options& options, const std::filesystem::path& default_name, int frames,
                         bool check_place) {
    const bool numbered = frames > 1;
    if (numbered) digits_ = std::max<int>(4, static_cast<int>(std::to_string(frames - 1).size()));
    if (options.value("-o") && options.value("--output")) throw UsageError("give -o or --output, not both");
    const std::string given = options.value("-o").value_or(options.value("--output").value_or(""));
    std::optional<ImageFormat> named;
    if (const auto name = options.value("--format")) {
        named = image_format_from_name(*name);
        if (!named) throw UsageError("unknown image format '" + *name + "' (give png, ppm, pfm or exr)");
    }
    if (given == "-") {
        if (numbered) throw UsageError("frames are written to numbered files, not to standard output");
        format_ = named.value_or(ImageFormat::Png);
        if (::isatty(STDOUT_FILENO)) throw UsageError("standard output is a terminal; redirect it to a file or a pipe");
        return;
    }
    path_ = given.empty() ? default_name : std::filesystem::path(given);
    if (const auto problem = image_format_problem(path_)) throw UsageError(path_.string() + ": " + *problem);
    format_ = *image_format_for(path_);
    if (named && *named != format_)
        throw UsageError("--format does not match the extension of " + path_.string() +
                         " (--format is for '-o -'; the extension names a file's format)");
    if (check_place) check(numbered ? 0 : -1);
}

void ImageOutput::check(int frame) const {
    if (!path_.empty()) check_image_output(path_of(frame));
}

std::filesystem::path ImageOutput::path_of(int frame) const {
    if (frame < 0) return path_;
    char number[24];
    std::snprintf(number, sizeof number, "_%0*d", digits_, frame);
    return path_.parent_path() / (path_.stem().string() + number + path_.extension().string());
}

std::string ImageOutput::name(int frame) const { return path_.empty() ? "<stdout>" : path_of(frame).string(); }

void ImageOutput::write(const Image& image, int frame) const {
    if (path_.empty())
        write_image_to_stdout(image, format_);
    else
        write_image(image, path_of(frame));
}

}  // namespace zeroset::cli
