// `zeroset render`: load a scene (or the built-in default), render it and
// write the image. Everything that can be checked before rendering —
// options, the output's format and place, the scene — is checked first, and
// the image is written atomically, so a failure never leaves a partial file.
#include <cstdio>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>

#include "commands.hpp"
#include "image_output.hpp"
#include "options.hpp"
#include "progress_bar.hpp"
#include "ray_options.hpp"
#include "scene_input.hpp"
#include "zeroset/io/image_writer.hpp"
#include "zeroset/render/renderer.hpp"
#include "zeroset/scene/load_scene.hpp"

namespace zeroset::cli {

namespace {

/// The most frames one render command makes.
constexpr int max_frames = 100000;

std::string render_usage() {
    return R"(Usage: zeroset render [SCENE] [options]

Renders SCENE (a .zs file, or a POV-Ray .pov scene: docs/povray.md) to an
image. Without SCENE, renders the built-in
default scene: the survey's Figure 1, two unit spheres at (±1.2, 0, 0)
blended as Blinn's blobs, h = 1 − e^(−f) − e^(−g) (eq. 12), over a floor
(the text of scenes/hart1993/blinn_blobs.zs).

Options:
)" + image_output_help("the scene file's name with .png, in the current\n                      directory (zeroset.png for the built-in scene)") + R"(  --width W           image width in pixels (default: the scene's, else 640)
  --height H          image height in pixels (default: the scene's, else 480)
  --spp N             samples per pixel, stratified (default: the scene's, else 1)
  --antialias A       how edges are antialiased: samples (by --spp alone) or
                      cone (one ray per pixel widened to the cone of its
                      footprint, Hart 1993; needs --spp 1; see
                      docs/antialiasing.md); default: the scene's, else samples
  --threads N         render threads (default: all cores)
  --method M          intersect every object with method M instead of its own:
                      auto, sphere, interval, lg, polynomial, newton,
                      regula_falsi, bisection (see docs/methods.md)
  --solver S          the polynomial method's root solver for every object:
                      closed, sturm, descartes, laguerre, fast (default: the
                      object's, else fast)
  --normals N         how every object's normals are computed: analytic (the
                      exact gradient, eq. 33), fd (forward differences, eq. 34)
                      or central (central differences); default: the object's,
                      else analytic (see docs/rendering.md#normals)
  --partition P       spatial partitioning of every object's bounds: auto,
                      none, lipschitz (Kalra-Barr octree), vertex-sign
                      (Bloomenthal's octree) or seed-fill (Bloomenthal's
                      surface tracking); default: the object's, else auto
                      (lipschitz for the interval, lg and sphere methods on
                      tapes of 64 clauses or more; see docs/methods.md)
  --max-evaluations N stop with an error once the render has spent N
                      evaluations of the surfaces (default: 16384 per camera
                      ray, at least 4194304; see docs/limits.md)
  --clock C           the value of the scene's `clock` (default 0)
  --frames N          an animation: N frames with `clock` running from 0 to 1,
                      written as OUT_0000.png, OUT_0001.png, … (OUT's name with
                      the frame number before its extension)
)" + scene_input_help() + R"(  -q, --quiet         no progress bar and no summary line
  -h, --help          this text

A progress bar is drawn on stderr when it is a terminal; a one-line summary
(size, time, rays, hits, function evaluations) is printed at the end.
)";
}

/// The render's settings from the options, defaulting to the scene's.
RenderSettings settings_for(const Options& options, const Scene& scene, bool layers) {
    RenderSettings settings;
    settings.width = options.integer("--width").value_or(scene.image.width);
    settings.height = options.integer("--height").value_or(scene.image.height);
    settings.samples_per_pixel = options.integer("--spp").value_or(scene.image.samples_per_pixel);
    settings.threads = options.integer("--threads").value_or(0);
    settings.cone_antialiasing = scene.image.cone_antialiasing;
    if (const auto antialias = options.value("--antialias")) {
        try {
            settings.cone_antialiasing = cone_antialiasing_named(*antialias);
        } catch (const std::invalid_argument& e) {
            throw UsageError(e.what());
        }
    }
    settings.layers = layers;
    settings.method = options.choice("--method", "method", all_methods(), method_name);
    settings.solver = options.choice("--solver", "polynomial solver", all_polynomial_solvers(), polynomial_solver_name);
    settings.normals = options.choice("--normals", "normal mode", all_normal_modes(), normal_mode_name);
    settings.partition = options.choice("--partition", "partition", all_partitions(), partition_name);
    settings.max_evaluations = options.count("--max-evaluations");
    validate(settings);
    return settings;
}

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

Scene load(const std::optional<std::filesystem::path>& scene_file, const Options& options, double clock, bool quiet) {
    return scene_file ? load_scene_file(*scene_file, options, clock, quiet) : default_scene();
}

}  // namespace

int render_command(const std::vector<std::string>& args) {
    std::vector<std::string> valued = {"--width",     "--height",    "--spp",    "--antialias", "--threads",         "--method",
                                       "--solver",    "--normals",   "--partition", "--max-evaluations", "--frames",
                                       "--clock"};
    valued.insert(valued.end(), scene_input_options.begin(), scene_input_options.end());
    valued.insert(valued.end(), image_output_options.begin(), image_output_options.end());
    const Options options(args, valued, {"-h", "--help", "-q", "--quiet"});
    if (options.has("-h") || options.has("--help")) {
        std::fputs(render_usage().c_str(), stdout);
        return 0;
    }
    if (options.positional().size() > 1) throw UsageError("render takes at most one scene file");

    const std::optional<std::filesystem::path> scene_file =
        options.positional().empty() ? std::nullopt : std::optional(std::filesystem::path(options.positional()[0]));
    const std::vector<double> clocks = frame_clocks(options);
    if (!scene_file && (options.value("--clock") || options.value("--frames")))
        throw UsageError("--clock and --frames animate a scene file; the built-in scene has no clock");
    const ImageOutput output(options, scene_file ? scene_file->stem().string() + ".png" : "zeroset.png",
                             static_cast<int>(clocks.size()));
    const bool quiet = options.has("-q") || options.has("--quiet");
    const bool layers = output.format() == ImageFormat::Exr;

    for (std::size_t frame = 0; frame < clocks.size(); ++frame) {
        const int number = clocks.size() > 1 ? static_cast<int>(frame) : -1;
        if (frame > 0) output.check(number);
        const Scene scene = load(scene_file, options, clocks[frame], quiet || frame > 0);
        RenderSettings settings = settings_for(options, scene, layers);
        ProgressBar bar;
        if (!quiet && bar.enabled()) {
            settings.on_progress = [&bar](int done, int total) { bar.update(done, total); };
            settings.on_prepare_progress = [&bar](int done, int total) { bar.update(done, total, "building octree"); };
        }
        RenderResult result = [&] {
            try {
                return render(scene, settings);
            } catch (...) {
                bar.finish();
                throw;
            }
        }();
        bar.finish();
        output.write(result.image, number);
        if (frame == 0)  // the same scene's warnings for every frame: once is enough
            for (const std::string& warning : result.stats.warnings) std::fprintf(stderr, "zeroset: warning: %s\n", warning.c_str());
        if (!quiet)
            std::fprintf(stderr, "zeroset: wrote %s — %s\n", output.name(number).c_str(),
                         summary_line(result.stats).c_str());
    }
    return 0;
}

}  // namespace zeroset::cli
