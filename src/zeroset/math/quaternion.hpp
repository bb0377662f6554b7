// Quaternion: a + b·i + c·j + d·k, the number system of Hart, Sandin and
// Kauffman's 3-D Julia sets (1989): z ← z² + c iterated over quaternions,
// the 3-D set a slice of the 4-D one. Only what that iteration needs.
#pragma once

#include <cmath>

namespace zeroset {

struct Quaternion {
    double r = 0.0, i = 0.0, j = 0.0, k = 0.0;

    friend constexpr Quaternion operator+(const Quaternion& a, const Quaternion& b) {
        return {a.r + b.r, a.i + b.i, a.j + b.j, a.k + b.k};
    }
    friend constexpr Quaternion operator*(double s, const Quaternion& a) { return {s * a.r, s * a.i, s * a.j, s * a.k}; }
    /// The Hamilton product (not commutative).
    friend constexpr Quaternion operator*(const Quaternion& a, const Quaternion& b) {
        return {a.r * b.r - a.i * b.i - a.j * b.j - a.k * b.k, a.r * b.i + a.i * b.r + a.j * b.k - a.k * b.j,
                a.r * b.j - a.i * b.k + a.j * b.r + a.k * b.i, a.r * b.k + a.i * b.j - a.j * b.i + a.k * b.r};
    }
};

/// |q|².
constexpr double norm_squared(const Quaternion& q) { return q.r * q.r + q.i * q.i + q.j * q.j + q.k * q.k; }

/// q², cheaper than q·q: the imaginary parts only scale by 2r.
constexpr Quaternion squared(const Quaternion& q) {
    return {q.r * q.r - q.i * q.i - q.j * q.j - q.k * q.k, 2.0 * q.r * q.i, 2.0 * q.r * q.j, 2.0 * q.r * q.k};
}

}  // namespace zeroset
