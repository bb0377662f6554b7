// Naming an expression's parts: its DAG's nodes operands first and each
// node's uses, then sizes and depths bottom up, naming parts as they pass
// the limits.
#include "zeroset/scene/expression_writer.hpp"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <vector>

namespace zeroset {

std::string ExpressionWriter::text(const Expr& e) {
    const NameOf name_of = [this](const Expr& n) -> const std::string* {
        const auto found = names_.find(n.id());
        return found == names_.end() ? nullptr : &found->second.name;
    };
    // The nodes below e, operands before their users (a part named already
    // not looked into), and how many operand slots hold each (a + a: two).
    const auto named = [this](const Expr& n) { return names_.contains(n.id()); };
    const std::vector<Expr> order = operands_first(e, named);
    std::unordered_map<const void*, int> uses;
    for (const Expr& n : order)
        if (!named(n))
            for (int i = 0; i < op_arity(n.op()); ++i) ++uses[n.operand(i).id()];
    // Bottom up: each part's size unfolded (saturating) and how deep its
    // text nests, a named part counting as a name.
    struct Extent {
        std::uint64_t size;
        int depth;
    };
    constexpr std::uint64_t size_cap = std::uint64_t{1} << 62;
    std::unordered_map<const void*, Extent> extent;
    for (const Expr& n : order) {
        Extent x{1, 0};
        const int arity = named(n) ? 0 : op_arity(n.op());
        for (int i = 0; i < arity; ++i) {
            const Extent& o = extent.at(n.operand(i).id());
            x.size = std::min(size_cap, x.size + o.size);
            x.depth = std::max(x.depth, o.depth + 1);
        }
        const bool shared = uses[n.id()] >= 2 && x.size >= shared_size;
        if (arity > 0 && (shared || x.depth >= nesting)) {
            std::string name = "part_" + std::to_string(names_.size() + 1);
            lets_ += "let " + name + " = ";
            append_infix(lets_, n, name_of, std::numeric_limits<std::size_t>::max());
            lets_ += "\n";
            names_.emplace(n.id(), Named{n, std::move(name)});
            x = {1, 0};
        }
        extent.emplace(n.id(), x);
    }
    std::string out;
    append_infix(out, e, name_of, std::numeric_limits<std::size_t>::max());
    return out;
}

}  // namespace zeroset
