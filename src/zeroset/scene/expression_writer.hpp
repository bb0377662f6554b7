// ExpressionWriter: expressions as scene-language text that reads back.
// An Expr is a DAG. Written as the tree it unfolds to, a model whose parts
// are shared (a POV-Ray function used twice by the next, and so on) grows
// exponentially, and a long chain nests deeper than the parser allows
// (SceneLimits::expression_nesting). So a part used more than once that is
// not small, and a part whose text would nest too deep, is written once as
// a `let` and named wherever it occurs; every let comes after the lets it
// names.
#pragma once

#include <cstdint>
#include <string>
#include <unordered_map>

#include "zeroset/expr/expr.hpp"

namespace zeroset {

class ExpressionWriter {
public:
    /// The text of `e`, its parts named as above; the lets it needs are
    /// added to lets().
    std::string text(const Expr& e);
    /// The let statements so far, one a line.
    [[nodiscard]] const std::string& lets() const { return lets_; }

    /// A shared part is named from this many nodes (unfolded) on …
    static constexpr std::uint64_t shared_size = 24;
    /// … and any part whose text nests this many operations deep (the
    /// parser counts at most two levels an operation, against its 1 000).
    static constexpr int nesting = 200;

private:
    struct Named {
        Expr node;  // kept alive, so that no id is reused
        std::string name;
    };
    std::unordered_map<const void*, Named> names_;  // by node id, the parts named so far
    std::string lets_;
};

}  // namespace zeroset
