// What the fuzz targets share: the input as text, and limits lowered so that
// no input the parser accepts takes more than a moment — the fuzzer looks
// for crashes, hangs and sanitizer reports, and a scene that legitimately
// runs a million loop iterations would only be reported as slow.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>

#include "zeroset/expr/expr.hpp"
#include "zeroset/scene/scene_limits.hpp"

namespace zeroset::fuzz {

inline std::string_view as_text(const std::uint8_t* data, std::size_t size) {
    return {reinterpret_cast<const char*>(data), size};
}

inline SceneLimits small_limits() {
    SceneLimits limits;
    limits.include_depth = 8;
    limits.loop_iterations = 20'000;
    limits.objects = 64;
    return limits;
}

/// Lowers the cap on live expression nodes to what is alive now plus
/// `extra` while it lives.
class ExpressionBudget {
public:
    explicit ExpressionBudget(std::size_t extra)
        : previous_(set_max_expression_nodes(live_expression_nodes() + extra)) {}
    ~ExpressionBudget() { set_max_expression_nodes(previous_); }
    ExpressionBudget(const ExpressionBudget&) = delete;
    ExpressionBudget& operator=(const ExpressionBudget&) = delete;

private:
    std::size_t previous_;
};

}  // namespace zeroset::fuzz
