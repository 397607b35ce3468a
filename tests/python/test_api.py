"""The Python API over the unchanged header: worlds from keywords, steps in C,
zero-copy views of the storage, copies in id order, errors as exceptions with
the library's messages, checkpoints, trajectories, observables."""
import gc
import math
import os

import numpy as np
import pytest

import hcbd


def small(**kw):
    kw.setdefault("N", 216)
    kw.setdefault("density", 0.24)
    kw.setdefault("seed", 5)
    return hcbd.World(**kw)


def test_defaults_are_the_c_defaults():
    w = hcbd.World(N=512)
    # the 2014 scene: 512 stars at n# = 0.24 in a cube of 512/0.24
    assert w.n == 512
    assert np.allclose(w.box, math.cbrt(512 / 0.24))
    assert w.step_count == 0


def test_views_are_the_storage_and_copies_are_in_id_order():
    w = small()
    w.step(300)  # list rebuilds re-sort the storage
    x, y, z, ids = w.x, w.y, w.z, w.id
    assert x.shape == (216,) and not x.flags.writeable and not ids.flags.writeable
    assert sorted(ids.tolist()) == list(range(216))
    xyz = w.positions()
    assert xyz.shape == (216, 3)
    # slot s holds particle ids[s]
    assert np.array_equal(xyz[ids, 0], x) and np.array_equal(xyz[ids, 1], y) and np.array_equal(xyz[ids, 2], z)
    v = w.velocities()
    assert np.array_equal(v[ids, 0], w.vx)
    # a view shows the world as it is now: the same memory
    before = x.copy()
    w.step(10)
    assert not np.array_equal(before, x)
    with pytest.raises(ValueError):
        x[0] = 1.0


def test_a_view_keeps_its_world_alive():
    w = small()
    x = w.x
    expect = w.positions()[w.id, 0].copy()
    del w
    gc.collect()
    assert np.array_equal(x, expect)


def test_setters_and_unwrapped_positions():
    w = small(N=8, L=[10.0, 10.0, 10.0], potential="ideal", kT=0.0)
    xyz = np.array([[1.0 + 1.1 * i, 2.0, 3.0 + 0.7 * i] for i in range(8)])
    w.set_positions(xyz)
    assert np.allclose(w.positions(), xyz)
    v = np.tile([0.5, 0.0, 0.0], (8, 1))
    w.set_velocities(v)
    assert np.allclose(w.velocities(), v)
    with pytest.raises(ValueError, match="rows"):
        w.set_velocities(np.zeros((3, 3)))


def test_bad_values_raise_value_error_naming_the_parameter():
    for kw, name in [({"dt": -1.0}, "dt"), ({"kT": float("nan")}, "kT"), ({"tau": 0.0}, "tau"),
                     ({"Rc": float("inf")}, "Rc"), ({"threads": 0}, "threads"), ({"density_norm": 2015}, "density_norm")]:
        with pytest.raises(ValueError, match=name):
            small(**kw)
    with pytest.raises(ValueError, match="unknown parameter 'bogus'"):
        small(bogus=1)
    with pytest.raises(ValueError, match="pair_integrator"):
        small(pair_integrator="rk4")
    with pytest.raises(ValueError, match="seed"):
        small(seed=-1)
    with pytest.raises(ValueError, match="L takes 3"):
        small(L=[1.0, 2.0])
    with pytest.raises(ValueError, match="N = 0"):
        hcbd.World(N=0)
    with pytest.raises(ValueError, match="step"):
        small().step(-1)


def test_a_failed_step_raises_and_names_the_limit():
    # two stars on top of each other at a huge step: the displacement guard
    w = small(N=2, L=[8.0, 8.0, 8.0], dt=1.0, min_distance=0.0)
    w.set_positions([[4.0, 4.0, 4.0], [4.05, 4.0, 4.0]])
    with pytest.raises(hcbd.HcbdError) as e:
        w.step(5)
    assert "step" in str(e.value)


