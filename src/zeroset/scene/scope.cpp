// Name lookup through nested frames, newest binding first.
#include "zeroset/scene/scope.hpp"

#include <algorithm>

namespace zeroset {

bool Scope::visible(std::size_t i) const {
    std::size_t limit = entries_.size();  // entries at or past it are hidden from the frame being searched
    for (std::size_t f = frames_.size(); f-- > 0;) {
        if (i >= frames_[f].start) return i < limit;
        limit = std::min(limit, frames_[f].visible);
    }
    return false;
}

const Binding* Scope::find(std::string_view name) const {
    const auto it = by_name_.find(name);
    if (it == by_name_.end()) return nullptr;
    for (auto i = it->second.rbegin(); i != it->second.rend(); ++i)
        if (visible(*i)) return &entries_[*i].binding;
    return nullptr;
}

std::vector<std::string_view> Scope::visible_names() const {
    std::vector<std::string_view> names;
    for (std::size_t i = 0; i < entries_.size(); ++i)
        if (visible(i)) names.push_back(entries_[i].name);
    return names;
}

void Scope::define(std::string name, Binding binding) {
    by_name_[name].push_back(entries_.size());
    entries_.push_back({std::move(name), std::move(binding)});
}

Scope::Frame::Frame(Scope& scope, std::size_t visible) : scope_(scope) {
    scope.frames_.push_back({scope.entries_.size(), visible});
}

Scope::Frame::~Frame() {
    const std::size_t start = scope_.frames_.back().start;
    while (scope_.entries_.size() > start) {
        auto it = scope_.by_name_.find(scope_.entries_.back().name);
        it->second.pop_back();
        if (it->second.empty()) scope_.by_name_.erase(it);
        scope_.entries_.pop_back();
    }
    scope_.frames_.pop_back();
}

}  // namespace zeroset
