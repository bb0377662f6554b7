// What rank 0 of a distributed render spends on one remote tile besides the
// MPI transfer: unpacking the result and placing its pixels (and a worker's
// packing), for the scaling model's per-tile service time
// (bench/distributed/simulate.py).
#include <benchmark/benchmark.h>

#include "zeroset/render/tile_result.hpp"

namespace {

zeroset::TileResult full_tile(bool layers) {
    zeroset::TileResult tile;
    tile.frame = 0;
    tile.tile = 7;
    tile.pixels = zeroset::Image(zeroset::tile_side, zeroset::tile_side);
    if (layers) tile.pixels.add_layers();
    for (std::size_t i = 0; i < tile.pixels.pixels.size(); ++i)
        tile.pixels.pixels[i] = {0.25f * static_cast<float>(i), 0.5f, 0.75f};
    return tile;
}

void BM_PackTile(benchmark::State& state) {
    const zeroset::TileResult tile = full_tile(state.range(0) != 0);
    for (auto _ : state) benchmark::DoNotOptimize(tile.pack());
}
BENCHMARK(BM_PackTile)->Arg(0)->Arg(1)->ArgName("layers");

/// Rank 0's side: unpack the bytes, copy the pixels into the image.
void BM_UnpackAndPlaceTile(benchmark::State& state) {
    const bool layers = state.range(0) != 0;
    const std::string bytes = full_tile(layers).pack();
    zeroset::Image image(800, 600);
    if (layers) image.add_layers();
    const zeroset::TileRect where{160, 160, 176, 176};
    for (auto _ : state) {
        const zeroset::TileResult tile = zeroset::TileResult::unpack(bytes);
        zeroset::place_tile(tile.pixels, where, image);
        benchmark::DoNotOptimize(image.pixels.data());
    }
    state.counters["bytes"] = static_cast<double>(bytes.size());
}
BENCHMARK(BM_UnpackAndPlaceTile)->Arg(0)->Arg(1)->ArgName("layers");

}  // namespace

BENCHMARK_MAIN();
