// `zeroset slice`: an image of f on a plane — its sign in black and white, or
// its value as a colour map with the zero contour — for a .vm model or an
// object of a scene. Options and the output name are checked before any
// work, and the image is written atomically.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "commands.hpp"
#include "image_output.hpp"
#include "model_input.hpp"
#include "options.hpp"
#include "ray_options.hpp"
#include "zeroset/expr/batch_lanes.hpp"
#include "zeroset/io/image_writer.hpp"
#include "zeroset/render/slice_image.hpp"
#include "zeroset/scene/file_text.hpp"
#include "zeroset/scene/load_scene.hpp"
#include "zeroset/scene/scene_error.hpp"
#include "zeroset/scene/model_library.hpp"

namespace zeroset::cli {

namespace {

std::string slice_usage() {
    return R"(Usage: zeroset slice INPUT [options]

Draws f on a plane: a square of the plane normal to an axis, sampled at
the pixel centres. INPUT is a .vm model (fidget's format) or a scene file
(.zs, or a POV-Ray .pov with --include-path DIRS for its #includes), whose
object is sliced in its own space (before its transforms).
By default inside (f < 0) is black and outside white; with --shading value,
inside is blue, outside orange, banded by the value of f, and the zero
contour is black. Where f is undefined (NaN) the pixel is magenta.

Tiles whose sign interval arithmetic decides are filled without evaluating
a pixel, and every tile's tape is pruned to the clauses live there (see
docs/slicing.md).

Options:
  --size N            width and height in pixels (default: 1024)
  --axis A            the plane's normal: x, y or z (default: z)
  --at V              where the plane cuts that axis (default: 0 for a .vm
                      model, else the centre of the object's bounds)
  --region MIN,MAX    both in-plane coordinates' range (default: -1,1 for a
                      .vm model, else the object's bounds, made square)
  --shading S         sign or value (default: sign)
  --object NAME       the scene object to slice (default: the first)
  --threads N         threads (default: all cores)
)" + image_output_help("slice.png") + R"(  -q, --quiet         no summary line
  -h, --help          this text
)";
}

int axis_from_name(const std::string& name) {
    if (name == "x") return 0;
    if (name == "y") return 1;
    if (name == "z") return 2;
    throw UsageError("unknown axis '" + name + "' (give x, y or z)");
}

/// The plane from the options, defaulting to the object's bounds when it has them.
SlicePlane plane_from(const Options& options, const std::optional<Box3>& bounds) {
    SlicePlane plane;
    if (const auto axis = options.value("--axis")) plane.axis = axis_from_name(*axis);
    if (bounds) {
        plane.at = 0.5 * (bounds->lo[plane.axis] + bounds->hi[plane.axis]);
        double lo = INFINITY, hi = -INFINITY;
        for (int i = 0; i < 3; ++i) {
            if (i == plane.axis) continue;
            lo = std::min(lo, bounds->lo[i]);
            hi = std::max(hi, bounds->hi[i]);
        }
        plane.min = lo;
        plane.max = hi;
    }
    if (const auto at = number_option(options, "--at")) plane.at = *at;
    if (const auto region = range_option(options, "--region")) std::tie(plane.min, plane.max) = *region;
    return plane;
}

}  // namespace

int slice_command(const std::vector<std::string>& args) {
    const Options options(args, {"-o", "--output", "--format", "--size", "--axis", "--at", "--region", "--shading", "--object",
                                 "--threads", "--include-path"},
                          {"-h", "--help", "-q", "--quiet"});
    if (options.has("-h") || options.has("--help")) {
        std::fputs(slice_usage().c_str(), stdout);
        return 0;
    }
    if (options.positional().size() != 1) throw UsageError("slice takes one .vm model or scene file");
    const ImageOutput output(options, "slice.png");
    SliceShading shading = SliceShading::Sign;
    if (const auto name = options.value("--shading")) {
        if (*name == "value") shading = SliceShading::Value;
        else if (*name != "sign") throw UsageError("unknown shading '" + *name + "' (give sign or value)");
    }

    const ModelInput input = load_model_input(options.positional()[0], options);
    SliceSettings settings;
    settings.plane = plane_from(options, input.bounds);
    settings.size = options.integer("--size").value_or(settings.size);
    settings.threads = options.integer("--threads").value_or(settings.threads);
    settings.every_pixel = shading == SliceShading::Value;

    const Tape tape(input.surface);
    const auto start = std::chrono::steady_clock::now();
    const SliceField field = slice(tape, settings);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const double band = (settings.plane.max - settings.plane.min) / 16.0;
    output.write(slice_image(field, shading, band));

    if (!options.has("-q") && !options.has("--quiet")) {
        const SliceStats& s = field.stats;
        const double pixels = static_cast<double>(field.size) * field.size;
        std::fprintf(stderr,
                     "zeroset: wrote %s (%dx%d) in %.1f ms — %llu tiles by interval, %.1f%% of pixels decided there; "
                     "%llu leaf batches of %.1f clauses on average (full tape %zu clauses, %u slots; leaves at most %u "
                     "slots; %s lanes)\n",
                     output.name().c_str(), field.size, field.size, seconds * 1e3,
                     static_cast<unsigned long long>(s.tiles), 100.0 * static_cast<double>(s.pixels_decided) / pixels,
                     static_cast<unsigned long long>(s.leaf_batches),
                     s.leaf_batches ? static_cast<double>(s.leaf_clauses) / static_cast<double>(s.leaf_batches) : 0.0,
                     s.full_clauses, s.full_slots, s.max_leaf_slots, batch_simd_target().c_str());
    }
    return 0;
}

}  // namespace zeroset::cli
