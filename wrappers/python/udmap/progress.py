"""A dependency-free progress bar with rate and ETA on stderr (shown only on a terminal)."""
from __future__ import annotations

import contextlib
import sys
import threading
import time


class Progress:
    """``with Progress(total, "label") as bar: ... bar.update(n)``; silent unless stderr is a
    TTY or ``force`` is set, and only once the work has run for ``delay`` seconds."""

    def __init__(self, total: int, label: str = "", force: bool = False, delay: float = 1.0,
                 stream=None):
        self.total = max(int(total), 1)
        self.label = label
        self.done = 0
        self.stream = stream or sys.stderr
        self.enabled = force or getattr(self.stream, "isatty", lambda: False)()
        self.delay = delay
        self.start = time.perf_counter()
        self._last = 0.0
        self._shown = False

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        if self._shown:
            self._draw(final=True)
            self.stream.write("\n")
            self.stream.flush()

    @contextlib.contextmanager
    def ticking(self, every: float = 0.25):
        """Redraws the bar every `every` seconds while the block runs (elapsed time and rate
        move even when one step takes long, e.g. a single force of a time integration)."""
        stop = threading.Event()

        def tick():
            while not stop.wait(every):
                self.update(0)
        thread = threading.Thread(target=tick, daemon=True) if self.enabled else None
        if thread is not None:
            thread.start()
        try:
            yield self
        finally:
            stop.set()
            if thread is not None:
                thread.join()

    def update(self, n: int = 1) -> None:
        self.done += n
        now = time.perf_counter()
        if self.enabled and now - self.start >= self.delay and now - self._last >= 0.1:
            self._last = now
            self._draw()

    def _draw(self, final: bool = False) -> None:
        elapsed = time.perf_counter() - self.start
        rate = self.done / elapsed if elapsed > 0 else 0.0
        eta = (self.total - self.done) / rate if rate > 0 else float("inf")
        frac = min(self.done / self.total, 1.0)
        bar = "#" * int(30 * frac) + "-" * (30 - int(30 * frac))
        eta_s = "done" if final else (f"ETA {eta:6.1f} s" if eta != float("inf") else "ETA   ?")
        self.stream.write(f"\r{self.label} [{bar}] {self.done}/{self.total} "
                          f"{rate:8.1f}/s {eta_s} ({elapsed:.0f} s)")
        self.stream.flush()
        self._shown = True
