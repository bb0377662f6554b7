// Where a command's image goes: a file named by -o/--output, whose format
// follows its extension, or standard output (`-o -`, PNG unless --format
// says otherwise). Everything that can be checked — the format, the place
// to write — is checked when the command starts, before any rendering.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "options.hpp"
#include "zeroset/io/image_writer.hpp"

namespace zeroset::cli {

/// The options every image-writing command takes, for its Options list.
inline const std::vector<std::string> image_output_options = {"-o", "--output", "--format"};

/// The help text's lines for those options, with the command's default file.
std::string image_output_help(const std::string& default_name);

class ImageOutput {
public:
    /// Reads -o/--output and --format; `default_name` when -o is absent.
    /// With `frames` > 1, a sequence: each frame's file name is numbered (and
    /// standard output is refused). Throws UsageError for a bad name or
    /// format, ImageWriteError when the (first) file could not be written.
    /// `check_place` false skips the check that the file could be written
    /// here (a distributed render's other ranks, which write nothing).
    ImageOutput(const Options& options, const std::filesystem::path& default_name, int frames = 1,
                bool check_place = true);

    [[nodiscard]] ImageFormat format() const { return format_; }
    /// The file name — with `_0042` before the extension for frame 42 of a
    /// sequence (more digits past 9 999 frames) — or "<stdout>".
    [[nodiscard]] std::string name(int frame = -1) const;
    /// Throws ImageWriteError unless the frame's file could be written now.
    void check(int frame) const;
    void write(const Image& image, int frame = -1) const;

private:
    [[nodiscard]] std::filesystem::path path_of(int frame) const;

    std::filesystem::path path_;  // empty for standard output
    ImageFormat format_;
    int digits_ = 0;  // of a frame number; 0 when the output is one image
};

}  // namespace zeroset::cli
