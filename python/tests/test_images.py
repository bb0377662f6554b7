# render(), slice(), ray() and write_image(): the same numbers as the
# command-line program, arrays of the documented shapes, the GIL released
# while rendering, and errors as Python exceptions.
import json
import math
import shutil
import subprocess
import threading
import time

import numpy as np
import pytest

import zeroset as zs
from conftest import read_pfm
from zeroset import x, y, z


def test_render_gives_the_programs_image(binary, tmp_path):
    rgb = zs.render(zs.default_scene(), 64, 48, spp=2, threads=2)
    assert rgb.shape == (48, 64, 3) and rgb.dtype == np.float32
    out = tmp_path / "out.pfm"
    subprocess.run([binary, "render", "-q", "-o", str(out), "--width", "64", "--height", "48", "--spp", "2"],
                   check=True)
    np.testing.assert_array_equal(rgb, read_pfm(out))


def test_cone_antialiasing_gives_the_programs_image(binary, tmp_path):
    rgb = zs.render(zs.default_scene(), 64, 48, threads=2, antialias="cone")
    out = tmp_path / "out.pfm"
    subprocess.run([binary, "render", "-q", "-o", str(out), "--width", "64", "--height", "48", "--antialias", "cone"],
                   check=True)
    np.testing.assert_array_equal(rgb, read_pfm(out))
    assert not np.array_equal(rgb, zs.render(zs.default_scene(), 64, 48, threads=2))  # its edges are blended
    with pytest.raises(ValueError, match="unknown antialiasing 'cones'"):
        zs.render(zs.default_scene(), 8, 8, antialias="cones")
    with pytest.raises(zs.RenderError, match="cone antialiasing traces one ray per pixel"):
        zs.render(zs.default_scene(), 8, 8, spp=4, antialias="cone")


def test_layers_are_depth_and_normals_of_the_hits():
    scene = zs.default_scene()
    rgb, depth, normals = zs.render(scene, 80, 60, threads=2, layers=True)
    assert depth.shape == (60, 80) and normals.shape == (60, 80, 3)
    hit = np.isfinite(depth)
    background = np.all(np.abs(rgb - np.float32(scene.background)) < 1e-6, axis=2)
    assert np.array_equal(hit, ~background)
    np.testing.assert_allclose(np.linalg.norm(normals[hit], axis=1), 1, atol=1e-5)
    assert not normals[~hit].any()
    assert depth[hit].min() > 0


def test_the_gil_is_released_while_rendering():
    # While the render runs, this thread keeps running: its longest pause is
    # a thread switch or two, far shorter than the render. (Holding the GIL,
    # the render would pause it for the whole render.)
    timing = {}

    def work():
        start = time.perf_counter()
        zs.render(zs.default_scene(), 480, 360, threads=1)
        timing["render"] = time.perf_counter() - start

    worker = threading.Thread(target=work)
    longest, last = 0.0, time.perf_counter()  # from before the start: the worker may run at once
    worker.start()
    while worker.is_alive():
        now = time.perf_counter()
        longest, last = max(longest, now - last), now
    longest = max(longest, time.perf_counter() - last)
    worker.join()
    assert timing["render"] > 0.05
    assert longest < 0.3 * timing["render"], (longest, timing["render"])


def test_a_scene_changed_during_a_render_does_not_disturb_it():
    scene = zs.default_scene()
    expected = zs.render(scene, 48, 36, threads=1)
    stop = threading.Event()

    def meddle():
        while not stop.is_set():
            scene.add_object(x - 100, bounds=((99, -1, -1), (101, 1, 1)))
            scene.background = (1, 0, 1)
            scene.background = zs.default_scene().background

    meddler = threading.Thread(target=meddle)
    meddler.start()
    try:
        for _ in range(5):
            assert zs.render(scene, 48, 36, threads=2).shape == expected.shape
    finally:
        stop.set()
        meddler.join()


def test_slice_samples_f_at_pixel_centres():
    f = x**2 + y**2 - 0.5 + 0.1 * zs.sin(5 * x)
    n = 64
    values = zs.slice(f, size=n, axis="z", at=0.0, region=(-1.0, 1.0))
    assert values.shape == (n, n) and values.dtype == np.float32
    centres = -1 + (np.arange(n) + 0.5) * 2 / n
    expected = f(centres[None, :], centres[::-1, None], 0.0)  # row 0 at the top: y decreasing
    np.testing.assert_allclose(values, expected, atol=1e-5)
    with pytest.raises(ValueError, match="unknown axis"):
        zs.slice(f, axis="w")


def test_ray_gives_the_programs_json(binary):
    result = subprocess.run([binary, "ray", "--json"], check=True, capture_output=True, text=True)
    assert zs.ray() == json.loads(result.stdout)
    one = zs.ray(method="interval")
    assert [m["method"] for m in one["methods"]] == ["interval"]
    scene = zs.parse_scene('object "s" { surface x^2 + y^2 + z^2 - 1  bounds box((-2,-2,-2),(2,2,2)) }')
    hit = zs.ray(scene, origin=(-5, 0, 0), dir=(1, 0, 0), method="polynomial")
    assert hit["methods"][0]["first_hit"] == pytest.approx(4.0)
    with pytest.raises(ValueError, match="origin and dir"):
        zs.ray(scene)


