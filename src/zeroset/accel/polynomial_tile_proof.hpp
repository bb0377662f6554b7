// Camera tiles proven free of a polynomial surface before their rays are
// traced. On POV-Ray's quartic samples most camera rays miss, each miss
// costs the polynomial method a guarded subdivision of its own, and the
// misses come in whole tiles: 40–50 % of the trace of hyptorus, steiner,
// partorus and quarcyl went to 16×16 tiles without a hit.
//
// Over a tile's frustum the surface seen at depth s through (u, v) is
// P(s, u, v) = f(o + s·(F + u·R + v·U)), a polynomial of f's degree n in s
// and of degree ≤ n in u and in v. About a centre depth s_c, the
// coefficient Q_k(u, v) of (s − s_c)^k is sampled by the ray polynomial
// program, with its proven error bound, along the (n + 1)² directions of an
// equispaced grid over the tile's rectangle; interpolated into the
// rectangle's Bernstein basis; and the interpolation checked at the grid,
// so that its error anywhere in the rectangle is at most Λₙ² (the tensor
// grid's Lebesgue constant) times the worst at the nodes. A root radius
// that holds for every ray of the tile cuts the depths to where a root can
// be; in s the coefficients then go to the Bernstein basis piece by piece.
// Every Bernstein coefficient above its rounding and the interpolation's
// error proves P > 0 over the piece (the convex-hull property): no ray of
// the tile meets f = 0 between the depths, nor starts inside the solid.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>

#include "zeroset/accel/camera_frustum.hpp"
#include "zeroset/expr/ray_polynomial_program.hpp"
#include "zeroset/expr/tape.hpp"
#include "zeroset/math/box3.hpp"
#include "zeroset/trace/trace_counters.hpp"

namespace zeroset {

class PolynomialTileProof {
public:
    /// Degrees above this are not tried: the grid grows as (n + 1)².
    static constexpr int max_degree = 8;

    /// For a tape the polynomial method traces; one it cannot compile, of
    /// a degree above max_degree or without a rounding bound is never proven.
    explicit PolynomialTileProof(const Tape& tape);

    /// True when f > 0 is proven at every point o + s·(F + u·R + v·U) with
    /// (u, v) in the tile's widened rectangle and s ≥ 0 within the depths of
    /// `box`'s points; false when it is not proven. Counts the program's
    /// runs as point evaluations.
    bool proves_outside(const CameraFrustum& tile, const Box3& box, TraceCounters& counters);

    /// Λₙ (rounded up), the Lebesgue constant of interpolation at n + 1
    /// equispaced nodes of an interval: an interpolant is nowhere larger than
    /// Λₙ times its largest value at the nodes (Λₙ² on a tensor grid).
    static double lebesgue_bound(int n);

private:
    static constexpr int max_size = max_degree + 1;
    using Grid = std::array<std::array<double, max_size>, max_size>;

    std::optional<RayPolynomialProgram> program_;
    /// Bernstein coefficients of each Q_k over the rectangle, [k][m][l].
    std::array<Grid, max_size> bernstein_{};
    /// The bound on |Q_k − its interpolant| over the rectangle.
    std::array<double, max_size> error_{};
};

/// A leaf's proofs for the camera tiles one thread traces. A tile is tried
/// once, after 8 of its rays have missed at some cost (a tile with a hit
/// among them is never tried, nor one whose misses cost the method next to
/// nothing: they pass beside the gate or the bounds; a small object on
/// screen seldom gets that far), or when the renderer asks a second time
/// whether the tile is empty (a row of it all missed, the cheap misses of a
/// thin object too); its verdict is kept for the last few tiles; trying
/// stops where it does not pay (64 tries that spared fewer than 32 rays
/// each). The proof, and its program, are made at the first try: a scene
/// of thousands of small objects makes few.
class ProvenTiles {
public:
    explicit ProvenTiles(const Tape& tape) : tape_(tape) {}

    enum class State : std::uint8_t { Untried, Proven, Unproven };
    struct Entry {
        CameraFrustum tile;
        std::optional<CameraFrustum::RayCheck> check;
        State state = State::Untried;
        std::uint32_t costly_misses = 0;
        std::uint64_t last_use = 0;
    };
    /// The tile's entry: kept, or made now in place of the least recently
    /// used; nullptr once trying has stopped.
    Entry* entry(const CameraFrustum& tile);
    /// True when the ray, one of the entry's tile's, is proven to miss f
    /// within the box the tile was tried with.
    bool proven_miss(Entry& e, const Ray& ray);
    /// True when none of the tile's rays meets f within `box`, as the
    /// renderer asks before the tile's rays and again after some of its rows
    /// while all missed: proven already, or — for a tile not yet tried,
    /// when `try_now` (rows have missed) — tried now, though its misses
    /// were cheap (a thin object that most rays pass). The renderer then
    /// traces none of the rest; the tile's pixels count as spared (at most
    /// that many: some were traced, and another object may keep the tile).
    bool proves_tile(const CameraFrustum& tile, const Box3& box, bool try_now, TraceCounters& counters);
    /// What a traced ray of the entry's tile found, and the evaluations it
    /// spent: enough costly misses in a tile not yet tried ask for its proof
    /// over `box` (the leaf's search box).
    void traced(Entry& e, const Box3& box, bool hit, std::uint64_t spent, TraceCounters& counters);
    /// A miss that spent fewer evaluations than this — a run of the ray
    /// polynomial and its Bernstein form — is not worth a proof (which
    /// costs (n + 1)² runs of the ray polynomial and more)…
    static constexpr std::uint64_t costly_miss = 2;
    /// …and a tile is tried after this many.
    static constexpr std::uint32_t misses_before_proof = 8;

    static constexpr std::size_t capacity = 4;

private:
    /// Tries the entry's proof over `box`, and stops trying where proofs do not pay.
    void try_proof(Entry& e, const Box3& box, TraceCounters& counters);

    const Tape& tape_;
    std::unique_ptr<PolynomialTileProof> proof_;  // made at the first try
    std::array<Entry, capacity> entries_{};
    std::size_t count_ = 0, last_ = 0;  // last_: the entry asked for last
    std::uint64_t uses_ = 0, tries_ = 0, spared_ = 0;
    bool stopped_ = false;
};

}  // namespace zeroset
