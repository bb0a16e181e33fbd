"""Parquet alone (``--format parquet``): the chunks go from the workers' columns to Arrow record
batches, with no row text.

A worker returns its chunk as an Arrow IPC stream (:func:`chunk_payload`). The writer appends
every finished chunk at once, in whatever order the chunks finish, to the staging file
``FILE.rows.arrow`` as a frame ``#batch START COUNT BYTES\\n`` + the stream, each with a flush
and fsync: an interrupted run loses only the chunks being computed. A resumed run keeps every
complete frame that belongs to the run (the designs and their parameter values are checked) and
computes the designs that none holds. When every design is there, the frames are written to the
Parquet file in design order and the staging file goes.

The values are those of the CSV read back (:func:`udmap.doe.io.Output`'s Parquet copy): the
same column types and unit metadata; a missing float (an empty CSV cell) and a missing flag are
null, a message has its line breaks folded.
"""
from __future__ import annotations

import os
from pathlib import Path

import numpy as np

from ..errors import InputError
from .layout import (FORCE_FIELDS, SUMMARY_COLUMNS, cell, column_units, columns, frames,
                     output_names)

_TAG = b"#batch"
#: Rows per Parquet row group (the chunks are at most 256 designs).
_ROW_GROUP = 65536


def _pa():
    try:
        import pyarrow as pa
        import pyarrow.ipc  # noqa: F401
        import pyarrow.parquet  # noqa: F401
    except ImportError:
        raise InputError("--format parquet needs the Python package pyarrow "
                         "(pip install pyarrow)") from None
    return pa


def column_types(spec: dict) -> dict:
    """Column -> Arrow type: int64 for the design and integer parameters, bool for lift_off,
    hcf_ok@F and jump@F, strings for status and message, float64 for the rest."""
    pa = _pa()
    cols = columns(spec)
    types = {c: pa.float64() for c in cols}
    types.update({"design": pa.int64(), "lift_off": pa.bool_(), "status": pa.string(),
                  "message": pa.string()})
    for p in spec["params"]:
        if p["integer"]:
            types[p["name"]] = pa.int64()
    for label in spec["labels"]:
        for f in ("hcf_ok", "jump"):
            types[f"{f}@{label}"] = pa.bool_()
    return {c: types[c] for c in cols}


def schema(spec: dict):
    """The Arrow schema of a run: its columns, types and units (field metadata ``unit``)."""
    pa = _pa()
    units = column_units(spec)
    return pa.schema([pa.field(c, t, metadata={"unit": units[c]} if c in units else None)
                      for c, t in column_types(spec).items()])


def chunk_payload(spec: dict, start: int, values, rows) -> tuple[bytes, dict]:
    """The Arrow IPC stream of a chunk of designs ``start, start + 1, ...`` from its columns
    ``rows`` (a :class:`udmap.doe.worker.ChunkRows`), and its counts (as
    :func:`udmap.doe.io.format_chunk`)."""
    pa = _pa()
    sch = schema(spec)
    out = output_names(spec)
    n = rows.n

    def floats(a):
        a = np.asarray(a, dtype=float)
        return pa.array(a, mask=~np.isfinite(a), type=pa.float64())

    def flags(a):
        a = np.asarray(a)
        return pa.array(a == 1, mask=a < 0, type=pa.bool_())

    arrays = [pa.array(np.arange(start, start + n, dtype=np.int64))]
    for j, p in enumerate(spec["params"]):
        column = [v[j] for v in values]
        arrays.append(pa.array(column, type=pa.int64() if p["integer"] else pa.float64()))
    for c in SUMMARY_COLUMNS:
        if c in out:
            arrays.append(flags(rows.lift_off) if c == "lift_off" else floats(rows.num[c]))
    for i in range(len(spec["labels"])):
        for f in FORCE_FIELDS:
            if f in out:
                arrays.append(flags(rows.flags[f][:, i]) if f in rows.flags
                              else floats(rows.force[f][:, i]))
    if "F_adm" in out:
        arrays.append(floats(rows.num["F_adm"]))
    arrays.append(pa.array(list(rows.status), type=pa.string()))
    arrays.append(pa.array([cell(m) if m else "" for m in rows.message], type=pa.string()))
    batch = pa.RecordBatch.from_arrays(arrays, schema=sch)
    sink = pa.BufferOutputStream()
    with pa.ipc.new_stream(sink, sch) as writer:
        writer.write_batch(batch)
    return sink.getvalue().to_pybytes(), _counts(spec, batch)


