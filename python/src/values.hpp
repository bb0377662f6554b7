// Python objects as scene-language values and back: a number or an Expr is
// a number, a sequence of three of them a vector (returned as a tuple);
// a name of a family (a method…) as its member.
#pragma once

#include <span>
#include <string>
#include <string_view>

#include "bindings.hpp"
#include "zeroset/scene/value.hpp"
#include "zeroset/scene/wording.hpp"

namespace zeroset::python {

/// Throws TypeError naming `what` for anything else.
Value to_value(py::handle item, const std::string& what);
py::object from_value(const Value& value);

/// The member of a family (methods, normal modes) called `name`; ValueError
/// in the scene language's words otherwise.
template <class Member, class NameOf>
Member named(const std::string& name, std::string_view what, std::span<const Member> members, NameOf name_of) {
    for (const Member& m : members)
        if (name_of(m) == name) return m;
    throw py::value_error(unknown_choice(what, name, names_of(members, name_of)));
}

}  // namespace zeroset::python
