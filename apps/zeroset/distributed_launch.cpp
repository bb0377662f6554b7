// Whether an MPI launcher started this process as one of several, and as
// which rank: Open MPI's mpirun sets OMPI_COMM_WORLD_SIZE and _RANK,
// PMI-based launchers PMI_ or PMIX_SIZE and _RANK. Read from the
// environment, so that a single process never starts MPI (nor pays for it).
#include <cstdlib>
#include <optional>
#include <string>

#include "distributed_launch.hpp"

namespace zeroset::cli {

namespace {

/// The launcher's number `what` (SIZE or RANK) for this process, if set.
std::optional<int> launcher_number(const std::string& what) {
    for (const char* prefix : {"OMPI_COMM_WORLD_", "PMI_", "PMIX_"})
        if (const char* value = std::getenv((prefix + what).c_str())) return std::atoi(value);
    return std::nullopt;
}

}  // namespace

bool distributed_launch() { return launcher_number("SIZE").value_or(1) > 1; }

int launched_rank() { return launcher_number("RANK").value_or(0); }

}  // namespace zeroset::cli
