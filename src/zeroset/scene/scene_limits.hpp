// SceneLimits: how much a scene may ask of the parser. Every limit stops a
// scene that would otherwise overflow the stack, exhaust memory or run for
// minutes with a message at the statement that crossed it. The defaults are
// far above any real scene; tests and the fuzz targets pass smaller ones.
// docs/limits.md lists these with every other limit of zeroset.
#pragma once

#include <cstddef>

namespace zeroset {

struct SceneLimits {
    /// Files open at once, each including the next.
    std::size_t include_depth = 64;
    /// Blocks and bodies (objects in groups in loops …) nested in each other.
    int block_nesting = 200;
    /// Parentheses, calls, unary signs and exponents nested in one expression.
    int expression_nesting = 1000;
    /// Loop iterations read in all, nested loops counted in full.
    long long loop_iterations = 10'000'000;
    /// Objects made in all (every `object`, also inside shapes and loops):
    /// about 1.5 KiB each while parsing, more once prepared.
    long long objects = 1'000'000;
};

}  // namespace zeroset
