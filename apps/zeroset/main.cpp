// zeroset: the command-line program. Dispatches to subcommands and turns
// every failure into a clear message on stderr and a non-zero exit status.
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "commands.hpp"
#include "distributed_launch.hpp"
#include "interrupts.hpp"
#include "options.hpp"
#include "zeroset/scene/wording.hpp"

namespace {

constexpr const char* usage = R"(zeroset — ray tracing implicit surfaces

Usage:
  zeroset render [SCENE] [options]   render a scene (the built-in default when SCENE is omitted)
  zeroset basins [SCENE] [options]   map where Newton's method converges along a ray (the survey's Figure 5)
  zeroset ray [SCENE] [options]      every intersection method on one ray: hits, evaluations, a plot of H(t)
  zeroset slice INPUT [options]      f on a plane: its sign, or its value with the zero contour
  zeroset mesh INPUT -o OUT.stl      a triangle mesh of the surface (.stl, .obj or .ply)
  zeroset import SCENE.pov           a POV-Ray scene written as a zeroset scene (.zs)
  zeroset --help                     this text
  zeroset COMMAND --help             a command's options
  zeroset --version                  the version

A surface is the zero set of f(x, y, z), negative inside. Scenes are text
files; see docs/scene-language.md. Every command that reads a scene also
reads POV-Ray's (.pov; docs/povray.md).
)";

}  // namespace

int main(int argc, char** argv) {
    zeroset::cli::handle_interrupts();
    const std::vector<std::string> args(argv + 1, argv + argc);
    try {
        if (args.empty() || args[0] == "--help" || args[0] == "-h" || args[0] == "help") {
            std::fputs(usage, args.empty() ? stderr : stdout);
            return args.empty() ? 2 : 0;
        }
        if (args[0] == "--version") {
            std::puts("zeroset " ZEROSET_VERSION);
            std::puts(zeroset::cli::mpi_version_line().c_str());
            return 0;
        }
        const std::vector<std::string> rest(args.begin() + 1, args.end());
        if (args[0] == "render") return zeroset::cli::render_command(rest);
        if (args[0] == "basins") return zeroset::cli::basins_command(rest);
        if (args[0] == "ray") return zeroset::cli::ray_command(rest);
        if (args[0] == "slice") return zeroset::cli::slice_command(rest);
        if (args[0] == "mesh") return zeroset::cli::mesh_command(rest);
        if (args[0] == "import") return zeroset::cli::import_command(rest);
        constexpr std::string_view commands[] = {"render", "basins", "ray", "slice", "mesh", "import"};
        throw zeroset::cli::UsageError("unknown command '" + args[0] + "'" + zeroset::did_you_mean(args[0], commands) +
                                       " (try zeroset --help)");
    } catch (const zeroset::cli::UsageError& e) {
        std::fprintf(stderr, "zeroset: %s\n", e.what());
        return 2;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "zeroset: error: %s\n", e.what());
        return 1;
    }
}
