// A rank other than 0 in a distributed render: it loads the scene from the
// files rank 0 sent, traces the tiles rank 0 hands it, and sends them back,
// until rank 0 says the job is done or has failed.
#pragma once

#include <string_view>

#include "../render_job.hpp"

namespace zeroset::cli {

/// Runs the rank's part; returns its exit status: 0, also when the job
/// failed, which rank 0 reports and ends with its own status.
/// `files` is the packed FileSnapshot rank 0 broadcast.
int run_worker_rank(const RenderJob& job, std::string_view files);

}  // namespace zeroset::cli
