// The picture `zeroset ray --plot` draws: H(t) over the span, the way the
// survey draws it — the graph (Figs. 2–3), Newton's iterates with their
// tangent lines (Fig. 4), the interval method's boxes (Fig. 10) — and, under
// it, the roots each method found.
#pragma once

#include <optional>
#include <string>

#include "zeroset/render/ray_probe.hpp"
#include "zeroset/render/ray_report.hpp"
#include "zeroset/io/svg_plot.hpp"

namespace zeroset::cli {

/// Another object's H along the same ray, drawn dashed for comparison (the
/// survey's Fig. 8 sets soft objects against Blinn's blobs this way).
struct ComparedFunction {
    std::string label;
    const Tape* tape;
};

/// The plot of one probed ray; the probe must have a span. `tape` is the
/// object's, for sampling H.
Plot ray_plot(const RaySubject& subject, const RayProbe& probe, const Tape& tape,
              const std::optional<ComparedFunction>& compared = std::nullopt);

}  // namespace zeroset::cli
