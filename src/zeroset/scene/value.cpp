// Which of x, y, z a value depends on — only ever needed to word an error.
#include "zeroset/scene/value.hpp"

#include <unordered_set>
#include <vector>

#include "zeroset/scene/wording.hpp"

namespace zeroset {

namespace {

void collect_variables(const Expr& root, std::array<bool, 3>& used) {
    std::unordered_set<const void*> seen;
    std::vector<Expr> stack{root};
    while (!stack.empty()) {
        const Expr e = stack.back();
        stack.pop_back();
        if (e.is_constant_valued() || !seen.insert(e.id()).second) continue;
        switch (e.op()) {
            case Op::VarX: used[0] = true; break;
            case Op::VarY: used[1] = true; break;
            case Op::VarZ: used[2] = true; break;
            default:
                for (int i = 0; i < op_arity(e.op()); ++i) stack.push_back(e.operand(i));
        }
    }
}

std::string describe_variables(const std::array<bool, 3>& used) {
    static constexpr std::array<std::string_view, 3> names{"x", "y", "z"};
    std::vector<std::string_view> words;
    for (std::size_t i = 0; i < names.size(); ++i)
        if (used[i]) words.push_back(names[i]);
    return join_words(words, "and");
}

}  // namespace

std::string variables_of(const Expr& e) {
    std::array<bool, 3> used{};
    collect_variables(e, used);
    return describe_variables(used);
}

std::string variables_of(const ExprVector& v) {
    std::array<bool, 3> used{};
    for (const Expr& e : v) collect_variables(e, used);
    return describe_variables(used);
}

}  // namespace zeroset
