"""Executors of the design of experiments: serial, process pool, thread pool, Dask distributed.

Each runs :func:`udmap.doe.worker.run_chunk` on chunks ``(start, values, refs)`` and yields its
results in completion order (the output puts them back in design order). A bounded number of
chunks is in flight, so millions of designs never sit in memory as futures. Worker processes keep
their context (the nominal case, the shared blade, the model and its tracings) for the whole run:
the pool stays warm.
"""
from __future__ import annotations

import math
import os
import signal
import threading
import time
from concurrent.futures import FIRST_COMPLETED, wait

from ..errors import InputError, error_from_status
from .worker import run_chunk


def default_chunk(samples: int, workers: int) -> int:
    """Designs per chunk: about eight chunks per worker for load balance, at most 256 (one chunk
    is what an interruption can lose per worker) and at least 1."""
    return max(1, min(256, math.ceil(samples / (8 * max(workers, 1)))))


def chunk_ranges(first: int, samples: int, held, chunk: int) -> list[tuple[int, int]]:
    """The ``(start, stop)`` ranges of at most ``chunk`` designs that cover designs
    ``first .. samples-1`` except the ``(start, count)`` ranges ``held`` (already computed)."""
    ranges = []
    pos = first
    for start, count in sorted(held) + [(samples, 0)]:
        while pos < start:
            stop = min(pos + chunk, start)
            ranges.append((pos, stop))
            pos = stop
        pos = max(pos, start + count)
    return ranges


def default_workers() -> int:
    """The cores this process may run on."""
    try:
        return max(len(os.sched_getaffinity(0)), 1)
    except AttributeError:
        return max(os.cpu_count() or 1, 1)


def _init_worker(parent: int) -> None:
    """Worker process set-up: Ctrl-C is handled by the parent, which stops the pool (workers
    must not die noisily), and a worker whose parent was killed exits instead of lingering."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)

    def watch():
        while os.getppid() == parent:
            time.sleep(0.5)
        os._exit(1)

    threading.Thread(target=watch, name="udmap-doe-parent-watch", daemon=True).start()


class SerialExecutor:
    """Runs the chunks in this process, one after the other."""
    kind = "serial"
    workers = 1
    startup_seconds = 0.0

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        return False

    def run(self, spec, ranges):
        for start, values, refs in ranges:
            yield run_chunk(spec, start, values, refs)


class PoolExecutor:
    """A pool of ``workers`` processes or threads (the kernel releases the GIL in every call;
    each thread has its own objects)."""

    def __init__(self, workers: int, threads: bool = False):
        self.workers = workers
        self.threads = threads
        self.kind = "thread" if threads else "process"
        self.pool = None
        self.startup_seconds = 0.0

    def __enter__(self):
        from concurrent.futures import ProcessPoolExecutor, ThreadPoolExecutor
        import multiprocessing
        t0 = time.perf_counter()
        if self.threads:
            self.pool = ThreadPoolExecutor(max_workers=self.workers)
        else:
            # fork where there is one: fast start, and a user's script is not run again in
            # every worker (spawn imports __main__); the kernel starts no threads of its own.
            method = "fork" if "fork" in multiprocessing.get_all_start_methods() else "spawn"
            self.pool = ProcessPoolExecutor(max_workers=self.workers,
                                            mp_context=multiprocessing.get_context(method),
                                            initializer=_init_worker,
                                            initargs=(os.getpid(),))
        self.startup_seconds = time.perf_counter() - t0
        return self

    def __exit__(self, *exc):
        if self.pool is not None:
            self.pool.shutdown(wait=exc[0] is None, cancel_futures=True)
            self.pool = None
        return False

    def run(self, spec, ranges):
        todo = iter(ranges)
        pending = set()

        def submit():
            item = next(todo, None)
            if item is not None:
                pending.add(self.pool.submit(run_chunk, spec, *item))

        for _ in range(2 * self.workers):
            submit()
        while pending:
            done, _ = wait(pending, return_when=FIRST_COMPLETED)
            for fut in done:
                pending.discard(fut)
                yield fut.result()
                submit()


def _dask_chunk_function():
    """The function a Dask worker runs on a chunk, made inside this function so that it is not
    importable by name: cloudpickle then sends it by value (its code, with no globals), and the
    scheduler, which unpickles the task graph, needs only dask and distributed, not udmap. The
    worker imports udmap when it runs the task. The arguments (the spec, the design values) and
    the result are plain Python data; a udmap error comes back as ``("error", status,
    message)`` rather than as an exception of a udmap class, for the same reason."""

    def udmap_doe_chunk(spec, start, values, refs=None):
        import udmap.doe.worker
        try:
            return ("ok", udmap.doe.worker.run_chunk(spec, start, values, refs))
        except udmap.UdmapError as exc:
            return ("error", exc.status, str(exc))

    return udmap_doe_chunk


def _dask_result(reply):
    """The chunk result of :func:`_dask_chunk_function`'s reply, or its udmap error raised."""
    if reply[0] == "ok":
        return reply[1]
    raise error_from_status(reply[1], reply[2])


