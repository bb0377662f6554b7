// The one-line render summary names size, time, rays, hits and evaluations.
#include <gtest/gtest.h>

#include "zeroset/render/render_stats.hpp"

namespace zeroset {
namespace {

TEST(RenderSummary, NamesEveryFigure) {
    RenderStats s;
    s.width = 800;
    s.height = 600;
    s.samples_per_pixel = 4;
    s.threads = 2;
    s.seconds = 1.5;
    s.prepare_seconds = 0.25;
    s.methods = {{"polynomial", 3}, {"plane", 1}};
    s.camera_rays = 1920000;
    s.shadow_rays = 1000;
    s.hits = 12345;
    s.counters.point_evaluations = 50'000'000;
    s.counters.interval_evaluations = 7;
    const std::string line = summary_line(s);
    EXPECT_NE(line.find("800x600"), std::string::npos) << line;
    EXPECT_NE(line.find("4 spp"), std::string::npos) << line;
    EXPECT_NE(line.find("2 threads"), std::string::npos) << line;
    EXPECT_NE(line.find("1.500 s (prepare 0.250 s, trace 1.250 s)"), std::string::npos) << line;
    EXPECT_NE(line.find("objects: polynomial 3, plane 1"), std::string::npos) << line;
    EXPECT_EQ(line.find("failed"), std::string::npos) << line;
    s.counters.failed_queries = 4;
    EXPECT_NE(summary_line(s).find("; 4 ray queries failed"), std::string::npos) << summary_line(s);
    EXPECT_NE(line.find("1921000 rays"), std::string::npos) << line;
    EXPECT_NE(line.find("12345 hits"), std::string::npos) << line;
    EXPECT_NE(line.find("50.0M evaluations"), std::string::npos) << line;
}

}  // namespace
}  // namespace zeroset
