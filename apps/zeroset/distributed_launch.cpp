// Whether an MPI launcher started this process as one of several: Open
// MPI's mpirun sets OMPI_COMM_WORLD_SIZE, PMI-based launchers PMI_SIZE or
// PMIX_SIZE. Read from the environment, so that a single process never
// starts MPI (nor pays for it).
#include <cstdlib>

#include "distributed_launch.hpp"

namespace zeroset::cli {

bool distributed_launch() {
    for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_SIZE"})
        if (const char* size = std::getenv(name); size && std::atoi(size) > 1) return true;
    return false;
}

}  // namespace zeroset::cli
