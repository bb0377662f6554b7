// The tile proof of polynomial_tile_proof.hpp, step by step: the depths,
// the samples, their interpolation and its error, the tile's root radius,
// and the Bernstein pieces in depth.
#include "zeroset/accel/polynomial_tile_proof.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>

#include "zeroset/math/scalar.hpp"
#include "zeroset/roots/bernstein.hpp"
#include "zeroset/roots/polynomial_enclosure.hpp"

namespace zeroset {

namespace {

constexpr int max_size = PolynomialTileProof::max_degree + 1;
/// What the samples' directions may be off by, in roundings of their
/// magnitude (7 and room; see proves_outside).
constexpr int input_roundings = 16;
/// Pieces of the depths a proof may look at, and how often one is halved.
constexpr int max_pieces = 16;
constexpr int max_piece_depth = 12;

/// γ_k = k·u / (1 − k·u) (Higham §3.1).
double gamma(int k) {
    const double ku = k * unit_roundoff;
    return ku / (1.0 - ku);
}

/// Λₙ = max over x of Σᵢ |ℓᵢ(x)| for the nodes i/n, rounded up (the values
/// are 1, 1.25, 1.6311, 2.2078, 3.1063, 4.5493, 6.9297, 10.9456).
constexpr std::array<double, max_size> lebesgue_constant{1.0, 1.001, 1.252, 1.634, 2.21, 3.11, 4.555, 6.94, 10.96};

/// The Bernstein basis of degree n at the nodes i/n, and an approximate
/// inverse of that matrix: the interpolation. Each value is an integer,
/// C(n, m)·i^m·(n − i)^(n−m), over n^n, both exact in doubles: one rounding.
/// The inverse's accuracy decides only how often a proof succeeds: every
/// interpolant is checked at the nodes.
struct NodeBasis {
    std::array<std::array<double, max_size>, max_size> at{};       // at[i][m] = B_m(i/n)
    std::array<std::array<double, max_size>, max_size> inverse{};  // ≈ at⁻¹
};

NodeBasis make_node_basis(int n) {
    NodeBasis b;
    const auto power = [](double x, int k) {
        double p = 1.0;
        for (int i = 0; i < k; ++i) p *= x;
        return p;
    };
    double binomial = 1.0;  // C(n, m), built up column by column
    for (int m = 0; m <= n; ++m) {
        for (int i = 0; i <= n; ++i) b.at[i][m] = binomial * power(i, m) * power(n - i, n - m) / power(n, n);
        binomial = binomial * (n - m) / (m + 1);
    }
    // Gauss–Jordan with partial pivoting on [at | I].
    std::array<std::array<double, 2 * max_size>, max_size> a{};
    for (int i = 0; i <= n; ++i) {
        for (int m = 0; m <= n; ++m) a[i][m] = b.at[i][m];
        a[i][n + 1 + i] = 1.0;
    }
    for (int c = 0; c <= n; ++c) {
        int pivot = c;
        for (int r = c + 1; r <= n; ++r)
            if (std::abs(a[r][c]) > std::abs(a[pivot][c])) pivot = r;
        std::swap(a[c], a[pivot]);
        const double d = a[c][c];
        for (int k = 0; k <= 2 * n + 1; ++k) a[c][k] /= d;
        for (int r = 0; r <= n; ++r) {
            if (r == c) continue;
            const double f = a[r][c];
            for (int k = 0; k <= 2 * n + 1; ++k) a[r][k] -= f * a[c][k];
        }
    }
    for (int i = 0; i <= n; ++i)
        for (int j = 0; j <= n; ++j) b.inverse[i][j] = a[i][n + 1 + j];
    return b;
}

const NodeBasis& node_basis(int n) {
    static const std::array<NodeBasis, max_size> table = [] {
        std::array<NodeBasis, max_size> t{};
        for (int k = 1; k < max_size; ++k) t[k] = make_node_basis(k);
        return t;
    }();
    return table[static_cast<std::size_t>(n)];
}

/// The depths of the box's points seen from the tile — depth is linear, so
/// its corners' least and largest — widened far past their rounding and
/// from 0 on (camera rays go forwards), and the depth of its centre within
/// them. Nothing for a box that is not finite.
struct Depths {
    double lo, hi, centre;
};

std::optional<Depths> proof_depths(const CameraFrustum& tile, const Box3& box) {
    if (!box.valid()) return std::nullopt;
    const std::optional<Span> corners = tile.depths_of(box);
    if (!corners) return std::nullopt;
    double lo = corners->t0, hi = corners->t1;
    const double pad = 1e-9 * (std::abs(lo) + std::abs(hi));
    lo = std::max(lo - pad, 0.0);
    hi += pad;
    const double centre = tile.depth_of(box.center());
    if (!std::isfinite(centre)) return std::nullopt;
    return Depths{lo, hi, std::clamp(centre, lo, std::max(lo, hi))};
}

}  // namespace

double PolynomialTileProof::lebesgue_bound(int n) { return lebesgue_constant[static_cast<std::size_t>(n)]; }

PolynomialTileProof::PolynomialTileProof(const Tape& tape) {
    RayPolynomialProgram::Compiled compiled = RayPolynomialProgram::compile(tape, input_roundings);
    if (compiled.program && compiled.program->error_known() && compiled.program->degree() >= 1 &&
        compiled.program->degree() <= max_degree)
        program_ = std::move(*compiled.program);
}

bool PolynomialTileProof::proves_outside(const CameraFrustum& tile, const Box3& box, TraceCounters& counters) {
    if (!program_) return false;
    const std::optional<Depths> depths = proof_depths(tile, box);
    if (!depths) return false;
    if (depths->hi < depths->lo) return true;  // the box lies behind the eye
    const int n = program_->degree();
    const auto size = static_cast<std::size_t>(n) + 1;
    const NodeBasis& basis = node_basis(n);

    // The samples: Q_k at the nodes, each within its radius. A direction is
    // computed from the node's (u, v), not exact: its u and v are a few
    // roundings off, times R and U, and the sum rounds too — within 7 units
    // of `direction_magnitude` in each coordinate, which the program's
    // inputs allow (input_roundings).
    const CameraFrustum::Rectangle rect = tile.widened_rectangle();
    const double u_size = std::abs(rect.u_lo) + std::abs(rect.u_hi);
    const double v_size = std::abs(rect.v_lo) + std::abs(rect.v_hi);
    Vec3d direction_magnitude;
    for (int a = 0; a < 3; ++a) {
        const double sum = std::abs(tile.forward[a]) + u_size * std::abs(tile.right[a]) + v_size * std::abs(tile.up[a]);
        direction_magnitude[a] = sum * (1.0 + 8.0 * unit_roundoff);
    }
    // [k][i][j], only the first n + 1 of each read: left unset (zeroing
    // 12 KB was a tenth of a proof).
    std::array<Grid, max_size> sample, radius;
    for (int i = 0; i <= n; ++i) {
        const double u = rect.u_lo + (rect.u_hi - rect.u_lo) * (static_cast<double>(i) / n);
        for (int j = 0; j <= n; ++j) {
            const double v = rect.v_lo + (rect.v_hi - rect.v_lo) * (static_cast<double>(j) / n);
            const Ray ray{tile.origin, tile.forward + tile.right * u + tile.up * v};
            program_->evaluate(ray, depths->centre, direction_magnitude);
            ++counters.point_evaluations;
            const std::span<const double> value = program_->value();
            for (int k = 0; k <= n; ++k) {
                sample[k][i][j] = value[static_cast<std::size_t>(k)];
                radius[k][i][j] = program_->radius(k);
                if (!std::isfinite(sample[k][i][j]) || !std::isfinite(radius[k][i][j])) return false;
            }
        }
    }

    // Each Q_k into the rectangle's Bernstein basis (inverse·S·inverseᵀ),
    // then back to the nodes (at·β·atᵀ): the interpolant's error there, with
    // the samples' radii, bounds it everywhere by Λₙ². Σ_m B_m = 1 and the
    // B_m ≥ 0, so going back rounds by at most γ times the largest |β|.
    const double lebesgue = lebesgue_bound(n) * lebesgue_bound(n);
    const double back_rounding = gamma(2 * n + 8);
    std::array<double, max_size> largest{};  // max |β_k|
    for (int k = 0; k <= n; ++k) {
        Grid half;
        for (int m = 0; m <= n; ++m)
            for (int j = 0; j <= n; ++j) {
                double sum = 0.0;
                for (int i = 0; i <= n; ++i) sum += basis.inverse[m][i] * sample[k][i][j];
                half[m][j] = sum;
            }
        Grid& beta = bernstein_[k];
        for (int m = 0; m <= n; ++m)
            for (int l = 0; l <= n; ++l) {
                double sum = 0.0;
                for (int j = 0; j <= n; ++j) sum += half[m][j] * basis.inverse[l][j];
                beta[m][l] = sum;
                largest[k] = std::max(largest[k], std::abs(sum));
            }
        for (int m = 0; m <= n; ++m)
            for (int j = 0; j <= n; ++j) {
                double sum = 0.0;
                for (int l = 0; l <= n; ++l) sum += beta[m][l] * basis.at[j][l];
                half[m][j] = sum;
            }
        double worst = 0.0;
        for (int i = 0; i <= n; ++i)
            for (int j = 0; j <= n; ++j) {
                double sum = 0.0;
                for (int m = 0; m <= n; ++m) sum += basis.at[i][m] * half[m][j];
                worst = std::max(worst, radius[k][i][j] + std::abs(sample[k][i][j] - sum));
            }
        error_[k] = lebesgue * (worst + back_rounding * largest[k]) * (1.0 + 16.0 * unit_roundoff);
        if (!std::isfinite(error_[k])) return false;
    }

    // The tile's root radius about the centre: |Q_k| ≤ max|β_k| + E_k over
    // the rectangle, and the leading |Q_n| ≥ its least |β| less E_n when
    // they share a sign. No ray of the tile has a root farther out, so the
    // depths beyond, joined to those kept, keep their sign.
    const double s0 = (depths->lo - depths->centre) * (1.0 + 4.0 * unit_roundoff);
    const double s1 = (depths->hi - depths->centre) * (1.0 + 4.0 * unit_roundoff);
    double kept0 = s0, kept1 = s1;
    {
        double least = std::numeric_limits<double>::infinity(), most = -least;
        for (int m = 0; m <= n; ++m)
            for (int l = 0; l <= n; ++l) {
                least = std::min(least, bernstein_[n][m][l]);
                most = std::max(most, bernstein_[n][m][l]);
            }
        const double lead = std::max(least, -most) - error_[n];
        const double within = std::max(-s0, s1);
        if (lead > 0.0 && within > 0.0) {
            std::array<double, max_size> weight{}, none{};
            for (int k = 0; k < n; ++k) weight[k] = (largest[k] + error_[k]) * (1.0 + 4.0 * unit_roundoff);
            weight[n] = lead * (1.0 - 4.0 * unit_roundoff);
            const PolynomialEnclosure bounds{std::span<const double>(weight.data(), size),
                                             std::span<const double>(none.data(), size)};
            const double rho = root_radius(bounds, within, within);
            kept0 = std::clamp(-rho, s0, s1);
            kept1 = std::clamp(rho, s0, s1);
        }
    }

    // P > 0 on the kept depths, piece by piece: every Bernstein coefficient
    // of every (m, l) above its conversion's rounding and Σ E_k·|σ|^k.
    const auto positive_on = [&](double a, double b) {
        const double reach = std::max(std::abs(a), std::abs(b));
        double bound = 0.0;
        for (int k = n; k >= 0; --k) bound = bound * reach + error_[k];
        bound *= 1.0 + 4.0 * (n + 1) * unit_roundoff;
        std::array<double, max_size> c{}, out{};
        for (int m = 0; m <= n; ++m)
            for (int l = 0; l <= n; ++l) {
                for (int k = 0; k <= n; ++k) c[k] = bernstein_[k][m][l];
                double magnitude = 0.0;
                to_bernstein(std::span<const double>(c.data(), size), n, a, b, out, magnitude);
                const double floor = bernstein_noise(n, magnitude) + bound;
                for (int i = 0; i <= n; ++i)
                    if (!(out[i] > floor)) return false;
            }
        return true;
    };
    struct Piece {
        double a, b;
        int depth;
    };
    std::array<Piece, max_piece_depth + 2> stack{};  // each halving replaces one piece by two
    std::size_t top = 0;
    stack[top++] = {kept0, kept1, 0};
    int looked = 0;
    while (top > 0) {
        const Piece piece = stack[--top];
        if (++looked > max_pieces) return false;
        if (positive_on(piece.a, piece.b)) continue;
        const double middle = 0.5 * piece.a + 0.5 * piece.b;
        if (piece.depth == max_piece_depth || !(piece.a < middle && middle < piece.b)) return false;
        stack[top++] = {middle, piece.b, piece.depth + 1};
        stack[top++] = {piece.a, middle, piece.depth + 1};
    }
    return true;
}

ProvenTiles::Entry* ProvenTiles::entry(const CameraFrustum& tile) {
    if (stopped_) return nullptr;
    // Rays come tile by tile: the entry asked for last is nearly always it.
    if (last_ < count_ && entries_[last_].tile.same_as(tile)) return &entries_[last_];
    for (std::size_t i = 0; i < count_; ++i)
        if (entries_[i].tile.same_as(tile)) return &entries_[last_ = i];
    if (count_ < capacity) {
        last_ = count_++;
    } else {
        const auto oldest = std::min_element(entries_.begin(), entries_.end(),
                                             [](const Entry& a, const Entry& b) { return a.last_use < b.last_use; });
        last_ = static_cast<std::size_t>(oldest - entries_.begin());
    }
    entries_[last_] = Entry{tile, tile.ray_check(), State::Untried, 0, ++uses_};
    return &entries_[last_];
}

bool ProvenTiles::proven_miss(Entry& e, const Ray& ray) {
    if (e.state != State::Proven || !e.tile.holds(ray, *e.check)) return false;
    e.last_use = ++uses_;
    ++spared_;
    return true;
}

bool ProvenTiles::proves_tile(const CameraFrustum& tile, const Box3& box, bool try_now, TraceCounters& counters) {
    Entry* e = entry(tile);
    if (!e) return false;
    e->last_use = ++uses_;
    if (try_now && e->state == State::Untried && e->check) try_proof(*e, box, counters);
    if (e->state != State::Proven) return false;
    spared_ += static_cast<std::uint64_t>(tile.pixels());
    return true;
}

void ProvenTiles::traced(Entry& e, const Box3& box, bool hit, std::uint64_t spent, TraceCounters& counters) {
    e.last_use = ++uses_;
    if (e.state != State::Untried) return;
    if (hit || stopped_ || !e.check) {
        e.state = State::Unproven;
        return;
    }
    if (spent < costly_miss || ++e.costly_misses < misses_before_proof) return;  // a later miss may ask
    try_proof(e, box, counters);
}

void ProvenTiles::try_proof(Entry& e, const Box3& box, TraceCounters& counters) {
    if (!proof_) proof_ = std::make_unique<PolynomialTileProof>(tape_);
    ++tries_;
    e.state = proof_->proves_outside(e.tile, box, counters) ? State::Proven : State::Unproven;
    if (tries_ >= 64 && spared_ < 32 * tries_) stopped_ = true;
}

}  // namespace zeroset