def test_keyword_fuzz_never_crashes():
    rng = np.random.default_rng(1)
    keys = ["dt", "kT", "xi", "xip", "tau", "Rc", "f", "sigma", "rcut", "skin", "gdot", "threads", "density_norm",
            "guard_every", "min_distance", "star_eps", "wall_thickness", "wall_a", "lagged_density", "sort"]
    values = [0.0, -1.0, 1e-300, 1e300, float("nan"), float("inf"), -float("inf"), 3, 2014, 2016, 1e-4, 0.5,
              2 ** 40, "x", None, [1, 2, 3]]
    made = refused = 0
    for _ in range(300):
        kw = {str(rng.choice(keys)): values[rng.integers(len(values))] for _ in range(rng.integers(1, 4))}
        try:
            w = hcbd.World(N=125, density=0.24, **kw)
            w.step(2)
            made += 1
        except (ValueError, hcbd.HcbdError):
            refused += 1
    assert made > 0 and refused > 0


def test_checkpoint_restart_and_threads_give_the_same_bits(tmp_path):
    a = small(gdot=2.0)
    a.step(200)
    a.save(str(tmp_path / "a.ckpt"))
    a.step(200)
    b = hcbd.World.load(str(tmp_path / "a.ckpt"))
    b.set_threads(2)
    b.step(200)
    assert a.checksum() == b.checksum()
    assert b.step_count == 400
    with pytest.raises(hcbd.HcbdError):
        hcbd.World.load(str(tmp_path / "missing.ckpt"))


def test_xyz_frames(tmp_path):
    w = small(N=125)
    p = str(tmp_path / "t.xyz")
    w.write_xyz(p, append=False)
    w.step(5)
    w.write_xyz(p)
    lines = open(p).read().splitlines()
    assert lines[0] == "125" and lines[127] == "125" and "Lattice=" in lines[1]


def test_temperature_momentum_and_stress():
    w = small(N=512, gdot=2.0)
    w.step(200)
    assert 0.8 < w.temperature() < 1.2
    assert np.all(np.abs(w.momentum()) < 1e-9)
    w.stress_enable()
    w.step(50)
    s = w.stress_read()
    assert s["steps"] == 50 and s["total"] == pytest.approx(s["pair"] + s["background"] + s["boundary"])


def test_rdf_of_an_ideal_gas_is_one():
    w = small(N=1000, potential="ideal", dynamics="bd", place="random", seed=3)
    g = hcbd.RDF(rmax=3.0, nbins=6, block=5)
    for _ in range(20):
        w.step(20)
        g.sample(w)
    r, gr, err = g.result()
    assert np.all(np.abs(gr - 1) < 5 * err + 0.02), (gr, err)


def test_msd_of_free_brownian_particles():
    # classical BD, no forces: <dr^2> = 6 kT t / xi
    w = small(N=500, potential="ideal", dynamics="bd", place="random", brownian="euler", seed=4)
    m = hcbd.MSD(500, B=10, levels=2, block=50)
    for _ in range(400):
        w.step(1)
        m.add(w.positions(unwrapped=True))
    D, err = m.diffusion(1, 30)
    D /= 1e-4  # per unit time: dt = 1e-4
    err /= 1e-4
    assert abs(D - 1.0) < 5 * err + 0.02


def test_carreau_fit_recovers_its_curve():
    g = np.logspace(-2, 2, 9)
    eta = 1.0 + (5.0 - 1.0) * (1 + (2.0 * g) ** 2) ** ((0.4 - 1) / 2)
    f = hcbd.carreau_fit(g, eta, 0.01 * eta, eta_inf=1.0)
    assert f["eta0"] == pytest.approx(5.0, rel=1e-6) and f["lambda"] == pytest.approx(2.0, rel=1e-6)
    assert f["n"] == pytest.approx(0.4, abs=1e-6)
    with pytest.raises(ValueError):
        hcbd.carreau_fit(g[:3], eta[:3], eta[:3], 1.0)


