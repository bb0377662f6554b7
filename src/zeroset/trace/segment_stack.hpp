// SegmentStack: the ray segments a subdividing method still has to look at,
// the front of the ray on top, so roots are met in increasing t. Splitting
// pops one segment and pushes its two halves, so the stack grows by one per
// level of subdivision; its fixed capacity bounds the depth, and callers split
// only while can_split() (otherwise they must settle the segment as it is).
#pragma once

#include <array>
#include <cstddef>

namespace zeroset {

struct Segment {
    double a, b;
    std::size_t depth;  // number of splits above this segment
};

class SegmentStack {
public:
    static constexpr std::size_t max_depth = 128;

    void push(double a, double b, std::size_t depth) { items_[size_++] = {a, b, depth}; }
    /// Pushes the halves of [from, s.b] (the front half on top).
    void split(const Segment& s, double from) {
        const double mid = 0.5 * (from + s.b);
        push(mid, s.b, s.depth + 1);
        push(from, mid, s.depth + 1);
    }
    [[nodiscard]] bool can_split(const Segment& s) const {
        return size_ + 2 <= items_.size() && s.depth + 1 < max_depth;
    }
    /// True while the segment's midpoint is a double strictly inside it:
    /// narrower segments are at the resolution of doubles.
    [[nodiscard]] static bool above_resolution(const Segment& s) {
        const double mid = 0.5 * (s.a + s.b);
        return s.a < mid && mid < s.b;
    }
    [[nodiscard]] bool empty() const { return size_ == 0; }
    Segment pop() { return items_[--size_]; }

private:
    // Not zeroed: only pushed entries are read, and zeroing 3 KB on every
    // construction was a fifth of a Gaussian blob's interval isolation.
    std::array<Segment, max_depth + 2> items_;
    std::size_t size_ = 0;
};

}  // namespace zeroset
