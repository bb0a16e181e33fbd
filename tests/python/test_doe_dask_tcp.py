"""Design of experiments on a real Dask cluster: a `dask scheduler` and two `dask worker`
processes on 127.0.0.1 (ports chosen by the system), 256 designs through
`udmap doe ... --dask tcp://127.0.0.1:PORT` (the client), and the file compared byte for byte with a serial
run. The scheduler runs where udmap cannot be imported (a `udmap` package that refuses to load
comes first on its path), so the run also shows that only the client and the workers need udmap;
a task that names a udmap function by reference is refused by that same scheduler (the control).
Every process is started in its own session and killed with its group at the end."""
import contextlib
import io
import json
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from udmap.cli import main

ROOT = Path(__file__).resolve().parents[2]
BLADE_A = ROOT / "cases" / "blade_a.json"
DOE = ["doe", str(BLADE_A), "--vary", "mu=0.1:0.8,CF=300:1500", "--samples", "256",
       "--forces", "2,4,6", "--json"]
REFUSAL = "udmap must not be imported by the Dask scheduler"


def _udmap_env():
    """This test's environment, with the udmap it imports first on an absolute PYTHONPATH (the
    client and the workers run in other directories)."""
    import udmap
    env = dict(os.environ)
    paths = [str(Path(udmap.__file__).resolve().parents[1])]
    paths += [str(Path(p).resolve()) for p in env.get("PYTHONPATH", "").split(os.pathsep) if p]
    env["PYTHONPATH"] = os.pathsep.join(paths)
    return env


def _start(args, env, cwd, log):
    with open(log, "w") as out:
        return subprocess.Popen(args, env=env, cwd=cwd, stdout=out, stderr=subprocess.STDOUT,
                                stdin=subprocess.DEVNULL, start_new_session=True)


def _stop(procs):
    for p in procs:
        if p.poll() is None:
            os.killpg(p.pid, signal.SIGTERM)
    deadline = time.monotonic() + 15
    for p in procs:
        try:
            p.wait(timeout=max(deadline - time.monotonic(), 0.1))
        except subprocess.TimeoutExpired:
            os.killpg(p.pid, signal.SIGKILL)
            p.wait(timeout=10)


def _udmap(args):
    """`udmap ARGS` (the command line's main, in this process: a new interpreter importing
    numpy, scipy and distributed costs more than the run on a loaded machine)."""
    out = io.StringIO()
    with contextlib.redirect_stdout(out):
        status = main(args)
    assert status == 0, out.getvalue()
    return json.loads(out.getvalue())


@pytest.fixture(scope="module")
def cluster(tmp_path_factory):
    tmp = tmp_path_factory.mktemp("dask")
    # The scheduler's environment: dask and distributed, and a udmap that refuses to be imported
    # in front of anything else (without it udmap is simply not on the path; the refusal makes
    # the check hold on a machine where udmap is installed too).
    blocked = tmp / "no-udmap"
    (blocked / "udmap").mkdir(parents=True)
    (blocked / "udmap" / "__init__.py").write_text(f"raise ImportError({REFUSAL!r})\n")
    sched_env = {k: v for k, v in os.environ.items() if not k.startswith("UDMAP_")}
    sched_env["PYTHONPATH"] = str(blocked)
    probe = subprocess.run([sys.executable, "-c", "import udmap"], env=sched_env, cwd=tmp,
                           capture_output=True, text=True, timeout=60)
    assert probe.returncode != 0 and REFUSAL in probe.stderr, probe.stderr

    procs = []
    try:
        sched_file = tmp / "scheduler.json"
        procs.append(_start([sys.executable, "-m", "dask", "scheduler", "--host", "127.0.0.1",
                             "--port", "0", "--no-dashboard", "--scheduler-file", sched_file,
                             "--idle-timeout", "600"],
                            sched_env, tmp, tmp / "scheduler.log"))
        deadline = time.monotonic() + 60
        while not sched_file.is_file() or not sched_file.read_text().strip():
            assert procs[0].poll() is None, (tmp / "scheduler.log").read_text()
            assert time.monotonic() < deadline, "the scheduler did not start in 60 s"
            time.sleep(0.2)
        time.sleep(0.2)  # the file is written in one go, but be sure it is complete
        address = json.loads(sched_file.read_text())["address"]
        assert address.startswith("tcp://127.0.0.1:")
        # The workers: this test's environment (PYTHONPATH with wrappers/python, the library).
        for i in range(2):
            procs.append(_start([sys.executable, "-m", "dask", "worker", address, "--nthreads",
                                 "1", "--no-nanny", "--no-dashboard", "--host", "127.0.0.1",
                                 "--death-timeout", "60", "--name", f"w{i}",
                                 "--local-directory", tmp / f"w{i}"],
                                _udmap_env(), tmp, tmp / f"worker{i}.log"))
        from distributed import Client
        with Client(address, timeout=60) as client:
            client.wait_for_workers(2, timeout=60)
            assert len(client.scheduler_info()["workers"]) == 2
        yield address, tmp, procs
    finally:
        _stop(procs)


def test_tcp_cluster_writes_the_serial_file(cluster, tmp_path):
    address, _, procs = cluster
    serial = _udmap(DOE + ["--workers", "1", "--out", str(tmp_path / "serial.csv")])
    dask = _udmap(DOE + ["--dask", address, "--out", str(tmp_path / "dask.csv")])
    assert serial["executor"] == "serial" and dask["executor"] == "dask"
    assert dask["workers"] == 2 and dask["computed"] == dask["written"] == 256
    assert dask["status"] == {"ok": 256}
    assert (tmp_path / "dask.csv").read_bytes() == (tmp_path / "serial.csv").read_bytes()
    assert all(p.poll() is None for p in procs), "a cluster process died during the run"


def test_the_scheduler_cannot_import_udmap(cluster):
    """The control: a task naming udmap.doe.run_chunk by reference cannot even be scheduled
    there, so the run above really went through a scheduler without udmap."""
    address, tmp, _ = cluster
    from distributed import Client

    from udmap.doe import run_chunk
    with Client(address, timeout=60) as client:
        with pytest.raises(Exception, match="deserializ|udmap"):
            client.submit(run_chunk, {}, 0, [], pure=False).result(timeout=60)
    assert REFUSAL in (tmp / "scheduler.log").read_text()
