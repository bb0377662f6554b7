// `zeroset ray`: one ray through one object, asked of every intersection
// method — the survey's comparison on its own worked example (§§2–5), and a
// tool to see why a method misses a hit on any ray. Everything is checked
// before any output; the plot is written atomically.
#include <charconv>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <optional>
#include <string>
#include <vector>

#include "commands.hpp"
#include "options.hpp"
#include "scene_input.hpp"
#include "ray_list.hpp"
#include "ray_options.hpp"
#include "ray_plot.hpp"
#include "zeroset/render/camera_rays.hpp"
#include "zeroset/render/ray_report.hpp"
#include "zeroset/scene/load_scene.hpp"

namespace zeroset::cli {

namespace {

constexpr const char* ray_usage = R"usage(Usage: zeroset ray [SCENE] [options]

Casts one ray r(t) = origin + t*dir through one object of SCENE and asks every
intersection method for the first hit and for all hits in the span [t0, t1]
where the ray is inside the object's bounds (from t = 0), shrunk by interval
analysis to where the surface can be (a plane without bounds: a box about
where the ray meets it, see docs/ray-command.md). For each method it
prints the hits, the function evaluations each query spent and how it ended:
ok, no hit, failed (the method gave up, or is not available: the message is
shown) or diverged (Newton's iterates ran away).

Without SCENE, uses the built-in default scene's first object, "blobs" (the
survey's two blended spheres, Figure 1), and the survey's ray:
origin -4.905,-0.67,0.364 and dir 0.981,0.174,0.0872. With a SCENE file,
--origin and --dir (or --rays) are required.

The direction is used as given, not normalised: t counts multiples of dir.
(The survey's t values are for its direction, which is not quite unit length.)

Options:
  --origin X,Y,Z      the ray's origin
  --dir X,Y,Z         the ray's direction (not zero; used as given)
  --object NAME       the object to intersect (default: the scene's first)
  --pixel X,Y         the camera's ray through the centre of pixel (X, Y) of
                      the scene's image (its own size; 0,0 is the top left):
                      what `zeroset render` traces there at 1 spp
  --method M|all      one method or all of them (default: all): auto, sphere,
                      interval, lg, polynomial, newton, regula_falsi,
                      bisection; auto is
                      shown with the method it stands for, e.g. "auto (sphere)"
  --newton-from T0    start Newton's method at t = T0 (default: t0, the span's start)
  --json              print one JSON object per ray instead of the table
  --rays FILE         the rays to cast, one per line: "ox oy oz dx dy dz"
                      (blank lines and # comments allowed); with --json, one
                      JSON object per line (JSON Lines)
  --plot FILE.svg     also draw H(t) over the span: the graph, each method's
                      hits, the interval method's boxes (Fig. 10) and, with
                      --newton-from, Newton's iterates (Fig. 4); one ray only
  --compare SCENE     with --plot: also draw, dashed, H of SCENE's object along
                      the same ray (Fig. 8 compares soft objects with Blinn's)
  --compare-object NAME
                      which object of the --compare scene (default: its first)
  -h, --help          this text

Evaluations are TraceCounters::evaluations(): point evaluations of f plus
interval and gradient enclosures, counted separately for the first-hit query
and the all-hits query. See docs/ray-command.md for the formats.
)usage";

/// The methods to run: all (auto first, as all_methods() lists them) or one.
std::vector<Method> chosen_methods(const Options& options) {
    if (options.value("--method").value_or("all") == "all") return {all_methods().begin(), all_methods().end()};
    return {*options.choice("--method", "method", all_methods(), method_name)};
}

/// --pixel X,Y: the camera ray through the centre of that pixel of the scene's image.
Ray pixel_ray(const Scene& scene, const std::string& text) {
    const auto comma = text.find(',');
    const auto whole = [&](std::string_view part, int size, const char* axis) {
        int v = -1;
        const auto [end, error] = std::from_chars(part.data(), part.data() + part.size(), v);
        if (error != std::errc{} || end != part.data() + part.size() || v < 0 || v >= size)
            throw UsageError("--pixel " + text + ": " + axis + " must be a whole number from 0 to " +
                             std::to_string(size - 1) + " (the scene's image is " + std::to_string(scene.image.width) +
                             "x" + std::to_string(scene.image.height) + ")");
        return v;
    };
    if (comma == std::string::npos) throw UsageError("--pixel takes X,Y, e.g. --pixel 320,240");
    const std::string_view all = text;
    const int px = whole(all.substr(0, comma), scene.image.width, "X");
    const int py = whole(all.substr(comma + 1), scene.image.height, "Y");
    return CameraRays(scene.camera, scene.image.width, scene.image.height).ray(px, py, 0.5, 0.5);
}

/// The rays to cast: from --rays, --pixel, or --origin/--dir (the survey's ray for the default scene).
std::vector<Ray> chosen_rays(const Options& options, const Scene& scene, bool default_scene) {
    const auto origin = vector_option(options, "--origin");
    const auto dir = vector_option(options, "--dir");
    if (const auto pixel = options.value("--pixel")) {
        if (origin || dir || options.value("--rays")) throw UsageError("give --pixel, --rays or --origin/--dir, one of them");
        return {pixel_ray(scene, *pixel)};
    }
    if (const auto file = options.value("--rays")) {
        if (origin || dir) throw UsageError("give --rays or --origin/--dir, not both");
        if (options.value("--plot")) throw UsageError("--plot draws one ray; it cannot be used with --rays");
        return read_ray_list(*file);
    }
    if (!default_scene && (!origin || !dir))
        throw UsageError("with a scene file, give the ray: --origin X,Y,Z and --dir X,Y,Z (or --pixel X,Y, or --rays FILE)");
    const Ray ray{origin.value_or(survey_origin), dir.value_or(survey_dir)};
    if (ray.dir == Vec3d{}) throw UsageError("option --dir must not be zero");
    return {ray};
}

}  // namespace

int ray_command(const std::vector<std::string>& args) {
    const Options options(args, {"--origin", "--dir", "--object", "--method", "--newton-from", "--rays", "--plot",
                                 "--compare", "--compare-object", "--pixel", "--include-path"},
                          {"-h", "--help", "--json"});
    if (options.has("-h") || options.has("--help")) {
        std::fputs(ray_usage, stdout);
        return 0;
    }
    if (options.positional().size() > 1) throw UsageError("ray takes at most one scene file");
    const std::optional<std::filesystem::path> plot_file = options.value("--plot");
    if (plot_file && plot_file->extension() != ".svg")
        throw UsageError("--plot writes SVG: give a file name ending in .svg, not '" + plot_file->string() + "'");
    const bool default_scene_used = options.positional().empty();
    const std::vector<Method> methods = chosen_methods(options);
    const std::optional<double> newton_from = number_option(options, "--newton-from");

    const Scene scene = default_scene_used ? default_scene() : load_scene_file(options.positional()[0], options);
    const std::vector<Ray> rays = chosen_rays(options, scene, default_scene_used);
    const PlacedObject placed = find_object(scene, options.value("--object"));
    const RaySubject subject{default_scene_used ? "<default>" : options.positional()[0], placed.name(), newton_from};

    const ObjectProbe probe_object(placed, newton_from);

    // --compare: another scene's object, drawn along the same ray.
    std::optional<Scene> compare_scene;
    std::optional<Tape> compare_tape;
    std::optional<ComparedFunction> compared;
    if (const auto file = options.value("--compare")) {
        if (!plot_file) throw UsageError("--compare adds a curve to the plot: give --plot too");
        compare_scene = load_scene_file(*file, options);
        const PlacedObject other = find_object(*compare_scene, options.value("--compare-object"));
        if (!other.to_scene.is_identity() || !placed.to_scene.is_identity())
            throw UsageError("--compare draws both objects along one ray: neither may be transformed");
        compare_tape.emplace(surface_of(other.object()));
        const std::string file_name = std::filesystem::path(*file).filename().string();
        compared = ComparedFunction{
            "H of " + (other.name().empty() ? file_name : other.name() + " (" + file_name + ")"), &*compare_tape};
    } else if (options.value("--compare-object")) {
        throw UsageError("--compare-object names an object of the --compare scene: give --compare too");
    }

    std::string output;
    for (const Ray& ray : rays) {
        const RayProbe probe = probe_object.probe(ray, methods);
        if (plot_file) {
            if (!probe.span) throw std::runtime_error("cannot plot: the ray misses the object's bounds");
            write_svg_plot(ray_plot(subject, probe, probe_object.tape(), compared), *plot_file);
            std::fprintf(stderr, "zeroset: wrote %s\n", plot_file->string().c_str());
        }
        if (options.has("--json")) output += ray_report_json(subject, probe) + "\n";
        else output += (output.empty() ? "" : "\n") + ray_report_text(subject, probe);
    }
    std::fputs(output.c_str(), stdout);
    return 0;
}

}  // namespace zeroset::cli
