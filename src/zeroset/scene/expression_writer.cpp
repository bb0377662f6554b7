// Naming an expression's parts: one walk over its DAG for the order
// (operands first) and each node's uses, then sizes and depths bottom up,
// naming parts as they pass the limits.
#include "zeroset/scene/expression_writer.hpp"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <unordered_set>
#include <vector>

namespace zeroset {

std::string ExpressionWriter::text(const Expr& e) {
    const NameOf name_of = [this](const Expr& n) -> const std::string* {
        const auto found = names_.find(n.id());
        return found == names_.end() ? nullptr : &found->second;
    };
    // The nodes below e, operands before their users, and how many operand
    // slots there hold each (a + a: two); a part named already is not
    // looked into.
    std::vector<Expr> order;
    std::unordered_map<const void*, int> uses;
    {
        struct Visit {
            Expr node;
            bool operands_done;
        };
        std::vector<Visit> stack{{e, false}};
        std::unordered_set<const void*> seen;
        while (!stack.empty()) {
            Visit v = std::move(stack.back());
            stack.pop_back();
            if (v.operands_done) {
                order.push_back(std::move(v.node));
                continue;
            }
            if (!seen.insert(v.node.id()).second) continue;
            stack.push_back({v.node, true});
            if (names_.contains(v.node.id())) continue;
            for (int i = op_arity(v.node.op()); i-- > 0;) {
                Expr operand = v.node.operand(i);
                ++uses[operand.id()];
                stack.push_back({std::move(operand), false});
            }
        }
    }
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
        const int arity = names_.contains(n.id()) ? 0 : op_arity(n.op());
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
            names_.emplace(n.id(), std::move(name));
            named_.push_back(n);
            x = {1, 0};
        }
        extent.emplace(n.id(), x);
    }
    std::string out;
    append_infix(out, e, name_of, std::numeric_limits<std::size_t>::max());
    return out;
}

}  // namespace zeroset
