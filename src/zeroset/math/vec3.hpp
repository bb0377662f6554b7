// Vec3<T>: a 3-vector over any number type (double, float, Interval, Dual…),
// so geometry code is written once and reused by every evaluator.
#pragma once

#include <cmath>

namespace zeroset {

template <class T>
struct Vec3 {
    T x{}, y{}, z{};

    constexpr Vec3() = default;
    constexpr Vec3(T x_, T y_, T z_) : x(x_), y(y_), z(z_) {}

    constexpr T& operator[](int i) { return i == 0 ? x : (i == 1 ? y : z); }
    constexpr const T& operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }

    constexpr Vec3& operator+=(const Vec3& o) { x = x + o.x; y = y + o.y; z = z + o.z; return *this; }
    constexpr Vec3& operator-=(const Vec3& o) { x = x - o.x; y = y - o.y; z = z - o.z; return *this; }
    constexpr Vec3& operator*=(const T& s) { x = x * s; y = y * s; z = z * s; return *this; }
};

template <class T> constexpr Vec3<T> operator+(const Vec3<T>& a, const Vec3<T>& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
template <class T> constexpr Vec3<T> operator-(const Vec3<T>& a, const Vec3<T>& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
template <class T> constexpr Vec3<T> operator-(const Vec3<T>& a) { return {-a.x, -a.y, -a.z}; }
template <class T> constexpr Vec3<T> operator*(const Vec3<T>& a, const T& s) { return {a.x * s, a.y * s, a.z * s}; }
template <class T> constexpr Vec3<T> operator*(const T& s, const Vec3<T>& a) { return {a.x * s, a.y * s, a.z * s}; }
template <class T> constexpr Vec3<T> operator/(const Vec3<T>& a, const T& s) { return {a.x / s, a.y / s, a.z / s}; }
/// Component-wise product (colours, scales).
template <class T> constexpr Vec3<T> hadamard(const Vec3<T>& a, const Vec3<T>& b) { return {a.x * b.x, a.y * b.y, a.z * b.z}; }
template <class T> constexpr bool operator==(const Vec3<T>& a, const Vec3<T>& b) { return a.x == b.x && a.y == b.y && a.z == b.z; }

template <class T> constexpr T dot(const Vec3<T>& a, const Vec3<T>& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
template <class T> constexpr Vec3<T> cross(const Vec3<T>& a, const Vec3<T>& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
template <class T> T length(const Vec3<T>& a) { using std::sqrt; return sqrt(dot(a, a)); }
template <class T> Vec3<T> normalize(const Vec3<T>& a) { return a / length(a); }

template <class T> constexpr Vec3<T> min(const Vec3<T>& a, const Vec3<T>& b) {
    return {a.x < b.x ? a.x : b.x, a.y < b.y ? a.y : b.y, a.z < b.z ? a.z : b.z};
}
template <class T> constexpr Vec3<T> max(const Vec3<T>& a, const Vec3<T>& b) {
    return {a.x > b.x ? a.x : b.x, a.y > b.y ? a.y : b.y, a.z > b.z ? a.z : b.z};
}

/// Component-wise |a| (for plain numbers).
template <class T> Vec3<T> abs_components(const Vec3<T>& a) {
    using std::abs;
    return {abs(a.x), abs(a.y), abs(a.z)};
}

/// |x| + |y| + |z|: at least the length, without a square root.
template <class T> T norm1(const Vec3<T>& a) {
    using std::abs;
    return abs(a.x) + abs(a.y) + abs(a.z);
}

/// The largest |coordinate| of a (for plain numbers): the scale of a point.
template <class T> T max_abs(const Vec3<T>& a) {
    using std::abs;
    const T x = abs(a.x), y = abs(a.y), z = abs(a.z);
    const T xy = x > y ? x : y;
    return xy > z ? xy : z;
}

using Vec3d = Vec3<double>;
using Vec3f = Vec3<float>;

}  // namespace zeroset
