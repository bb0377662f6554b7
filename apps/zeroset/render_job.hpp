// What `zeroset render` was asked to do, checked before any rendering: the
// scene file (or the built-in scene), each frame's clock, the output, and
// how to report. The local frame loop (render_command.cpp) and the
// distributed one (distributed/) both run a RenderJob.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "image_output.hpp"
#include "options.hpp"
#include "tile_log.hpp"
#include "zeroset/render/image.hpp"
#include "zeroset/render/render_settings.hpp"
#include "zeroset/render/render_stats.hpp"
#include "zeroset/scene/scene.hpp"

namespace zeroset::cli {

class RenderJob {
public:
    /// Reads and checks the options (UsageError, ImageWriteError), and that
    /// the image and tile log could be written — unless `writes_files` is
    /// false: a distributed render's other ranks, whose folders may differ.
    explicit RenderJob(const Options& options, bool writes_files = true);

    [[nodiscard]] std::size_t frame_count() const { return clocks_.size(); }
    /// The number in a frame's file name; -1 when there is only one frame.
    [[nodiscard]] int frame_number(std::size_t frame) const;
    /// Loads the frame's scene (SceneError); the importer's notes go to
    /// stderr unless `quiet_notes`.
    [[nodiscard]] Scene load_frame(std::size_t frame, bool quiet_notes) const;
    /// The frame's render settings: the options over the scene's own.
    [[nodiscard]] RenderSettings settings_for(const Scene& scene) const;

    /// --threads: render threads per process, 0 for all cores.
    [[nodiscard]] int threads() const;
    [[nodiscard]] const ImageOutput& output() const { return output_; }
    /// Writes the frame's image, then prints the scene's warnings (for frame
    /// 0 only: every frame has the same) and, unless quiet, the summary line.
    void write_frame(std::size_t frame, const Image& image, const RenderStats& stats) const;
    [[nodiscard]] bool quiet() const { return quiet_; }
    /// --tile-log's file, when given.
    [[nodiscard]] const std::optional<std::filesystem::path>& tile_log() const { return tile_log_; }

private:
    const Options& options_;
    std::optional<std::filesystem::path> scene_file_;
    std::vector<double> clocks_;
    ImageOutput output_;
    bool quiet_ = false;
    std::optional<std::filesystem::path> tile_log_;
};

/// The option names `zeroset render` takes a value for.
std::vector<std::string> render_valued_options();

}  // namespace zeroset::cli
