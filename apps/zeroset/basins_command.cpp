// `zeroset basins`: the survey's Figure 5 — which root Newton's method
// (eq. 22) reaches from every start value t₀ of a rectangle of the complex
// plane, for one object along one ray. Options, the scene and the output
// name are all checked before any work, and the image is written atomically.
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include "commands.hpp"
#include "image_output.hpp"
#include "options.hpp"
#include "scene_input.hpp"
#include "ray_options.hpp"
#include "zeroset/io/image_writer.hpp"
#include "zeroset/render/newton_basins.hpp"
#include "zeroset/scene/load_scene.hpp"

namespace zeroset::cli {

namespace {

std::string basins_usage() {
    return R"(Usage: zeroset basins [SCENE] [options]

Draws the survey's Figure 5: for every start value t0 in a rectangle of the
complex plane, where Newton's method t <- t - H(t)/H'(t) goes, H(t) being the
object's function along the ray origin + t*dir. A start value that converges
to a real root (a ray intersection) is drawn in that root's colour, darker
the more steps it took; one that converges to a complex root is black; one
that diverges (or has not converged after --iterations steps) is white.
The real roots found are printed on stderr.

Without SCENE, uses the built-in default scene's "blobs" (the survey's two
blended spheres) and the survey's ray.

Options:
  --object NAME       the scene object (default: the first)
  --origin X,Y,Z      the ray origin (default: -4.905,-0.67,0.364, the survey's)
  --dir X,Y,Z         the ray direction, used as given, not normalised
                      (default: 0.981,0.174,0.0872, the survey's)
  --re MIN,MAX        the range of Re t0 (default: 0.5,9.1)
  --im MIN,MAX        the range of Im t0 (default: -2.42,2.42)
  --width W           image width in pixels (default: 480)
  --height H          image height in pixels (default: 270)
  --iterations N      Newton steps before giving up (default: 100)
  --threads N         threads (default: all cores)
)" + image_output_help("basins.png") + R"(  -h, --help          this text
)";
}

}  // namespace

int basins_command(const std::vector<std::string>& args) {
    const Options options(args,
                          {"-o", "--output", "--format", "--object", "--origin", "--dir", "--re", "--im", "--width", "--height",
                           "--iterations", "--threads", "--include-path"},
                          {"-h", "--help"});
    if (options.has("-h") || options.has("--help")) {
        std::fputs(basins_usage().c_str(), stdout);
        return 0;
    }
    if (options.positional().size() > 1) throw UsageError("basins takes at most one scene file");
    const ImageOutput output(options, "basins.png");

    BasinSettings settings;
    if (const auto re = range_option(options, "--re")) std::tie(settings.region.re_min, settings.region.re_max) = *re;
    if (const auto im = range_option(options, "--im")) std::tie(settings.region.im_min, settings.region.im_max) = *im;
    settings.width = options.integer("--width").value_or(settings.width);
    settings.height = options.integer("--height").value_or(settings.height);
    settings.max_iterations = options.integer("--iterations").value_or(settings.max_iterations);
    settings.threads = options.integer("--threads").value_or(settings.threads);
    const Ray ray{vector_option(options, "--origin").value_or(survey_origin),
                  vector_option(options, "--dir").value_or(survey_dir)};

    const Scene scene = options.positional().empty() ? default_scene() : load_scene_file(options.positional()[0], options);
    const PlacedObject object = find_object(scene, options.value("--object"));
    const BasinMap map = newton_basins(Tape(surface_of(object.object())), to_object_space(object, ray), settings);
    output.write(map.image);

    std::string roots;
    for (const double t : map.real_roots) {
        char text[32];
        std::snprintf(text, sizeof text, "%s%.6g", roots.empty() ? "" : ", ", t);
        roots += text;
    }
    std::fprintf(stderr, "zeroset: real roots along the ray: %s\n", roots.empty() ? "none" : roots.c_str());
    std::fprintf(stderr, "zeroset: wrote %s (%dx%d)\n", output.name().c_str(), settings.width, settings.height);
    return 0;
}

}  // namespace zeroset::cli
