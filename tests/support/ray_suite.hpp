// The ray suite: over ten thousand rays across the surfaces of
// ray_suite_surfaces.hpp, each with its first hit computed rigorously by the
// MPFI oracle (tests/data/ray_suite.tsv, made offline by
// tests/tools/make_ray_suite.cpp). Every ray-intersection method runs on the
// same suite (DESIGN.md, "Testing principles"): load it, rebuild each row's
// surface by name, and compare the method's first hit with t_ref — tightly
// for simple roots, leniently for tangent and multiple ones (see
// tests/data/README.md for what each kind promises).
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "zeroset/math/box3.hpp"
#include "zeroset/math/ray.hpp"

namespace zeroset::test {

enum class RefKind {
    Simple,    // a proven root with H′ ≠ 0, exact to far below 1e-15 relative
    Multiple,  // a proven crossing where H′ vanishes (odd-order or clustered roots)
    Tangent,   // H touches 0 without a proven crossing (a double root or a kink)
    None,      // no root in [t0, t1]
};

std::string_view ref_kind_name(RefKind kind);
std::optional<RefKind> ref_kind_from_name(std::string_view name);

struct SuiteRay {
    std::string surface;          // a name from ray_suite_surfaces()
    Ray ray;                      // unit direction (to rounding)
    Span span;                    // the query: the first root in [t0, t1]
    std::optional<double> t_ref;  // the first root; empty for RefKind::None
    RefKind kind = RefKind::None;
    double scale = 1.0;            // the surface's bounds diagonal
    std::string ray_class;         // how the ray was made (random, graze, near_miss, …)
    double slope = 0.0;            // |H′(t_ref)| for a simple root, else 0
    std::optional<double> t_next;  // the next root after t_ref in [t0, t1], if any
};

/// The header line naming the columns (starts with '#', like every comment).
std::string_view ray_suite_columns();

/// One row of the suite (no newline).
std::string format_suite_ray(const SuiteRay& ray);

/// Reads a suite file; throws std::runtime_error naming the line of a bad row.
std::vector<SuiteRay> load_ray_suite(const std::filesystem::path& path);

}  // namespace zeroset::test
