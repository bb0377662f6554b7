// `zeroset render`: load a scene (or the built-in default), render it and
// write the image. Everything that can be checked before rendering —
// options, the output's format and place, the scene — is checked first, and
// the image is written atomically, so a failure never leaves a partial file.
#include <cstdio>
#include <string>

#include "commands.hpp"
#include "distributed_launch.hpp"
#include "image_output.hpp"
#include "options.hpp"
#include "progress_bar.hpp"
#include "render_job.hpp"
#include "scene_input.hpp"
#include "zeroset/io/image_writer.hpp"
#include "zeroset/render/renderer.hpp"

namespace zeroset::cli {

namespace {

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
  --frustum-culling C on (default) or off: cull each 16x16 tile's frustum
                      against the partitioned objects by interval analysis
                      before their camera rays are traced, prove tiles free
                      of polynomial surfaces (their Bernstein form over the
                      tile), list the components of blobs each tile may
                      meet, and leave tiles proven to show nothing to the
                      background, untraced (docs/methods.md)
  --max-evaluations N stop with an error once the render has spent N
                      evaluations of the surfaces (default: 16384 per camera
                      ray, at least 4194304; see docs/limits.md)
  --clock C           the value of the scene's `clock` (default 0)
  --frames N          an animation: N frames with `clock` running from 0 to 1,
                      written as OUT_0000.png, OUT_0001.png, … (OUT's name with
                      the frame number before its extension)
  --tile-log FILE     write what every 16x16 tile cost (place, rank, seconds,
                      evaluations) to FILE as CSV
)" + scene_input_help() + R"(  -q, --quiet         no progress bar and no summary line
  -h, --help          this text

A progress bar is drawn on stderr when it is a terminal; a one-line summary
(size, time, rays, hits, function evaluations) is printed at the end.

Under mpirun (mpirun -n N zeroset render …), the ranks share the tiles and
frames and rank 0 writes the same image one process would; see
docs/distributed.md.
)";
}

}  // namespace

int render_command(const std::vector<std::string>& args) {
    const Options options(args, render_valued_options(), {"-h", "--help", "-q", "--quiet"});
    if (options.has("-h") || options.has("--help")) {
        std::fputs(render_usage().c_str(), stdout);
        return 0;
    }
    if (distributed_launch() && (options.value("-o") == "-" || options.value("--output") == "-"))
        throw UsageError("under mpirun, write the image to a file (-o FILE): mpirun gives each rank a terminal as "
                         "standard output, not the pipe it was started with");
    const RenderJob job(options, launched_rank() == 0);  // only rank 0 writes
    if (distributed_launch()) return render_distributed(job);
    TileLog log;
    for (std::size_t frame = 0; frame < job.frame_count(); ++frame) {
        const int number = job.frame_number(frame);
        if (frame > 0) job.output().check(number);
        const Scene scene = job.load_frame(frame, job.quiet() || frame > 0);
        RenderSettings settings = job.settings_for(scene);
        ProgressBar bar;
        if (!job.quiet() && bar.enabled()) {
            settings.on_progress = [&bar](int done, int total) { bar.update(done, total); };
            settings.on_prepare_progress = [&bar](int done, int total) { bar.update(done, total, "building octree"); };
        }
        if (job.tile_log())
            settings.on_tile = [&log, frame](const TileRect& tile, const TileWork& work) { log.add(frame, 0, tile, work); };
        RenderResult result = [&] {
            try {
                return render(scene, settings);
            } catch (...) {
                bar.finish();
                throw;
            }
        }();
        bar.finish();
        job.write_frame(frame, result.image, result.stats);
    }
    if (job.tile_log()) log.write(*job.tile_log());
    return 0;
}

}  // namespace zeroset::cli
