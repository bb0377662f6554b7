// Formatting of the render summary.
#include "zeroset/render/render_stats.hpp"

#include <cstdio>

namespace zeroset {

namespace {
std::string count(std::uint64_t n) {
    char buffer[32];
    if (n >= 10'000'000) std::snprintf(buffer, sizeof buffer, "%.1fM", static_cast<double>(n) / 1e6);
    else std::snprintf(buffer, sizeof buffer, "%llu", static_cast<unsigned long long>(n));
    return buffer;
}
}  // namespace

std::string summary_line(const RenderStats& s) {
    char buffer[512];
    std::snprintf(buffer, sizeof buffer,
                  "%dx%d, %d spp, %d thread%s: %.3f s (prepare %.3f s, trace %.3f s); %s rays (%s camera, %s shadow%s), "
                  "%s hits; %s evaluations (%s point, %s interval, %s gradient)",
                  s.width, s.height, s.samples_per_pixel, s.threads, s.threads == 1 ? "" : "s", s.seconds,
                  s.prepare_seconds, s.seconds - s.prepare_seconds,
                  count(s.rays()).c_str(), count(s.camera_rays).c_str(), count(s.shadow_rays).c_str(),
                  s.reflection_rays ? (", " + count(s.reflection_rays) + " reflection").c_str() : "",
                  count(s.hits).c_str(),
                  count(s.counters.evaluations()).c_str(), count(s.counters.point_evaluations).c_str(),
                  count(s.counters.interval_evaluations).c_str(), count(s.counters.gradient_evaluations).c_str());
    std::string line = buffer;
    if (s.counters.failed_queries > 0)
        line += "; " + count(s.counters.failed_queries) + " ray queries failed (a method's budget spent: no hit there)";
    if (s.cone_antialiasing) {
        const ConeCounters& c = s.cone;
        line += "; cone antialiasing: " + count(c.edges) + " edges (" + count(c.aimed_rays) +
                " rays aimed across them), " + count(c.steps) + " steps, " + count(c.evaluations) + " evaluations";
        if (c.missed_edges) line += ", " + count(c.missed_edges) + " edges no surface reached into";
        if (c.gave_up) line += ", " + count(c.gave_up) + " cones stopped at their step limit";
    }
    if (!s.methods.empty()) {
        line += "; objects:";
        for (std::size_t i = 0; i < s.methods.size(); ++i)
            line += (i == 0 ? " " : ", ") + s.methods[i].first + " " + std::to_string(s.methods[i].second);
    }
    if (!s.partitions.empty()) {
        char cells[64];
        const std::uint64_t rays = s.rays();
        std::snprintf(cells, sizeof cells, "%.2f", rays ? static_cast<double>(s.counters.cell_visits) / static_cast<double>(rays) : 0.0);
        line += "; " + s.partitions + "; " + cells + " cells a ray";
    }
    if (!s.blobs.empty()) {
        char kernels[64];
        const std::uint64_t rays = s.rays();
        std::snprintf(kernels, sizeof kernels, "%.2f", rays ? static_cast<double>(s.counters.blob_kernels) / static_cast<double>(rays) : 0.0);
        line += "; " + s.blobs + "; " + kernels + " blob components a ray";
    }
    return line;
}

}  // namespace zeroset