class DaskExecutor:
    """Dask distributed: ``local:K`` starts a LocalCluster of K single-threaded worker processes,
    ``tcp://HOST:PORT`` (or any scheduler address) uses a running cluster, whose workers must be
    able to import udmap and load its library (and read the case's files); its scheduler needs
    only dask and distributed (see :func:`_dask_chunk_function`)."""
    kind = "dask"

    def __init__(self, address: str):
        self.address = address
        self.client = None
        self.cluster = None
        self.workers = 1
        self.startup_seconds = 0.0
        if address.startswith("local:"):
            try:
                self.local = int(address[len("local:"):])
            except ValueError:
                raise InputError(f"--dask {address}: expected local:K with K workers") from None
            if self.local < 1:
                raise InputError(f"--dask {address}: K must be at least 1")
        elif "://" in address:
            self.local = None
        else:
            raise InputError(f"--dask {address}: expected local:K or a scheduler address "
                             "such as tcp://HOST:PORT")
        try:
            import distributed  # noqa: F401
        except ImportError:
            raise InputError("--dask needs the Python packages dask and distributed "
                             "(pip install dask distributed)") from None

    def __enter__(self):
        import logging
        from distributed import Client, LocalCluster
        t0 = time.perf_counter()
        if self.local is not None:
            self.cluster = LocalCluster(n_workers=self.local, threads_per_worker=1,
                                        processes=True, dashboard_address=None,
                                        silence_logs=logging.ERROR)
            self.client = Client(self.cluster)
        else:
            try:
                self.client = Client(self.address, timeout=30)
            except (OSError, TimeoutError) as exc:
                raise InputError(f"--dask {self.address}: cannot reach the scheduler: "
                                 f"{exc}") from None
        info = self.client.scheduler_info()
        self.workers = max(sum(w.get("nthreads", 1) for w in info["workers"].values()), 1)
        self.startup_seconds = time.perf_counter() - t0
        return self

    def __exit__(self, *exc):
        if self.client is not None:
            self.client.close()
            self.client = None
        if self.cluster is not None:
            self.cluster.close()
            self.cluster = None
        return False

    def run(self, spec, ranges):
        from distributed import as_completed
        chunk_function = _dask_chunk_function()
        spec_future = self.client.scatter(spec, broadcast=True)
        todo = iter(ranges)

        def submit():
            item = next(todo, None)
            if item is None:
                return None
            return self.client.submit(chunk_function, spec_future, *item, pure=False)

        first = [f for f in (submit() for _ in range(2 * self.workers)) if f is not None]
        queue = as_completed(first)
        for fut in queue:
            yield _dask_result(fut.result())
            fut.release()
            nxt = submit()
            if nxt is not None:
                queue.add(nxt)


def make_executor(workers: int | None = None, threads: bool = False, dask: str | None = None):
    """The executor for the options: Dask if ``dask``, else ``workers`` processes or threads
    (default: all cores), serial for one worker."""
    if dask:
        return DaskExecutor(dask)
    if workers is None:
        workers = default_workers()
    if workers < 1:
        raise InputError(f"--workers must be at least 1, got {workers}")
    if workers == 1:
        return SerialExecutor()
    return PoolExecutor(workers, threads=threads)
