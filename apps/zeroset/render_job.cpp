// The render command's options, read into a job.
#include "render_job.hpp"

#include <cstdio>
#include <stdexcept>

#include "ray_options.hpp"
#include "scene_input.hpp"
#include "zeroset/scene/load_scene.hpp"

namespace zeroset::cli {

namespace {

/// The most frames one render command makes.
constexpr int max_frames = 100000;

/// The clock of each frame: --clock's value, or 0 → 1 in equal steps over --frames.
std::vector<double> frame_clocks(const Options& options) {
    const int frames = options.integer("--frames").value_or(1);
    if (frames < 1 || frames > max_frames)
        throw UsageError("--frames must be between 1 and " + std::to_string(max_frames) + ", got " +
                         std::to_string(frames));
    const std::optional<double> clock = number_option(options, "--clock");
    if (clock && options.value("--frames")) throw UsageError("give --clock or --frames, not both");
    if (frames == 1) return {clock.value_or(0.0)};
    std::vector<double> clocks;
    for (int i = 0; i < frames; ++i) clocks.push_back(static_cast<double>(i) / (frames - 1));
    return clocks;
}

std::optional<std::filesystem::path> scene_file_of(const Options& options) {
    if (options.positional().size() > 1) throw UsageError("render takes at most one scene file");
    if (options.positional().empty()) return std::nullopt;
    return std::filesystem::path(options.positional()[0]);
}

}  // namespace

std::vector<std::string> render_valued_options() {
    std::vector<std::string> valued = {"--width",     "--height",    "--spp",    "--antialias", "--threads",
                                       "--method",    "--solver",    "--normals", "--partition", "--max-evaluations",
                                       "--frames",    "--clock",     "--tile-log", "--frustum-culling"};
    valued.insert(valued.end(), scene_input_options.begin(), scene_input_options.end());
    valued.insert(valued.end(), image_output_options.begin(), image_output_options.end());
    return valued;
}

RenderJob::RenderJob(const Options& options, bool writes_files)
    : options_(options),
      scene_file_(scene_file_of(options)),
      clocks_(frame_clocks(options)),
      output_(options, scene_file_ ? scene_file_->stem().string() + ".png" : "zeroset.png",
              static_cast<int>(clocks_.size()), writes_files),
      quiet_(options.has("-q") || options.has("--quiet")) {
    if (!scene_file_ && (options.value("--clock") || options.value("--frames")))
        throw UsageError("--clock and --frames animate a scene file; the built-in scene has no clock");
    if (const auto log = options.value("--tile-log")) {
        tile_log_ = *log;
        if (writes_files) TileLog::check(*tile_log_);
    }
}

int RenderJob::frame_number(std::size_t frame) const { return clocks_.size() > 1 ? static_cast<int>(frame) : -1; }

Scene RenderJob::load_frame(std::size_t frame, bool quiet_notes) const {
    return scene_file_ ? load_scene_file(*scene_file_, options_, clocks_[frame], quiet_notes) : default_scene();
}

void RenderJob::write_frame(std::size_t frame, const Image& image, const RenderStats& stats) const {
    const int number = frame_number(frame);
    output_.write(image, number);
    if (frame == 0)
        for (const std::string& warning : stats.warnings) std::fprintf(stderr, "zeroset: warning: %s\n", warning.c_str());
    if (!quiet_)
        std::fprintf(stderr, "zeroset: wrote %s — %s\n", output_.name(number).c_str(), summary_line(stats).c_str());
}

int RenderJob::threads() const { return options_.integer("--threads").value_or(0); }

RenderSettings RenderJob::settings_for(const Scene& scene) const {
    const Options& options = options_;
    RenderSettings settings;
    settings.width = options.integer("--width").value_or(scene.image.width);
    settings.height = options.integer("--height").value_or(scene.image.height);
    settings.samples_per_pixel = options.integer("--spp").value_or(scene.image.samples_per_pixel);
    settings.threads = threads();
    settings.cone_antialiasing = scene.image.cone_antialiasing;
    if (const auto antialias = options.value("--antialias")) {
        try {
            settings.cone_antialiasing = cone_antialiasing_named(*antialias);
        } catch (const std::invalid_argument& e) {
            throw UsageError(e.what());
        }
    }
    settings.layers = output_.format() == ImageFormat::Exr;
    settings.method = options.choice("--method", "method", all_methods(), method_name);
    settings.solver = options.choice("--solver", "polynomial solver", all_polynomial_solvers(), polynomial_solver_name);
    settings.normals = options.choice("--normals", "normal mode", all_normal_modes(), normal_mode_name);
    settings.partition = options.choice("--partition", "partition", all_partitions(), partition_name);
    settings.max_evaluations = options.count("--max-evaluations");
    if (const auto culling = options.value("--frustum-culling")) {
        if (*culling != "on" && *culling != "off")
            throw UsageError("--frustum-culling takes on or off, not '" + *culling + "'");
        settings.frustum_culling = *culling == "on";
    }
    validate(settings);
    return settings;
}

}  // namespace zeroset::cli
