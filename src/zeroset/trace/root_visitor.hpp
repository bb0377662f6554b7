// RootVisitor: a non-owning, non-allocating reference to a callback that is
// handed each root a method isolates, in increasing t; it returns false to
// stop the search (first hit) or true to go on (all hits).
#pragma once

#include <memory>
#include <type_traits>

namespace zeroset {

class RootVisitor {
public:
    template <class F>
        requires(!std::is_same_v<std::remove_cvref_t<F>, RootVisitor>)
    RootVisitor(F& callback)  // NOLINT: implicit, like a function pointer
        : object_(std::addressof(callback)), call_([](void* o, double t) { return (*static_cast<F*>(o))(t); }) {}

    bool operator()(double t) const { return call_(object_, t); }

private:
    void* object_;
    bool (*call_)(void*, double);
};

}  // namespace zeroset
