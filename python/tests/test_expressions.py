# Expressions from Python: operators, evaluation on numbers and arrays, the
# scene language's functions through one bridge, parse() and load_vm().
import math

import numpy as np
import pytest

import zeroset as zs
from conftest import MODELS_DIR
from zeroset import x, y, z


def test_operators_build_the_function_python_reads():
    f = x**2 + y**2 + z**2 - 1
    assert f(1.0, 0.0, 0.0) == 0.0
    assert f(0.0, 0.0, 0.0) == -1.0
    g = (2 - x) * (1 / (y + 3)) - (-z) / 4 + 2**x + x**0.5
    px, py, pz = 1.5, 0.25, -2.0
    expected = (2 - px) * (1 / (py + 3)) - (-pz) / 4 + 2**px + px**0.5
    assert g(px, py, pz) == pytest.approx(expected, rel=1e-15)
    assert isinstance(+x, zs.Expr)
    assert zs.Expr(2.5)(9, 9, 9) == 2.5
    assert (zs.Expr(2) * 3 + zs.sin(zs.Expr(1))).is_constant and not f.is_constant


def test_numpy_numbers_and_huge_powers_are_numbers():
    assert zs.sd_sphere(np.int64(1))(2, 0, 0) == pytest.approx(1.0)
    assert zs.Material(color=np.array([0.1, 0.2, 0.3], dtype=np.float32)).color == pytest.approx((0.1, 0.2, 0.3))
    assert (x ** np.int32(3))(2, 0, 0) == 8
    assert (x ** (2**40))(1, 0, 0) == 1  # past 1024: pow, not repeated multiplication
    assert zs.parse("1 + clock", clock=0.25)(0, 0, 0) == 1.25


def test_arrays_broadcast_like_numpy():
    f = x**2 + y**2 + z**2 - 1
    xs = np.linspace(-2, 2, 5)
    values = f(xs[:, None], xs[None, :], 0.0)
    assert values.shape == (5, 5)
    np.testing.assert_allclose(values, xs[:, None] ** 2 + xs[None, :] ** 2 - 1)


def test_the_scene_languages_functions_are_modules_functions():
    assert zs.sd_sphere(1)(2, 0, 0) == pytest.approx(1.0)
    assert zs.sd_torus(1, 0.25)(1, 0, 0) == pytest.approx(-0.25)
    assert zs.min(x, y, z)(3, 1, 2) == 1
    assert zs.max(x, 5)(3, 0, 0) == 5
    assert zs.sqrt(x)(4, 0, 0) == 2
    moved = zs.translate(zs.sd_sphere(1), (3, 0, 0))
    assert moved(3, 0, 0) == pytest.approx(-1.0)
    blended = zs.smooth_union(zs.sd_sphere(1), moved, 0.5)
    assert blended(1.5, 0, 0) < min(zs.sd_sphere(1)(1.5, 0, 0), moved(1.5, 0, 0))
    fillet = zs.algebraic_blend(x * x + z * z - 0.25, y, 0.36, 0.3)
    assert fillet(0.61 ** 0.5, 0, 0) == pytest.approx(0.0, abs=1e-14)  # on the plate where g = a
    # A shape evaluated at a point of expressions, as in the language.
    assert zs.sd_sphere(1, (x - 1, y, z))(1, 0, 0) == pytest.approx(-1.0)
    # The named algebraic surfaces come from their own table.
    assert zs.barth_sextic()(0, 0, 0) == pytest.approx(zs.parse("barth_sextic()")(0, 0, 0))


def test_a_wrong_call_says_what_the_language_says():
    with pytest.raises(ValueError, match="sd_sphere: radius .* must be a constant number"):
        zs.sd_sphere(x)
    with pytest.raises(ValueError, match="sd_torus"):
        zs.sd_torus(1)
    with pytest.raises(TypeError, match="must be a number, an Expr or a vector"):
        zs.sin("x")


def test_parse_binds_names_and_locates_mistakes():
    f = zs.parse("sd_sphere(r) + a * sin(10 * x)", r=1.0, a=0.1)
    assert f(0.5, 0, 0) == pytest.approx(-0.5 + 0.1 * math.sin(5.0))
    v = zs.parse("(1, x, 3)")
    assert isinstance(v, tuple) and v[1](7, 0, 0) == 7
    with pytest.raises(zs.SceneError) as error:
        zs.parse("x +\n  * 2")
    assert (error.value.file, error.value.line, error.value.column) == ("<expression>", 2, 3)
    assert "expected an expression" in error.value.message
    assert str(error.value).startswith("<expression>:2:3: ")
    with pytest.raises(zs.SceneError, match="unknown identifier 'w'"):
        zs.parse("x + w")
    with pytest.raises(zs.SceneError, match="cannot be bound"):
        zs.parse("x", pi=3)


def test_load_vm_reads_fidgets_models():
    bear = MODELS_DIR / "bear.vm"
    if not bear.exists():
        pytest.skip(f"{bear} is not there")
    f = zs.load_vm(str(bear))
    assert f.node_count > 100
    same = zs.parse(f'model("{bear}")')
    for p in [(0.0, 0.0, 0.0), (0.3, -0.2, 0.1), (2.0, 2.0, 2.0)]:
        assert f(*p) == same(*p)
    with pytest.raises(OSError):
        zs.load_vm(str(MODELS_DIR / "no-such-model.vm"))
