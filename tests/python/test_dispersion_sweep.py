"""tests/python/test_dispersion_sweep.py -- examples/python/dispersion_sweep.py: the sweep on a
local Dask cluster gives the same statistics as the same chunks in this process, the closed
form is compiled once per worker, and the sine law of the swing plane holds to the order the
thesis states it (first order in |w| t)."""
import os
import subprocess
import sys

import numpy as np
import pytest
from conftest import SOURCE_DIR

EXAMPLES = os.path.join(SOURCE_DIR, "examples", "python")
sys.path.insert(0, EXAMPLES)
import dispersion_sweep as ds  # noqa: E402


def test_sweep_on_a_local_cluster_matches_this_process():
    from dask.distributed import Client, LocalCluster

    # the workers unpickle the tasks by module name: they need the example on their path
    import symrep

    package = os.path.dirname(os.path.dirname(os.path.abspath(symrep.__file__)))
    os.environ["PYTHONPATH"] = os.pathsep.join([EXAMPLES, package, os.environ.get("PYTHONPATH", "")])
    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None,
                      silence_logs=40) as cluster, Client(cluster) as client:
        client.run(ds.compile_here)
        stats, wall = ds.sweep(client, 30000, 7000, 3600.0)
        per_worker = client.run(ds.worker_compilations)
    assert stats["scenes"] == 30000
    assert sorted(per_worker.values()) == [1, 1]  # compiled once per worker, not per task
    here = ds.combine([ds.chunk_statistics(k, n, 3600.0) for k, n in enumerate([7000] * 4 + [2000])])
    # the same scenes, the same compiled program: the same numbers (sums in another order: 1e-12)
    assert here["scenes"] == stats["scenes"]
    assert abs(here["mean"] - stats["mean"]) <= 1e-12 * abs(here["mean"])
    assert here["max"] == stats["max"]
    # the sine law after one hour (|w| t ~ 0.26): second-order differences, well under 0.05 rad
    assert 0 < stats["mean"] < 0.05 and stats["max"] < 0.1


def test_the_example_runs_and_reports_throughput():
    env = dict(os.environ)
    r = subprocess.run([sys.executable, os.path.join(SOURCE_DIR, "examples", "python", "dispersion_sweep.py"),
                        "--scenes", "20000", "--chunk", "5000"], capture_output=True, text=True, env=env,
                       timeout=300)
    assert r.returncode == 0, r.stderr
    assert "scenes: 20000" in r.stdout
    assert "compiled once per worker: [1, 1]" in r.stdout
    assert "scenes/s per core" in r.stdout
