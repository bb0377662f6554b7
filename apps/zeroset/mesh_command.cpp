// `zeroset mesh`: a triangle mesh of one object's surface (or a .vm model),
// for 3-D printing and modellers. The output name is checked before any
// work, and the file is written atomically.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "commands.hpp"
#include "model_input.hpp"
#include "options.hpp"
#include "ray_options.hpp"
#include "zeroset/io/mesh_writer.hpp"
#include "zeroset/io/atomic_file.hpp"
#include "zeroset/mesh/polygonize.hpp"

namespace zeroset::cli {

namespace {

constexpr const char* mesh_usage = R"(Usage: zeroset mesh INPUT -o OUT.stl|.obj|.ply [options]

Writes a triangle mesh of the surface f = 0 of INPUT: a .vm model (fidget's
format, meshed over the cube [-1, 1]³ unless --region says otherwise) or a
scene file (.zs, or a POV-Ray .pov with --include-path DIRS for its
#includes), whose object (--object, default its first) is meshed
within its bounds and placed as the scene places it.

The bounds are split as an octree; cells where interval arithmetic proves
f ≠ 0 are dropped, and the rest, down to a grid of RESOLUTION cells a side,
are meshed. A surface closed within the bounds gives a closed (watertight),
consistently oriented mesh; details smaller than a cell may be lost (see
docs/meshes.md).

Methods:
  dual        dual contouring (the default): a vertex for each patch of
              surface in a cell, where its tangent planes meet, so sharp
              corners and edges are kept; every vertex within one cell of a
              cell the surface crosses
  tetrahedra  marching tetrahedra: every vertex on the surface to the
              reported tolerance and the mesh always manifold, but sharp
              edges are cut

Options:
  -o, --output FILE   the mesh to write: .stl (binary), .obj or .ply (binary)
  --resolution R      cells along each side of the bounds: a power of two
                      from 2 to 4096 (default 128)
  --method M          dual or tetrahedra (default dual)
  --object NAME       the scene object to mesh (default: the first)
  --region MIN,MAX    for a .vm model: the cube [MIN, MAX]³ (default -1,1)
  -q, --quiet         no summary line
  -h, --help          this text
)";

/// What the summary can say of where the vertices lie.
std::string accuracy(MeshMethod method, const PolygonizeStats& s) {
    char text[160];
    if (method == MeshMethod::Dual)
        std::snprintf(text, sizeof text, "dual contouring, every vertex within one cell (%.3g) of a cell the surface crosses", s.cell_size);
    else
        std::snprintf(text, sizeof text, "marching tetrahedra, vertices within %.2g of the surface", s.vertex_tolerance);
    return text;
}

}  // namespace

int mesh_command(const std::vector<std::string>& args) {
    const Options options(args, {"-o", "--output", "--resolution", "--method", "--object", "--region", "--include-path"},
                          {"-h", "--help", "-q", "--quiet"});
    if (options.has("-h") || options.has("--help")) {
        std::fputs(mesh_usage, stdout);
        return 0;
    }
    if (options.positional().size() != 1) throw UsageError("mesh takes one .vm model or scene file");
    if (options.value("-o") && options.value("--output")) throw UsageError("give -o or --output, not both");
    const auto given = options.value("-o") ? options.value("-o") : options.value("--output");
    if (!given) throw UsageError("give the mesh to write: -o OUT.stl, .obj or .ply");
    const std::filesystem::path output = *given;
    if (const auto problem = mesh_format_problem(output)) throw UsageError(output.string() + ": " + *problem);
    try {
        const AtomicFile probe(output);  // the place must take a file now, not after the work
    } catch (const FileWriteError& e) {
        throw MeshWriteError(output, e.reason());
    }
    PolygonizeSettings settings;
    settings.resolution = options.integer("--resolution").value_or(settings.resolution);
    if (const auto method = options.choice("--method", "mesh method", std::span<const NamedMeshMethod>(mesh_methods),
                                           [](const NamedMeshMethod& m) { return m.first; }))
        settings.method = method->second;

    const ModelInput input = load_model_input(options.positional()[0], options);
    Box3 box{{-1, -1, -1}, {1, 1, 1}};
    if (const auto region = range_option(options, "--region")) {
        if (input.bounds) throw UsageError("--region is for a .vm model; a scene object is meshed within its bounds");
        box = {{region->first, region->first, region->first}, {region->second, region->second, region->second}};
    } else if (input.bounds) {
        box = *input.bounds;
    } else if (!options.positional()[0].ends_with(".vm")) {  // a scene's object
        throw UsageError("the object has no bounds (a plane, say): a mesh needs a finite region");
    }

    const auto start = std::chrono::steady_clock::now();
    PolygonizeResult result = [&] {
        try {
            return polygonize(Tape(input.surface), box, settings);
        } catch (const std::invalid_argument& e) {
            throw UsageError(e.what());
        }
    }();
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    Mesh& mesh = result.mesh;
    transform_mesh(mesh, input.to_scene);
    write_mesh(mesh, output);
    if (!options.has("-q") && !options.has("--quiet")) {
        const PolygonizeStats& s = result.stats;
        std::fprintf(stderr,
                     "zeroset: wrote %s — %zu triangles, %zu vertices, resolution %d (cells of %.4g) in %.2f s; "
                     "%llu octree cells, %llu with the surface; %s%s\n",
                     output.string().c_str(), mesh.triangles.size(), mesh.vertices.size(), settings.resolution,
                     s.cell_size, seconds, static_cast<unsigned long long>(s.cells_visited),
                     static_cast<unsigned long long>(s.leaf_cells), accuracy(settings.method, s).c_str(),
                     input.to_scene.is_identity() ? "" : " (sizes in the object's own units, before its transforms)");
    }
    return 0;
}

}  // namespace zeroset::cli
