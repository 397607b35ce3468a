"""The same seed and parameters from Python and from C end in the same state
hash: GI-BD against the gibd_bulk example, the walled channel and the 2018
world against the golden hashes of tests/test_golden.c (the C suite's)."""
import math
import os
import re
import subprocess

import hcbd

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))


def golden(index):
    text = open(os.path.join(ROOT, "tests", "test_golden.c")).read()
    dbl = re.search(r"static const uint64_t dbl\[G_N\] = \{([^}]*)\}", text).group(1)
    return int(re.findall(r"0x([0-9a-f]+)ULL", dbl)[index], 16)


def test_gibd_as_the_c_example():
    exe = os.path.join(ROOT, "build", "gibd_bulk")
    subprocess.run(["make", "-s", "-C", ROOT, "build/gibd_bulk"], check=True, capture_output=True)
    out = subprocess.run([exe, "steps=1000", "out=" + os.path.join(ROOT, "build", "pytest_gibd_bulk")],
                         check=True, capture_output=True, text=True).stdout
    c = int(re.search(r"state_checksum=([0-9a-f]{16})", out).group(1), 16)
    w = hcbd.World(N=512, density=0.24)  # the example's defaults
    w.step(6000)  # its 5000 steps of equilibration and 1000 measured
    assert w.checksum() == c


def test_walled_channel_as_the_c_golden():
    for threads in (1, 2):
        w = hcbd.World(N=512, density=0.24, L=[12.9, 13.0, 12.9], seed=104, wall_thickness=1.5,
                       potential="ideal", fext=[20.0, 0.0, 0.0], tau=3e-3, threads=threads)
        w.step(300)
        assert w.checksum() == golden(3), threads


def test_hcbd_as_the_c_golden():
    a = 1.6119919540164696
    nbar = 3.0 / (4.0 * 3.14159265358979323846)
    rho = 1.0 * nbar
    h = hcbd.HCWorld(fluid=12 * 8 * 5, polymers=60, L=[12 * a, 8 * a, 5 * a], dt=0.02, kT=1.0, nbar=nbar, rho=rho,
                     eta=1.0 * rho, P0=5.0 * 5.0 * rho / 7.0, h=1.3, fluctuations=1, xi=10.0, sigma=1.0, rc=2.5,
                     alpha=50.0, tau_lambda=0.5, p_kuhn=100.0, n_max=5.0, chi=0.5, seed=7, gdot=0.05, threads=2)
    h.step(200)
    assert h.checksum() == golden(4)
