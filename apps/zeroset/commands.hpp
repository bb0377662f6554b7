// The program's subcommands. Each returns the process exit status:
// 0 success, 1 a failure (bad scene, render error, unwritable output), 2 bad usage.
#pragma once

#include <string>
#include <vector>

namespace zeroset::cli {

int render_command(const std::vector<std::string>& args);
int basins_command(const std::vector<std::string>& args);
int ray_command(const std::vector<std::string>& args);
int slice_command(const std::vector<std::string>& args);
int mesh_command(const std::vector<std::string>& args);
int import_command(const std::vector<std::string>& args);

}  // namespace zeroset::cli
