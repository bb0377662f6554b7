# Scenes from Python: loading and parsing files with located errors, and
# building a scene — camera, lights, materials, objects and placements.
import numpy as np
import pytest

import zeroset as zs
from conftest import SOURCE_DIR
from zeroset import x, y, z


def ball_scene(**placement):
    scene = zs.Scene()
    scene.camera = zs.Camera(from_=(0, 0, -6), at=(0, 0, 0), fov=40)
    scene.add_light(zs.Light.point((-5, 5, -5)))
    scene.add_object(x**2 + y**2 + z**2 - 1, name="ball", bounds=((-1.5, -1.5, -1.5), (1.5, 1.5, 1.5)),
                     material=zs.Material(color=(0.9, 0.2, 0.1)), **placement)
    return scene


def hit_mask(scene, width=65, height=65):
    _, depth, _ = zs.render(scene, width, height, threads=2, layers=True)
    return np.isfinite(depth)


def test_scene_files_load_and_parse():
    scene = zs.load_scene(str(SOURCE_DIR / "scenes" / "hart1993" / "blinn_blobs.zs"))
    assert scene.objects == zs.default_scene().objects == ["blobs", "floor"]
    text = 'camera { from (0, 0, -5) }\nobject "s" { surface x^2 + y^2 + z^2 - 1 }\n'
    assert zs.parse_scene(text).objects == ["s"]
    assert zs.parse_scene(text).surface("s")(0, 0, 0) == -1


def test_povray_scenes_load_for_their_image_size(tmp_path):
    pov = tmp_path / "two.pov"
    pov.write_text("camera { location <0, 0, -5> look_at 0 right x*image_width/image_height angle 40 }\n"
                   "light_source { <1, 2, -3> color rgb 1 }\n"
                   "sphere { 0, image_width / image_height }\n"
                   "sphere { <3, 0, 0>, 1 no_shadow }\n")
    scene = zs.load_scene(str(pov), width=100, height=50)
    assert scene.objects == ["sphere", "sphere"]
    assert scene.surface()(2, 0, 0) == 0  # the radius is the image's aspect, 2
    with pytest.raises(zs.SceneError) as error:
        zs.load_scene(str(tmp_path / "missing.pov"))
    assert error.value.line == 0


def test_scene_mistakes_carry_their_place():
    with pytest.raises(zs.SceneError) as error:
        zs.parse_scene('object "s" {\n  surface x^2 +\n}\n', name="mine.zs")
    assert (error.value.file, error.value.line) == ("mine.zs", 3)
    assert error.value.column == 1
    with pytest.raises(zs.SceneError) as missing:
        zs.load_scene("/no/such/scene.zs")
    assert missing.value.line == 0 and "cannot open" in missing.value.message


def test_a_built_scene_renders_what_it_says():
    scene = ball_scene()
    assert scene.objects == ["ball"]
    rgb = zs.render(scene, 65, 65, threads=2)
    centre, corner = rgb[32, 32], rgb[0, 0]
    np.testing.assert_allclose(corner, scene.background, rtol=1e-6)
    assert centre[0] > 3 * centre[2]  # the material's red
    mask = hit_mask(scene)
    # The ball's silhouette: radius atan(1/sqrt(35)) of the 20° half-view.
    expected = np.pi * (np.tan(np.arcsin(1 / 6)) / np.tan(np.radians(20)) * 32.5) ** 2
    assert mask.sum() == pytest.approx(expected, rel=0.05)


def test_placement_moves_and_scales_the_object():
    base = hit_mask(ball_scene())
    moved = hit_mask(ball_scene(translate=(1, 0, 0)))
    columns = np.nonzero(moved.any(axis=0))[0].mean() - np.nonzero(base.any(axis=0))[0].mean()
    assert columns > 5  # to the right on screen: +x is right for this camera
    small = hit_mask(ball_scene(scale=0.5))
    assert small.sum() == pytest.approx(base.sum() / 4, rel=0.1)


def test_bad_building_blocks_are_value_errors():
    scene = zs.Scene()
    with pytest.raises(ValueError, match="unknown method"):
        scene.add_object(x, method="magic")
    with pytest.raises(ValueError, match="lo < hi"):
        scene.add_object(x, bounds=((1, 0, 0), (0, 1, 1)))
    with pytest.raises(ValueError, match="scale of 0"):
        scene.add_object(x, scale=0)
    with pytest.raises(ValueError, match="positive radius"):
        zs.Bounds.sphere((0, 0, 0), -1)
    with pytest.raises(ValueError, match="no objects"):
        scene.surface()


def test_materials_take_patterns_and_reflection():
    pattern = zs.Material(color=(x, 0.5, zs.mod(zs.floor(z), 2)), reflection=0.5)
    red, green, blue = pattern.color
    assert isinstance(red, zs.Expr) and blue(0, 0, 1.5) == 1
    assert pattern.reflection == 0.5
    plain = zs.Material(color=(0.1, 0.2, 0.3))
    assert plain.color == (0.1, 0.2, 0.3)
    with pytest.raises(ValueError, match="reflection"):
        zs.Material(reflection=2)
    with pytest.raises(ValueError, match="negative"):
        zs.Material(color=(-1, 0, 0))
    with pytest.raises(ValueError, match="NaN"):
        zs.Material(color=(float("nan"), 0, 0))
    with pytest.raises(ValueError, match="reflection must be between 0 and 1"):
        plain.reflection = 5
    with pytest.raises(ValueError, match="ambient must be between"):
        plain.ambient = -1
    scene = zs.Scene()
    scene.camera = zs.Camera(from_=(0.3, 6, 0.2), at=(0.3, 0, 0.2), up=(0, 0, 1))
    scene.add_light(zs.Light.directional((0, -1, 0), shadows=False))
    checker = zs.mod(zs.floor(x) + zs.floor(z), 2)
    scene.add_object(y, bounds=zs.Bounds.none(),
                     material=zs.Material(color=(0.2 + 0.6 * checker, 0.2, 0.2), specular=0))
    rgb = zs.render(scene, 32, 24)
    assert np.unique(np.round(rgb[:, :, 0].astype(float), 5)).tolist() == pytest.approx([0.2, 0.8])


def test_the_clock_is_read_when_the_scene_is():
    text = 'let r = 1 + clock\nobject "s" { surface x^2 + y^2 + z^2 - r^2 }\n'
    assert zs.parse_scene(text).surface()(1, 0, 0) == 0
    assert zs.parse_scene(text, clock=0.5).surface()(1.5, 0, 0) == 0


def test_a_shifted_lens_moves_the_picture():
    # The ball at the centre; the lens shifted up by a quarter of the image
    # height shows it a quarter of the image lower.
    centred = hit_mask(ball_scene())
    scene = ball_scene()
    scene.camera = zs.Camera(from_=(0, 0, -6), at=(0, 0, 0), fov=40, shift_up=0.25)
    shifted = hit_mask(scene)
    rows = np.nonzero(centred.any(axis=1))[0]
    moved_rows = np.nonzero(shifted.any(axis=1))[0]
    assert abs((moved_rows.mean() - rows.mean()) - 0.25 * 65) < 2
    with pytest.raises(ValueError, match="shift_up must be between"):
        scene.camera.shift_up = float("nan")