def test_blocking_error_of_white_noise():
    x = np.random.default_rng(2).normal(size=4096)
    m, e, neff, plateau = hcbd.blocking_error(x)
    assert abs(e - 1 / 64) < 0.3 / 64 and abs(m) < 4 * e


def test_hcworld_fluid_and_polymers(tmp_path):
    h = hcbd.HCWorld(fluid=806, polymers=30, seed=3, gdot=1e-5)
    assert h.n_fluid == 806 and h.n_polymers == 30
    x, v = h.fluid()
    assert np.array_equal(x[:, 0], h.fx) and np.array_equal(v[:, 1], h.fvy) and not h.fx.flags.writeable
    assert np.array_equal(h.polymers()[:, 2], h.pz)
    h.stress_enable()
    h.step(20)
    s = h.stress_read()
    assert s["steps"] == 20
    assert s["total"] == pytest.approx(s["fluid"] + s["polymer"] + s["interaction"], rel=1e-12, abs=1e-12)
    lo, hi, pmin = h.density_range()
    assert 0.9 < lo <= hi < 1.1
    h.save(str(tmp_path / "h.ckpt"))
    h.step(10)
    k = hcbd.HCWorld.load(str(tmp_path / "h.ckpt"))
    k.step(10)
    assert h.checksum() == k.checksum()
    with pytest.raises(ValueError, match="coupling"):
        hcbd.HCWorld(fluid=806, coupling="exact")
    with pytest.raises(ValueError, match="eta"):
        hcbd.HCWorld(fluid=806, eta=-1.0)


def test_params_read_back_what_was_set():
    w = small(tau=2e-3, potential="ideal", pair_integrator="euler", seed=2 ** 64 - 1, fext=[1.0, 0, 0])
    p = w.params
    assert p["tau"] == 2e-3 and p["potential"] == "ideal" and p["pair_integrator"] == "euler"
    assert p["seed"] == 2 ** 64 - 1 and isinstance(p["threads"], int)
    assert np.array_equal(p["fext"], [1.0, 0, 0]) and np.allclose(p["L"], w.box)
    assert hcbd.HCWorld(fluid=806, coupling="raw").params["coupling"] == "raw"


def test_transverse_current_is_the_sum_over_particles():
    """j(k) = sum_i v_i,a exp(-i k x_i,d) for the two components a = d+1, d+2 (mod 3), from
    the copies in id order: the C sum and numpy's agree to round-off."""
    w = small(potential="ideal")
    w.step(20)
    x, v, L = w.positions(), w.velocities(), w.box
    j = w.transverse_current(2)
    for d in range(3):
        ph = np.exp(-1j * 2 * np.pi * 2 / L[d] * x[:, d])
        ref = [np.sum(v[:, (d + c) % 3] * ph) for c in (1, 2)]
        scale = np.sum(np.abs(v))
        assert np.allclose(j[d], ref, rtol=0, atol=1e-12 * scale), (d, j[d], ref)


def test_friction_average_and_forces():
    """Averaged over the three axes, 1 - cos(k x_d) lies between k^2 r^2 / 6 (1 - k^2 r^2 / 12)
    and k^2 r^2 / 6 pair by pair (r < Rc), so sum_f_k lies within the bounds sum_f_r2 sets (the C tests hold each average to its equation); the forces
    sum to zero (Newton's third law)."""
    w = small(N=512)
    w.step(10)
    f = w.forces()
    assert f.shape == (512, 3) and np.abs(f.sum(axis=0)).max() < 1e-9 * np.abs(f).sum()
    a = w.friction_average(1)
    assert a["sum_f"] > 0 and a["sum_f_r2"] > 0
    k = 2 * np.pi / w.box[0]
    kr2 = (k * w.params["Rc"]) ** 2
    assert a["sum_f_r2"] * k ** 2 / 6 * (1 - kr2 / 12) <= a["sum_f_k"] <= a["sum_f_r2"] * k ** 2 / 6
