// Scope: the names a scene binds — with `let` (a number or a vector), as a
// loop's counter or a shape's parameter, or as a shape (`shape NAME …`). A
// name is visible from its binding to the end of the scene (across
// includes), or to the end of the loop or shape body that binds it, and is
// bound only once among the names visible: no name hides another.
//
// Bodies are read again for every loop iteration and every placement of a
// shape; a shape's body sees the names that were visible where it was
// defined, and its own — never one bound later outside it.
#pragma once

#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <unordered_map>
#include <utility>
#include <vector>

#include "zeroset/scene/value.hpp"

namespace zeroset {

struct ShapeDefinition;

struct Binding {
    Value value;             // a number or a vector (unused for a shape)
    std::string defined_at;  // "file:line:column" of the name where it is bound
    std::shared_ptr<ShapeDefinition> shape = nullptr;  // a shape's definition; null for values
};

class Scope {
public:
    [[nodiscard]] const Binding* find(std::string_view name) const;
    /// The names find() knows now (for "did you mean …").
    [[nodiscard]] std::vector<std::string_view> visible_names() const;
    /// Binds a name that find() does not know yet, in the innermost frame.
    void define(std::string name, Binding binding);

    /// How many bindings exist now: a body defined here sees exactly these
    /// (and its own) when it is read later.
    [[nodiscard]] std::size_t mark() const { return entries_.size(); }

    /// A frame of names for one reading of a body, which sees the names bound
    /// before `visible` (a mark) and its own; they are gone when it ends.
    class Frame {
    public:
        Frame(Scope& scope, std::size_t visible);
        ~Frame();
        Frame(const Frame&) = delete;
        Frame& operator=(const Frame&) = delete;

    private:
        Scope& scope_;
    };

private:
    struct NameHash {
        using is_transparent = void;
        std::size_t operator()(std::string_view name) const { return std::hash<std::string_view>{}(name); }
    };
    struct Entry {
        std::string name;
        Binding binding;
    };
    struct OpenFrame {
        std::size_t start;    // its first entry
        std::size_t visible;  // entries of the frames outside it it may see: those before this
    };
    /// Whether entry i can be seen from the innermost frame.
    [[nodiscard]] bool visible(std::size_t i) const;

    std::vector<Entry> entries_;
    std::vector<OpenFrame> frames_{{0, 0}};                                         // the scene's own frame first
    std::unordered_map<std::string, std::vector<std::size_t>, NameHash, std::equal_to<>> by_name_;  // entries, oldest first
};

}  // namespace zeroset
