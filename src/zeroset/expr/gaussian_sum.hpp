// Blinn's blobby model written out as one expression (survey eq. 12),
//
//   f = T − Σ sᵢ·exp(−kᵢ·|p − cᵢ|² + bᵢ),
//
// recognised so that it can be traced as a blob (accel/blob.hpp): a sum of
// Gaussians walked as one tape evaluates every kernel at every point, while
// the blob meets only the few in reach along each ray — 50 atoms render
// about ten times faster that way. Each term becomes a component of radius
// 1/√kᵢ and blobbiness −1, the same function up to rounding; the blob then
// cuts each Gaussian off far out (docs/blobs.md, Blinn's cut-off).
#pragma once

#include <optional>

#include "zeroset/expr/blob_model.hpp"
#include "zeroset/expr/expr.hpp"

namespace zeroset {

/// The Blinn blob that f is, when f is a positive constant T plus a sum of
/// constant multiples of exponentials of isotropic quadratics with a
/// negative leading coefficient (written any way: (x − a)², squares of
/// sums, products by constants, nested sums and differences); nothing
/// otherwise. Walks at most four times f's node count.
std::optional<BlobModel> gaussian_sum_as_blob(const Expr& f);

}  // namespace zeroset
