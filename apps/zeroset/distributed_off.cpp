// A build without MPI: mpirun would start independent copies that each
// render the whole image, so the render refuses and says how to get MPI.
#include "distributed_launch.hpp"

namespace zeroset::cli {

int render_distributed(const RenderJob&) {
    throw UsageError(
        "this zeroset was built without MPI, so under mpirun every process would render the whole image; install "
        "Open MPI (apt-get install libopenmpi-dev openmpi-bin) and rebuild (docs/distributed.md)");
}

std::string mpi_version_line() {
    return "MPI: not built in (install libopenmpi-dev and rebuild for distributed rendering; docs/distributed.md)";
}

}  // namespace zeroset::cli