def _counts(spec: dict, batch) -> dict:
    """Designs per status and passing designs per force (keys ``hcf_ok@F``) of a batch."""
    counts: dict = {}
    for status in batch.column("status").to_pylist():
        counts[status] = counts.get(status, 0) + 1
    if "hcf_ok" in output_names(spec):
        for label in spec["labels"]:
            k = sum(1 for v in batch.column(f"hcf_ok@{label}").to_pylist() if v)
            if k:
                counts[f"hcf_ok@{label}"] = k
    return counts


class Staging:
    """The staging file of a Parquet-alone run: frames of finished chunks in any order."""

    def __init__(self, path: Path, spec: dict, values):
        self.path = Path(path)
        self.spec = spec
        self.values = values
        #: start -> (count, offset of the stream, its size) of every frame in the file.
        self.frames: dict[int, tuple[int, int, int]] = {}
        self._file = None

    def create(self) -> None:
        _pa()
        self.path.write_bytes(b"")

    def scan(self, counts: dict) -> list[tuple[int, int]]:
        """A resumed run: keeps the complete frames of this run (their counts added to
        ``counts``), truncates the file after the last one and returns their (start, count)."""
        pa = _pa()
        end_ok = 0
        for start, count, offset, body in frames(self.path.read_bytes(), _TAG):
            try:
                batch = pa.ipc.open_stream(body).read_next_batch()
            except (pa.ArrowInvalid, StopIteration):
                break
            if not self._belongs(batch, start, count):
                raise InputError(f"--resume: {self.path} holds designs {start}.."
                                 f"{start + count - 1} of another run; use --force to start "
                                 "again")
            if start not in self.frames:
                self.frames[start] = (count, offset, len(body))
                for k, v in _counts(self.spec, batch).items():
                    counts[k] = counts.get(k, 0) + v
            end_ok = offset + len(body)
        with open(self.path, "r+b") as f:
            f.truncate(end_ok)
        return sorted((s, c) for s, (c, _, _) in self.frames.items())

    def _belongs(self, batch, start: int, count: int) -> bool:
        if batch.num_rows != count or start + count > len(self.values):
            return False
        if batch.column("design").to_pylist() != list(range(start, start + count)):
            return False
        for j, p in enumerate(self.spec["params"]):
            got = batch.column(p["name"]).to_pylist()
            if got != [v[j] for v in self.values[start:start + count]]:
                return False
        return True

    def open(self) -> None:
        self._file = open(self.path, "ab")

    def put(self, start: int, count: int, payload: bytes) -> None:
        head = f"{_TAG.decode()} {start} {count} {len(payload)}\n".encode()
        offset = self._file.tell() + len(head)
        self._file.write(head + payload)
        self._file.flush()
        os.fsync(self._file.fileno())
        self.frames[start] = (count, offset, len(payload))

    def written(self) -> int:
        return sum(c for c, _, _ in self.frames.values())

    def close(self) -> None:
        if self._file is not None:
            self._file.close()
            self._file = None

    def finish(self, parquet_path: Path) -> str:
        """Writes the frames in design order as the Parquet file; removes the staging file."""
        pa = _pa()
        import pyarrow.parquet as pq
        sch = schema(self.spec)
        tmp = parquet_path.with_name(parquet_path.name + ".tmp")
        pos = 0
        group: list = []
        with open(self.path, "rb") as f, pq.ParquetWriter(tmp, sch) as writer:
            for start in sorted(self.frames):
                count, offset, size = self.frames[start]
                if start != pos:
                    raise InputError(f"{self.path}: designs {pos}..{start - 1} are missing")
                f.seek(offset)
                group.append(pa.ipc.open_stream(f.read(size)).read_next_batch())
                pos += count
                if sum(b.num_rows for b in group) >= _ROW_GROUP:
                    writer.write_table(pa.Table.from_batches(group, schema=sch))
                    group = []
            if group:
                writer.write_table(pa.Table.from_batches(group, schema=sch))
        os.replace(tmp, parquet_path)
        self.path.unlink()
        return str(parquet_path)
