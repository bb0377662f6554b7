// Whether an MPI launcher started this process as one of several, and as
// which rank: Open MPI's mpirun sets OMPI_COMM_WORLD_SIZE and _RANK,
// PMI-based launchers PMI_ or PMIX_SIZE and _RANK. Read from the
// environment, so that a single process never starts MPI (nor pays for it).
#include <cstdlib>

#include "distributed_launch.hpp"

namespace zeroset::cli {

bool distributed_launch() {
    for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_SIZE"})
        if (const char* size = std::getenv(name); size && std::atoi(size) > 1) return true;
    return false;
}

int launched_rank() {
    for (const char* name : {"OMPI_COMM_WORLD_RANK", "PMI_RANK", "PMIX_RANK"})
        if (const char* rank = std::getenv(name)) return std::atoi(rank);
    return 0;
}

}  // namespace zeroset::cli
