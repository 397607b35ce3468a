"""The Python overhead of World.step(n) (issue 63): the time of a call that
steps nothing (step(0): argument checks and the ctypes call) against the
time of step(n) at N = 4096 (GI-BD stars, the 2014 scene), each the median
of many calls.  usage: python3 bench/python_overhead.py [n=100] [N=4096]"""
import os
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "python"))
import hcbd  # noqa: E402


def median(x):
    x = sorted(x)
    return x[len(x) // 2]


args = dict(a.split("=") for a in sys.argv[1:])
n, N = int(args.get("n", 100)), int(args.get("N", 4096))
w = hcbd.World(N=N, density=0.24, seed=1, threads=1)
w.step(200)
empty, full = [], []
for _ in range(15):
    t = time.perf_counter()
    for _ in range(1000):
        w.step(0)
    empty.append((time.perf_counter() - t) / 1000)
    t = time.perf_counter()
    w.step(n)
    full.append(time.perf_counter() - t)
e, f = median(empty), median(full)
print("python_overhead: N = %d, step(%d) takes %.3g s (%.0f ns per particle-step); a call costs %.2g s: %.4f %% of it"
      % (N, n, f, 1e9 * f / (n * N), e, 100 * e / f))
