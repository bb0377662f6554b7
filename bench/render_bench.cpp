// Whole-render time of the built-in default scene (the survey's Figure 1) at
// 800×600, one sample per pixel, with one thread and with all threads.
#include <benchmark/benchmark.h>

#include <thread>

#include "zeroset/render/renderer.hpp"
#include "zeroset/scene/load_scene.hpp"

namespace {

void BM_RenderDefaultScene(benchmark::State& state) {
    const zeroset::Scene scene = zeroset::default_scene();
    zeroset::RenderSettings settings;
    settings.width = 800;
    settings.height = 600;
    settings.samples_per_pixel = 1;
    settings.threads = static_cast<int>(state.range(0));
    zeroset::RenderStats stats;
    for (auto _ : state) stats = zeroset::render(scene, settings).stats;
    state.counters["rays"] = static_cast<double>(stats.camera_rays + stats.shadow_rays);
    state.counters["evaluations"] =
        static_cast<double>(stats.counters.evaluations());
}
BENCHMARK(BM_RenderDefaultScene)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(3.0);

}  // namespace

BENCHMARK_MAIN();
