"""The Python module against analytic fields and against the application's
own outputs for the same configuration and frames."""
import os
import subprocess

import numpy as np
import pytest

from conftest import BUILD, SOURCE
from sandstorm_files import read_appended_vtp, read_ascii_vtp_lines, read_png

import sandstorm

APP = BUILD / "sandstorm"
CONFIG = str(SOURCE / "tests" / "data" / "movie.toml")


def app(*args):
    """Runs the application as a user would, from the checkout; returns its output."""
    r = subprocess.run([str(APP), *args], cwd=SOURCE, capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    return r.stderr


def analytic(x, y, z):
    return np.stack([-y + 0.5 * z, x, 0.1 + 0.05 * z], axis=-1).astype(np.float32)


def write_vti(path, dims, lo, hi, values):
    """A VTK ImageData file with ASCII point data: the test's own writer."""
    nx, ny, nz = dims
    spacing = [(h - l) / (n - 1) for l, h, n in zip(lo, hi, dims)]
    flat = " ".join("%r" % float(v) for v in values.reshape(-1))
    with open(path, "w") as f:
        f.write('<?xml version="1.0"?>\n<VTKFile type="ImageData" version="1.0" '
                'byte_order="LittleEndian">\n'
                '<ImageData WholeExtent="0 %d 0 %d 0 %d" Origin="%r %r %r" Spacing="%r %r %r">\n'
                '<Piece Extent="0 %d 0 %d 0 %d">\n<PointData Vectors="velocity">\n'
                '<DataArray type="Float32" Name="velocity" NumberOfComponents="3" '
                'format="ascii">%s</DataArray>\n</PointData>\n</Piece>\n</ImageData>\n'
                '</VTKFile>\n' % (nx - 1, ny - 1, nz - 1, *lo, *spacing, nx - 1, ny - 1, nz - 1,
                                  flat))


def grid(dims, lo, hi):
    axes = [np.linspace(l, h, n, dtype=np.float64) for l, h, n in zip(lo, hi, dims)]
    z, y, x = np.meshgrid(axes[2], axes[1], axes[0], indexing="ij")
    return x, y, z


def test_a_loaded_field_is_the_analytic_field(tmp_path):
    dims, lo, hi = (5, 4, 3), (-1.0, -2.0, 0.0), (1.0, 1.0, 2.0)
    x, y, z = grid(dims, lo, hi)
    values = analytic(x, y, z)  # (nz, ny, nx, 3), x fastest as VTK stores it
    write_vti(tmp_path / "linear.vti", dims, lo, hi, values)
    f = sandstorm.load_field(str(tmp_path / "linear.vti"))
    assert f.values.shape == (3, 4, 5, 3)
    assert f.values.dtype == np.float32
    np.testing.assert_array_equal(f.values, values)
    assert f.valid.shape == (3, 4, 5) and f.valid.all()
    np.testing.assert_allclose(np.array(f.bounds), [lo, hi], rtol=0, atol=1e-6)
    assert f.array == "velocity"
    assert "dims:        5 x 4 x 3" in f.info
    assert f.times == []
    # Resampled onto a finer grid: trilinear is exact for a linear field.
    g = sandstorm.load_field(str(tmp_path / "linear.vti"), resolution=(9, 7, 5))
    assert g.values.shape == (5, 7, 9, 3)
    np.testing.assert_allclose(g.values, analytic(*grid((9, 7, 5), lo, hi)), atol=2e-6)


def test_a_field_made_in_numpy_runs(tmp_path):
    dims, lo, hi = (12, 10, 8), (-2.0, -2.0, 0.0), (2.0, 2.0, 3.0)
    values = analytic(*grid(dims, lo, hi))
    sandstorm.save_field(str(tmp_path / "mine.vti"), values, (lo, hi))
    back = sandstorm.load_field(str(tmp_path / "mine.vti"))
    np.testing.assert_array_equal(back.values, values)
    with sandstorm.Run(str(tmp_path / "mine.vti")) as run:  # opened as `sandstorm FILE` opens it
        run.step(5)
        assert len(run.particles()["position"]) > 0
    with pytest.raises(sandstorm.Error, match="shape \\(nz, ny, nx, 3\\)"):
        sandstorm.save_field(str(tmp_path / "bad.vti"), values[..., :2], (lo, hi))


def test_a_series_has_its_times_and_steps(tmp_path):
    dims, lo, hi = (3, 3, 3), (0.0, 0.0, 0.0), (1.0, 1.0, 1.0)
    x, y, z = grid(dims, lo, hi)
    entries = ""
    for i, t in enumerate([0.0, 0.5, 1.25]):
        write_vti(tmp_path / ("s%d.vti" % i), dims, lo, hi, analytic(x, y, z) * (i + 1))
        entries += '<DataSet timestep="%r" file="s%d.vti"/>\n' % (t, i)
    (tmp_path / "s.pvd").write_text('<?xml version="1.0"?>\n<VTKFile type="Collection" '
                                    'version="0.1">\n<Collection>\n%s</Collection>\n'
                                    '</VTKFile>\n' % entries)
    f = sandstorm.load_field(str(tmp_path / "s.pvd"), time_step=2)
    assert f.times == [0.0, 0.5, 1.25]
    np.testing.assert_allclose(f.values, analytic(x, y, z) * 3, rtol=1e-6)


def test_a_runs_particles_and_image_are_the_applications(tmp_path):
    sets = {"emitter.0.rate": 12000, "render.size": 0.2}
    app("--config", CONFIG, "--walls", "front", "--frames", "20",
        "--set", "emitter.0.rate=12000", "--set", "render.size=0.2",
        "--dump-particles", str(tmp_path / "app.vtp"), "--screenshot", str(tmp_path))
    with sandstorm.Run(CONFIG, set=sets, walls=["front"]) as run:
        assert run.walls == ["front"]
        run.step(12)
        run.step(8)
        assert run.frames == 20
        p = run.particles()
        image = run.image()
        stats = run.stats()
    dumped = read_appended_vtp(tmp_path / "app.vtp")
    assert len(p["position"]) > 1000
    np.testing.assert_array_equal(p["position"], dumped["Points"])
    np.testing.assert_array_equal(p["velocity"], dumped["velocity"])
    np.testing.assert_array_equal(p["age"], dumped["age"])
    np.testing.assert_array_equal(p["life_remaining"], dumped["life_remaining"])
    png = read_png(tmp_path / "front.png")
    assert image.shape == (128, 128, 3) and image.dtype == np.uint8
    np.testing.assert_array_equal(image, png[:, :, :3])
    assert stats["frames"] == 20 and stats["walls"][0]["name"] == "front"


def test_streamlines_and_trails_are_the_applications(tmp_path):
    sets = ["streamlines.enabled=true", "render.trail_length=4"]
    app("--config", CONFIG, "--walls", "front", "--frames", "6",
        *sum((["--set", s] for s in sets), []),
        "--dump-streamlines", str(tmp_path / "lines.vtp"),
        "--dump-trails", str(tmp_path / "trails.vtp"))
    with sandstorm.Run(CONFIG, set={"streamlines.enabled": True, "render.trail_length": 4},
                       walls=["front"]) as run:
        run.step(6)
        lines, trails = run.streamlines(), run.trails()
    for ours, path in ((lines, "lines.vtp"), (trails, "trails.vtp")):
        theirs = read_ascii_vtp_lines(tmp_path / path)
        assert len(ours) == len(theirs) > 0
        for a, b in zip(ours, theirs):
            np.testing.assert_allclose(a["points"], b, rtol=1e-6, atol=1e-6)
            assert a["velocity"].shape == a["points"].shape
            assert a["speed"].shape == (len(a["points"]),)
            assert np.isclose(a["arc_length"], 0).any()  # the seed (a trail: its particle)


def test_set_mid_run_changes_what_follows():
    with sandstorm.Run(CONFIG, walls=["front"]) as run:
        run.step(10)
        before = len(run.particles()["position"])
        run.set("emitter.0.rate", 40000)
        run.set("emitter.0.velocity", [0, 0, 1.5])
        run.step(10)
        assert len(run.particles()["position"]) > before


def test_bad_arguments_raise_with_sandstorms_message(tmp_path):
    with pytest.raises(sandstorm.Error, match="no-such.vti"):
        sandstorm.load_field(str(tmp_path / "no-such.vti"))
    with pytest.raises(sandstorm.Error, match="resolution has 2 numbers"):
        sandstorm.load_field(str(SOURCE / "data" / "tornado.vti"), resolution=(4, 4))
    with pytest.raises(sandstorm.Error, match="cannot read 'big'"):
        sandstorm.Run(CONFIG, set={"render.size": "big"})
    with pytest.raises(sandstorm.Error, match="--set gpu.update_items=3: gpu.update_items: expected"):
        sandstorm.Run(CONFIG, set={"gpu.update_items": 3})
    with pytest.raises(sandstorm.Error, match="no wall named 'ceiling'"):
        sandstorm.Run(CONFIG, walls=["ceiling"])
    with pytest.raises(sandstorm.Error, match="unknown extension"):
        sandstorm.Run(CONFIG, movie=str(tmp_path / "a.avi"))
    run = sandstorm.Run(CONFIG, walls=["front"])
    with pytest.raises(sandstorm.Error, match="step\\(\\) the run first"):
        run.particles()
    with pytest.raises(sandstorm.Error, match="no.such"):
        run.set("no.such", 1)
    with pytest.raises(sandstorm.Error, match="expected 1 or more"):
        run.step(0)
    with pytest.raises(sandstorm.Error, match="wall 3"):
        run.step(1)
        run.image(3)
    assert run.close() == 0
    with pytest.raises(sandstorm.Error, match="closed"):
        run.step()
    assert isinstance(sandstorm.Error("x"), RuntimeError)


def test_a_run_writes_a_movie(tmp_path):
    with sandstorm.Run(CONFIG, walls=["front"], movie=str(tmp_path / "a.mp4")) as run:
        run.step(12)
    data = (tmp_path / "a.mp4").read_bytes()
    assert data[4:8] == b"ftyp" and len(data) > 1000


def test_closing_a_run_ends_its_threads_and_contexts():
    def threads():
        return len(os.listdir("/proc/self/task"))
    with sandstorm.Run(CONFIG, walls=["front"]) as run:  # a first run: libraries load
        run.step(2)
    before = threads()
    for _ in range(3):
        run = sandstorm.Run(CONFIG)  # four walls drawn by a thread of their own
        run.step(2)
        assert threads() > before
        assert run.close() == 0
        assert threads() == before
