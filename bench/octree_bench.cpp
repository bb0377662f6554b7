// Octree builds (accel/octree.hpp) per model, depth and thread count: time,
// cells, memory, clauses a cell against the full tape, and the cells' median
// Lipschitz bound. bear.vm over the bounds of bench/scenes/bear.zs;
// prospero.vm (a 2-D model) over a slab of its ±1 square.
#include <benchmark/benchmark.h>

#include <fstream>
#include <string>

#include "zeroset/accel/octree.hpp"
#include "zeroset/expr/vm_import.hpp"

namespace {

using zeroset::Box3;
using zeroset::Tape;

Tape load(const std::string& name) {
    std::ifstream in(std::string(ZEROSET_MODELS_DIR) + "/" + name);
    return Tape(zeroset::import_vm(in));
}

void build(benchmark::State& state, const Tape& tape, const Box3& box, zeroset::Partition rule) {
    zeroset::OctreeSettings settings;
    settings.rule = rule;
    settings.max_depth = static_cast<int>(state.range(0));
    settings.threads = static_cast<int>(state.range(1));
    zeroset::OctreeStats stats;
    for (auto _ : state) {
        const zeroset::Octree octree(tape, box, settings);
        stats = octree.stats();
        benchmark::DoNotOptimize(stats.cells);
    }
    state.counters["cells"] = static_cast<double>(stats.cells);
    state.counters["MB"] = static_cast<double>(stats.bytes) / 1e6;
    state.counters["clauses_per_cell"] = stats.mean_cell_clauses;
    state.counters["full_clauses"] = static_cast<double>(stats.full_clauses);
    state.counters["median_L"] = stats.median_lipschitz;
    state.counters["unbounded_cells"] = static_cast<double>(stats.unbounded_cells);
}

void BM_OctreeBear(benchmark::State& state) {
    static const Tape tape = load("bear.vm");
    build(state, tape, {{-0.7, -0.65, -0.75}, {1.05, 0.9, 0.7}}, zeroset::Partition::Lipschitz);
}
void BM_OctreeBearVertexSign(benchmark::State& state) {
    static const Tape tape = load("bear.vm");
    build(state, tape, {{-0.7, -0.65, -0.75}, {1.05, 0.9, 0.7}}, zeroset::Partition::VertexSign);
}
void BM_OctreeProspero(benchmark::State& state) {
    static const Tape tape = load("prospero.vm");
    build(state, tape, {{-1, -1, -0.01}, {1, 1, 0.01}}, zeroset::Partition::Lipschitz);
}

// {depth, threads}
BENCHMARK(BM_OctreeBear)->Args({4, 2})->Args({5, 2})->Args({6, 1})->Args({6, 2})->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_OctreeBearVertexSign)->Args({5, 2})->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_OctreeProspero)->Args({4, 2})->Args({5, 2})->Args({6, 2})->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
