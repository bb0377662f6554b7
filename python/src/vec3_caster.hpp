// Vec3d to and from Python: any sequence of three numbers in, a tuple out —
// so a point is written (1, 2, 3) in Python as in the scene language.
#pragma once

#include <pybind11/pybind11.h>

#include "zeroset/math/vec3.hpp"

namespace pybind11::detail {

template <>
struct type_caster<zeroset::Vec3d> {
    PYBIND11_TYPE_CASTER(zeroset::Vec3d, const_name("tuple[float, float, float]"));

    bool load(handle source, bool convert) {
        if (!isinstance<sequence>(source) || isinstance<str>(source)) return false;
        const auto items = reinterpret_borrow<sequence>(source);
        if (items.size() != 3) return false;
        double xyz[3];
        for (size_t i = 0; i < 3; ++i) {
            make_caster<double> component;
            if (!component.load(items[i], convert)) return false;
            xyz[i] = cast_op<double>(component);
        }
        value = {xyz[0], xyz[1], xyz[2]};
        return true;
    }

    static handle cast(const zeroset::Vec3d& v, return_value_policy, handle) {
        return make_tuple(v.x, v.y, v.z).release();
    }
};

}  // namespace pybind11::detail
