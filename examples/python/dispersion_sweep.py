"""A dispersion study of the Foucault pendulum with Dask (docs/python.md, "Sweeps").

Thousands to millions of scenes -- latitudes, rotation rates, pendulum lengths, release
points and pushes drawn at random -- evaluated with ONE closed form: symrep derives the
exact solution of r'' + 2 w x r' + w x (w x r) + w0^2 r = 0 once, each Dask worker compiles
it once (numeric/evaluator.h) and evaluates its chunks of scenes over NumPy arrays. The
same code runs on a local cluster (the default) or on a multi-machine one:

    python3 examples/python/dispersion_sweep.py                         # local cluster, 2 workers
    python3 examples/python/dispersion_sweep.py --scenes 1000000 --workers 4
    python3 examples/python/dispersion_sweep.py --scheduler tcp://host:8786   # dask-scheduler / dask-worker

(the workers need the symrep package on their PYTHONPATH: build/python). It prints the
statistics of the swing plane's turn after the time T (against the sine law of the
thesis, VI.1.86: a turn of -|w| sin(latitude) T) and the throughput per core.
"""
import argparse
import math
import os
import sys
import time

import numpy as np

import symrep

CLOSED_FORM = "solve(ode(r'' + 2*w x r' + w x (w x r) + w0^2*r = 0, r(0) = r0, r'(0) = v0))"
EARTH_RATE = 7.2921e-5


def _holder():
    """Where this process keeps its compiled closed form: the Dask worker when there is one
    (a worker keeps it between tasks), else this module."""
    try:
        from distributed import get_worker

        return get_worker()
    except (ImportError, ValueError):
        return sys.modules[__name__]


def closed_form():
    """The compiled closed form, compiled once per process."""
    holder = _holder()
    f = getattr(holder, "_symrep_closed_form", None)
    if f is None:
        s = symrep.Session()
        s.eval("vector w, r0, v0; positive w0")
        f = s.compile(s.eval(CLOSED_FORM), ["t", "w", "w0", "r0", "v0"])
        holder._symrep_closed_form = f
        holder._symrep_compilations = getattr(holder, "_symrep_compilations", 0) + 1
    return f


def scenes(seed, n):
    """n random scenes (seeded: the same chunk gives the same scenes on every machine)."""
    rng = np.random.default_rng(seed)
    lat = np.radians(rng.uniform(-80.0, 80.0, n))
    rate = EARTH_RATE * (1 + 1e-3 * rng.standard_normal(n))
    w = np.stack([rate * np.cos(lat), np.zeros(n), rate * np.sin(lat)], axis=1)
    w0 = np.sqrt(9.81 / rng.uniform(10.0, 100.0, n))
    r0 = np.stack([rng.uniform(1.0, 3.0, n), 1e-3 * rng.standard_normal(n), np.zeros(n)], axis=1)
    v0 = np.stack([1e-4 * rng.standard_normal(n), 1e-4 * rng.standard_normal(n), np.zeros(n)], axis=1)
    return lat, rate, w, w0, r0, v0


def chunk_statistics(seed, n, T):
    """Evaluates n scenes near the time T; returns [count, sum, sum of squares, max] of the
    difference between the swing plane's turn and the sine law, in radians."""
    f = closed_form()
    lat, rate, w, w0, r0, v0 = scenes(seed, n)
    # each scene at its own time: the end of the swing nearest to T (w0 t a multiple of 2 pi,
    # where psi = r0 and r is r0 turned about w, VI.1.79), so that the azimuth is defined
    t = 2 * np.pi * np.maximum(np.round(T * w0 / (2 * np.pi)), 1) / w0
    x = f(t=t, w=w, w0=w0, r0=r0, v0=v0)
    # the swing plane's azimuth at t against its azimuth at 0 (the release point), folded
    # to (-pi/2, pi/2] (a plane has no direction)
    turn = np.arctan2(x[:, 1], x[:, 0]) - np.arctan2(r0[:, 1], r0[:, 0])
    turn = (turn + np.pi / 2) % np.pi - np.pi / 2
    law = -rate * np.sin(lat) * t
    law = (law + np.pi / 2) % np.pi - np.pi / 2
    d = np.abs(turn - law)
    d = np.minimum(d, np.pi - d)
    return np.array([n, d.sum(), (d * d).sum(), d.max()])


def combine(parts):
    p = np.array(parts)
    n = p[:, 0].sum()
    mean = p[:, 1].sum() / n
    return {"scenes": int(n), "mean": mean, "rms": math.sqrt(p[:, 2].sum() / n), "max": p[:, 3].max()}


def worker_compilations():
    return getattr(_holder(), "_symrep_compilations", 0)


def compile_here():
    """Compiles the closed form in this process if it is not yet; returns the number of
    compilations so far (for client.run: a Compiled does not travel between processes)."""
    closed_form()
    return worker_compilations()


def sweep(client, n_scenes, chunk, T):
    """The sweep on a Dask cluster: one task per chunk; returns the statistics and the
    wall time."""
    seeds = range(math.ceil(n_scenes / chunk))
    sizes = [min(chunk, n_scenes - k * chunk) for k in seeds]
    t0 = time.perf_counter()
    futures = client.map(chunk_statistics, list(seeds), sizes, [T] * len(sizes), pure=False)
    stats = combine(client.gather(futures))
    return stats, time.perf_counter() - t0


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--scenes", type=int, default=200000, help="number of scenes (default 200000)")
    p.add_argument("--chunk", type=int, default=20000, help="scenes per task (default 20000)")
    p.add_argument("--hours", type=float, default=1.0, help="the time T in hours (default 1)")
    p.add_argument("--workers", type=int, default=2, help="local workers, one thread each (default 2)")
    p.add_argument("--scheduler", help="address of a running Dask scheduler (else a local cluster)")
    a = p.parse_args(argv)
    from dask.distributed import Client, LocalCluster

    T = 3600.0 * a.hours
    cluster = None
    if a.scheduler:
        client = Client(a.scheduler)
    else:
        # one single-threaded process per worker: the engine's GiNaC state is per process
        cluster = LocalCluster(n_workers=a.workers, threads_per_worker=1, processes=True,
                               dashboard_address=None, silence_logs=40)
        client = Client(cluster)
    try:
        cores = sum(client.nthreads().values())
        client.run(compile_here)  # compile once per worker, outside the timed sweep
        stats, wall = sweep(client, a.scenes, a.chunk, T)
        per_worker = client.run(worker_compilations)
        # the same closed form in this process, one chunk, for the cost per scene on one core
        closed_form()
        t0 = time.perf_counter()
        chunk_statistics(0, a.chunk, T)
        one = time.perf_counter() - t0
    finally:
        client.close()
        if cluster is not None:
            cluster.close()
    print("closed form: %s" % CLOSED_FORM)
    print("scenes: %d at T = %g s on %d cores (%s)" % (stats["scenes"], T, cores,
                                                      a.scheduler or "local cluster"))
    print("swing plane against the sine law (VI.1.86): mean %.3e rad, rms %.3e rad, max %.3e rad"
          % (stats["mean"], stats["rms"], stats["max"]))
    print("compiled once per worker: %s" % sorted(per_worker.values()))
    print("throughput: %.3g scenes/s, %.3g scenes/s per core (one core without Dask: %.3g scenes/s)"
          % (stats["scenes"] / wall, stats["scenes"] / wall / cores, a.chunk / one))
    return 0


if __name__ == "__main__":
    sys.exit(main())
