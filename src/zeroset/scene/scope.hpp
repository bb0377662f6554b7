// Scope: the names a scene binds with `let`. A name is visible from its
// `let` to the end of the scene, across includes, and is bound only once.
#pragma once

#include <functional>
#include <map>
#include <string>
#include <string_view>
#include <utility>

#include "zeroset/scene/value.hpp"

namespace zeroset {

struct Binding {
    Value value;
    std::string defined_at;  // "file:line:column" of the name in its `let`
};

class Scope {
public:
    [[nodiscard]] const Binding* find(std::string_view name) const {
        const auto it = bindings_.find(name);
        return it == bindings_.end() ? nullptr : &it->second;
    }
    /// Binds a name that find() does not know yet.
    void define(std::string name, Binding binding) { bindings_.emplace(std::move(name), std::move(binding)); }

private:
    std::map<std::string, Binding, std::less<>> bindings_;
};

}  // namespace zeroset
