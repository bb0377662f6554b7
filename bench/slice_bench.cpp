// `zeroset slice` without the image: prospero.vm (the Prospero challenge)
// and bear.vm at z = 0 over the ±1 square, on 1 and 2 threads, at 256² and
// 1024² — the tile quadtree, pruned tapes and batch evaluation together.
#include <benchmark/benchmark.h>

#include <fstream>
#include <map>
#include <string>

#include "zeroset/expr/vm_import.hpp"
#include "zeroset/render/slice.hpp"

namespace {

using zeroset::Tape;

const Tape& model_tape(const std::string& name) {
    static std::map<std::string, Tape> tapes;
    auto found = tapes.find(name);
    if (found == tapes.end()) {
        std::ifstream in(std::string(ZEROSET_MODELS_DIR) + "/" + name);
        found = tapes.emplace(name, Tape(zeroset::import_vm(in))).first;
    }
    return found->second;
}

void slice_model(benchmark::State& state, const std::string& model, bool every_pixel) {
    const Tape& tape = model_tape(model);
    zeroset::SliceSettings settings;
    settings.size = static_cast<int>(state.range(0));
    settings.threads = static_cast<int>(state.range(1));
    settings.every_pixel = every_pixel;
    zeroset::SliceStats stats;
    for (auto _ : state) {
        const zeroset::SliceField field = zeroset::slice(tape, settings);
        stats = field.stats;
        benchmark::DoNotOptimize(field.values.data());
    }
    state.counters["tiles"] = static_cast<double>(stats.tiles);
    state.counters["tiles_decided"] = static_cast<double>(stats.tiles_decided);
    state.counters["interval_clauses"] = static_cast<double>(stats.interval_clauses);
    state.counters["leaf_batches"] = static_cast<double>(stats.leaf_batches);
    state.counters["clauses_per_leaf"] =
        stats.leaf_batches ? static_cast<double>(stats.leaf_clauses) / static_cast<double>(stats.leaf_batches) : 0.0;
}

void BM_SliceProspero(benchmark::State& state) { slice_model(state, "prospero.vm", false); }
void BM_SliceProsperoEveryPixel(benchmark::State& state) { slice_model(state, "prospero.vm", true); }
void BM_SliceBear(benchmark::State& state) { slice_model(state, "bear.vm", false); }

BENCHMARK(BM_SliceProspero)->Args({256, 1})->Args({1024, 1})->Args({1024, 2})->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_SliceProsperoEveryPixel)->Args({1024, 1})->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_SliceBear)->Args({1024, 1})->Args({1024, 2})->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