def test_write_image_by_extension(tmp_path):
    rgb = np.random.default_rng(1).random((6, 5, 3), dtype=np.float32)
    zs.write_image(str(tmp_path / "a.pfm"), rgb)
    np.testing.assert_array_equal(read_pfm(tmp_path / "a.pfm"), rgb)
    depth = np.full((6, 5), np.inf, dtype=np.float32)
    normals = np.zeros((6, 5, 3), dtype=np.float32)
    zs.write_image(str(tmp_path / "a.exr"), rgb, depth, normals)
    if shutil.which("exrheader"):
        header = subprocess.run(["exrheader", str(tmp_path / "a.exr")], check=True, capture_output=True, text=True)
        for channel in ["R", "G", "B", "Z", "N.x", "N.y", "N.z"]:
            assert f"    {channel}, 32-bit floating-point" in header.stdout
    with pytest.raises(ValueError, match="together"):
        zs.write_image(str(tmp_path / "b.exr"), rgb, depth)
    with pytest.raises(ValueError, match="shape"):
        zs.write_image(str(tmp_path / "b.png"), rgb[:, :, :2])
    with pytest.raises(OSError, match="unsupported image format"):
        zs.write_image(str(tmp_path / "b.jpg"), rgb)
    with pytest.raises(ValueError, match="at least 1"):
        zs.write_image(str(tmp_path / "b.png"), np.zeros((0, 4, 3), dtype=np.float32))


def test_bounds_that_cut_the_solid_warn():
    text = 'object "ball" { surface x^2 + y^2 + z^2 - 1  bounds box((-1.1, -1.1, -1.1), (1.1, 1.1, 0.5)) }'
    with pytest.warns(UserWarning, match=r"<string>:1:1: object 'ball': its bounds cut through its solid"):
        zs.render(zs.parse_scene(text), 8, 6)


def test_render_errors_are_render_errors():
    with pytest.raises(zs.RenderError, match="width must be between"):
        zs.render(zs.default_scene(), 0, 10)
    scene = zs.Scene()
    scene.add_object(zs.sqrt(x) + y**2 + z**2 - 1, name="bad", bounds=((-2, -2, -2), (2, 2, 2)))
    with pytest.raises(zs.RenderError, match="'bad' evaluates to NaN"):
        zs.render(scene, 16, 16)
    with pytest.raises(ValueError, match="unknown method"):
        zs.render(zs.default_scene(), 8, 8, method="magic")
    with pytest.raises(ValueError, match="reflection_depth must be between 0 and 64"):
        zs.default_scene().reflection_depth = 1000000


def test_mesh_gives_a_closed_mesh_as_arrays():
    vertices, triangles = zs.mesh(x**2 + y**2 + z**2 - 1, resolution=16, box=((-1.5, -1.5, -1.5), (1.5, 1.5, 1.5)),
                                  method="tetrahedra")
    assert vertices.shape[1] == 3 and triangles.shape[1] == 3 and triangles.dtype == np.uint32
    np.testing.assert_allclose(np.linalg.norm(vertices, axis=1), 1, atol=1e-6)
    edges = np.concatenate([triangles[:, [0, 1]], triangles[:, [1, 2]], triangles[:, [2, 0]]])
    directed = {tuple(e) for e in edges.tolist()}
    assert len(directed) == len(edges) and all((b, a) in directed for a, b in directed)  # closed, oriented
    assert len(vertices) - len(edges) // 2 + len(triangles) == 2  # a sphere
    # A scene's object: within its bounds, placed as the scene places it; a mirror keeps it outward.
    scene = zs.Scene()
    scene.add_object(x**2 + y**2 + z**2 - 1, bounds=((-1.2, -1.2, -1.2), (1.2, 1.2, 1.2)), translate=(5, 0, 0),
                     scale=(-1, 1, 1))
    placed, faces = zs.mesh(scene, resolution=16, method="tetrahedra")
    np.testing.assert_allclose(np.linalg.norm(placed - [5, 0, 0], axis=1), 1, atol=1e-6)
    a, b, c = (placed[faces[:, i]] - [5, 0, 0] for i in range(3))
    assert (np.einsum("ij,ij->i", a, np.cross(b, c)) > 0).all()  # every triangle faces outwards
    with pytest.raises(ValueError, match="power of two"):
        zs.mesh(x, resolution=100)
    with pytest.raises(ValueError, match="unknown mesh method 'duel'.*did you mean 'dual'"):
        zs.mesh(x, method="duel")


def test_mesh_by_dual_contouring_keeps_a_box_corners():
    vertices, triangles = zs.mesh(zs.sd_box((0.7, 0.5, 0.9)), resolution=16, box=((-1.5,) * 3, (1.5,) * 3))
    for corner in np.array(np.meshgrid([-0.7, 0.7], [-0.5, 0.5], [-0.9, 0.9])).reshape(3, -1).T:
        assert np.linalg.norm(vertices - corner, axis=1).min() < 1e-12
    edges = np.concatenate([triangles[:, [0, 1]], triangles[:, [1, 2]], triangles[:, [2, 0]]])
    directed = {tuple(e) for e in edges.tolist()}
    assert len(directed) == len(edges) and all((b, a) in directed for a, b in directed)  # closed, oriented
