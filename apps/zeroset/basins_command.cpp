// `zeroset basins`: the survey's Figure 5 — which root Newton's method
// (eq. 22) reaches from every start value t₀ of a rectangle of the complex
// plane, for one object along one ray. Options, the scene and the output
// name are all checked before any work, and the image is written atomically.
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "commands.hpp"
#include "options.hpp"
#include "zeroset/io/image_writer.hpp"
#include "zeroset/render/newton_basins.hpp"
#include "zeroset/scene/load_scene.hpp"

namespace zeroset::cli {

namespace {

constexpr const char* basins_usage = R"(Usage: zeroset basins [SCENE] [options]

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
  -o, --output FILE   the image to write (.png, .ppm or .pfm; default: basins.png)
  -h, --help          this text
)";

/// The option's value as `count` comma-separated finite numbers, or nothing when absent.
std::optional<std::vector<double>> numbers(const Options& options, const std::string& name, std::size_t count) {
    const auto text = options.value(name);
    if (!text) return std::nullopt;
    std::vector<double> result;
    const char* p = text->data();
    const char* const end = p + text->size();
    while (true) {
        double value = 0.0;
        const auto [next, error] = std::from_chars(p, end, value);
        if (error != std::errc() || !std::isfinite(value)) break;
        result.push_back(value);
        p = next;
        if (p == end || *p != ',') break;
        ++p;
    }
    if (p != end || result.size() != count)
        throw UsageError("option " + name + " needs " + std::to_string(count) +
                         " finite numbers separated by commas, got '" + *text + "'");
    return result;
}

std::optional<Vec3d> vector_option(const Options& options, const std::string& name) {
    const auto v = numbers(options, name, 3);
    if (!v) return std::nullopt;
    return Vec3d{(*v)[0], (*v)[1], (*v)[2]};
}

/// Overrides [lo, hi] from a `MIN,MAX` option.
void read_range(const Options& options, const std::string& name, double& lo, double& hi) {
    if (const auto v = numbers(options, name, 2)) {
        lo = (*v)[0];
        hi = (*v)[1];
        if (!(lo < hi)) throw UsageError("option " + name + " needs MIN < MAX, got '" + *options.value(name) + "'");
    }
}

const Object& find_object(const Scene& scene, const std::optional<std::string>& name) {
    if (scene.objects.empty()) throw UsageError("the scene has no objects");
    if (!name) return scene.objects.front();
    std::string names;
    for (const Object& object : scene.objects) {
        if (object.name == *name) return object;
        if (!object.name.empty()) names += (names.empty() ? "'" : ", '") + object.name + "'";
    }
    throw UsageError("the scene has no object named '" + *name + "'" +
                     (names.empty() ? std::string(" (its objects have no names)") : " (it has " + names + ")"));
}

}  // namespace

int basins_command(const std::vector<std::string>& args) {
    const Options options(args,
                          {"-o", "--output", "--object", "--origin", "--dir", "--re", "--im", "--width", "--height",
                           "--iterations", "--threads"},
                          {"-h", "--help"});
    if (options.has("-h") || options.has("--help")) {
        std::fputs(basins_usage, stdout);
        return 0;
    }
    if (options.positional().size() > 1) throw UsageError("basins takes at most one scene file");
    if (options.value("-o") && options.value("--output")) throw UsageError("give -o or --output, not both");
    const std::filesystem::path output = options.value("-o").value_or(options.value("--output").value_or("basins.png"));
    if (const auto problem = image_format_problem(output)) throw UsageError(output.string() + ": " + *problem);

    BasinSettings settings;
    read_range(options, "--re", settings.region.re_min, settings.region.re_max);
    read_range(options, "--im", settings.region.im_min, settings.region.im_max);
    settings.width = options.integer("--width").value_or(settings.width);
    settings.height = options.integer("--height").value_or(settings.height);
    settings.max_iterations = options.integer("--iterations").value_or(settings.max_iterations);
    settings.threads = options.integer("--threads").value_or(settings.threads);
    const Ray ray{vector_option(options, "--origin").value_or(Vec3d{-4.905, -0.67, 0.364}),
                  vector_option(options, "--dir").value_or(Vec3d{0.981, 0.174, 0.0872})};

    const Scene scene = options.positional().empty() ? default_scene() : load_scene(options.positional()[0]);
    const Object& object = find_object(scene, options.value("--object"));
    const BasinMap map = newton_basins(Tape(object.surface), ray, settings);
    write_image(map.image, output);

    std::string roots;
    for (const double t : map.real_roots) {
        char text[32];
        std::snprintf(text, sizeof text, "%s%.6g", roots.empty() ? "" : ", ", t);
        roots += text;
    }
    std::fprintf(stderr, "zeroset: real roots along the ray: %s\n", roots.empty() ? "none" : roots.c_str());
    std::fprintf(stderr, "zeroset: wrote %s (%dx%d)\n", output.string().c_str(), settings.width, settings.height);
    return 0;
}

}  // namespace zeroset::cli
