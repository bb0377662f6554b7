// The thresholds of the 8-bit sRGB codes, found once from the formula.
#include "zeroset/io/srgb.hpp"

#include <bit>

namespace zeroset {

const std::array<float, 256>& srgb8_thresholds() {
    static const std::array<float, 256> thresholds = [] {
        std::array<float, 256> t{};
        // The formula is monotone in its input, and so are the bit patterns
        // of the floats in [0, 1]: bisect those for each code's first float.
        const auto bits = [](float f) { return std::bit_cast<std::uint32_t>(f); };
        for (unsigned code = 1; code < t.size(); ++code) {
            std::uint32_t below = bits(0.0f), at_or_above = bits(1.0f);  // codes 0 and 255
            while (at_or_above - below > 1) {
                const std::uint32_t middle = below + (at_or_above - below) / 2;
                (encode_srgb8_by_formula(std::bit_cast<float>(middle)) >= code ? at_or_above : below) = middle;
            }
            t[code] = std::bit_cast<float>(at_or_above);
        }
        return t;
    }();
    return thresholds;
}

}  // namespace zeroset
