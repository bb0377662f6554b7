// Rank 0 of a distributed render: a work queue of the job's tiles, frame by
// frame, handed out so that every rank (itself included) keeps a few in
// flight — a rank that finishes early asks for more, so a cheap rank never
// idles while another traces an expensive region. It gathers the tiles
// into each frame's image, writes the images, and reports per rank.
#pragma once

#include <vector>

#include "../render_job.hpp"
#include "zeroset/render/tile_work.hpp"

namespace zeroset::cli {

/// A frame's image size, which gives its tiles (image_tiles).
struct FrameSize {
    int width = 0;
    int height = 0;
};

/// Runs rank 0's part of the job over `ranks` ranks, given every frame's
/// size; returns 0, or throws (after stopping every rank) when any rank failed.
int run_coordinator(const RenderJob& job, int ranks, const std::vector<FrameSize>& frame_sizes);

}  // namespace zeroset::cli
