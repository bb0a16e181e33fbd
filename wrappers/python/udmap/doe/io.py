"""Design-of-experiments output: row text, ordered chunked streaming, resume, the Parquet copy.

The CSV has one line per design in design order (a leading ``design`` index, then the columns of
INTERFACES.md "Design of experiments output"). Floats are written with ``repr`` (shortest text that
reads back to the same double), booleans as ``true``/``false``, missing values (a failed design,
an unbounded response) as empty cells; a message never contains a line break, so one line is one
design. Chunks are appended in order, each with a flush and fsync. A chunk that finishes before
an earlier one (parallel workers) waits in memory and, meanwhile, in the journal
``FILE.pending`` (also fsynced), so an interrupted run loses only the chunks being computed at
that moment, at most one per worker. ``FILE.meta.json`` records the run; a resumed run checks it,
every complete line of FILE and of the journal, continues after the last line of FILE and
computes only what the journal does not already hold. A complete run removes the journal.
"""
from __future__ import annotations

import csv
import io
import json
import os
from pathlib import Path

import numpy as np

from ..errors import InputError
from .arrow import Staging
from .layout import (FORCE_FIELDS, SUMMARY_COLUMNS, cell, column_units, columns, frames,
                     output_names)

FORMATS = ("csv", "parquet")
META_FORMAT = "udmap-doe-1"
# Record header of the journal of chunks waiting for an earlier one: "#chunk START COUNT BYTES".
_JOURNAL_TAG = b"#chunk"
# What a resumed run must share with the one that wrote the file.
_RUN_KEYS = ("name", "blade", "damper", "analysis", "params", "forces", "labels", "samples",
             "method", "seed", "outputs")


def _csv_line(cells: list[str]) -> str:
    buf = io.StringIO()
    csv.writer(buf, lineterminator="\n").writerow(cells)
    return buf.getvalue()


def _reprs(values) -> list[str]:
    """Cells of a list of floats (None where missing)."""
    return [repr(x) if x is not None and x - x == 0.0 else "" for x in values]


def row_cells(spec: dict, design: int, values, row: dict) -> list[str]:
    """The cells of one design's line. ``row``: ``status``, ``message`` and, as far as the
    design got, ``F_lim``, ``F_lim_backbone``, ``gamma_b``, ``M_max``, ``M_min``, ``lift_off``,
    ``F_adm`` and the per-force lists of floats ``gamma_P``, ``f_res``, ``sigma_a`` (None where
    unbounded or without stress rows) and of booleans ``hcf_ok`` and ``jump``."""
    cells = [str(design)] + [cell(v) for v in values]
    cells += [cell(row.get(k)) for k in SUMMARY_COLUMNS]
    gamma_P = row.get("gamma_P")
    if gamma_P is None:
        cells += [""] * (len(FORCE_FIELDS) * len(spec["labels"]))
    else:
        jump = row.get("jump") or [False] * len(gamma_P)
        for five in zip(_reprs(gamma_P), _reprs(row["f_res"]), _reprs(row["sigma_a"]),
                        ["true" if ok else "false" for ok in row["hcf_ok"]],
                        ["true" if j else "false" for j in jump]):
            cells += five
    cells += [cell(row.get("F_adm")), row["status"], cell(row.get("message", ""))]
    return cells


def _line(cells: list[str]) -> str:
    """The CSV line of a row's cells (as csv.writer writes it: only the message, the one free
    text, can need quotes)."""
    message = cells[-1]
    if "," in message or '"' in message:
        message = '"' + message.replace('"', '""') + '"'
    return ",".join(cells[:-1]) + "," + message + "\n"


def tally(spec: dict, cells: list[str], counts: dict) -> None:
    """Adds one line to the counts: designs per status and passing designs per force
    (keys ``hcf_ok@F``)."""
    status = cells[-2]
    counts[status] = counts.get(status, 0) + 1
    for label, at in _hcf_positions(spec):
        if cells[at] == "true":
            key = f"hcf_ok@{label}"
            counts[key] = counts.get(key, 0) + 1


def _hcf_positions(spec: dict) -> list[tuple[str, int]]:
    """(label, column index) of the hcf_ok@F columns of a run (none when not chosen)."""
    out = output_names(spec)
    if "hcf_ok" not in out:
        return []
    base = 1 + len(spec["params"]) + sum(c in out for c in SUMMARY_COLUMNS)
    per = sum(f in out for f in FORCE_FIELDS)
    at = [f for f in FORCE_FIELDS if f in out].index("hcf_ok")
    return [(label, base + per * i + at) for i, label in enumerate(spec["labels"])]


def format_rows(spec: dict, start: int, values, rows) -> tuple[str, dict]:
    """The text of a chunk of designs ``start, start + 1, ...`` and its counts."""
    counts: dict = {}
    lines = []
    for i, (v, row) in enumerate(zip(values, rows)):
        cells = row_cells(spec, start + i, v, row)
        tally(spec, cells, counts)
        lines.append(_line(cells))
    return "".join(lines), counts


def _float_cells(a) -> list[str]:
    """Cells of an array of floats: repr (as :func:`cell`), '' where not finite (missing)."""
    cells = list(map(repr, a.tolist()))
    bad = ~np.isfinite(a)
    if bad.any():
        for i in np.flatnonzero(bad):
            cells[i] = ""
    return cells


_FLAG_TEXT = np.array(["", "false", "true"])


def _message_cell(message: str) -> str:
    """A message as its CSV field (one line; quoted when it holds a comma or a quote)."""
    message = cell(message)
    if "," in message or '"' in message:
        message = '"' + message.replace('"', '""') + '"'
    return message


def format_chunk(spec: dict, start: int, values, rows) -> tuple[str, dict]:
    """The text of a chunk of designs ``start, start + 1, ...`` from its columns ``rows`` (a
    :class:`udmap.doe.worker.ChunkRows`) and its counts: column by column (numpy masks, the
    floats' shortest round-trip text), the same bytes as :func:`format_rows` writes for the
    same rows."""
    out = output_names(spec)
    n = rows.n
    cols = [list(map(str, range(start, start + n)))]
    for column in zip(*values) if n else []:
        cols.append(list(map(cell, column)))
    for c in SUMMARY_COLUMNS:
        if c not in out:
            continue
        if c == "lift_off":
            cols.append(_FLAG_TEXT[rows.lift_off + 1].tolist())
        else:
            cols.append(_float_cells(rows.num[c]))
    for i in range(len(spec["labels"])):
        for f in FORCE_FIELDS:
            if f not in out:
                continue
            if f in rows.flags:
                cols.append(_FLAG_TEXT[rows.flags[f][:, i] + 1].tolist())
            else:
                cols.append(_float_cells(rows.force[f][:, i]))
    if "F_adm" in out:
        cols.append(_float_cells(rows.num["F_adm"]))
    cols.append(rows.status)
    cols.append([_message_cell(m) if m else "" for m in rows.message])
    text = "\n".join(map(",".join, zip(*cols)))
    counts: dict = {}
    for status in rows.status:
        counts[status] = counts.get(status, 0) + 1
    if "hcf_ok" in out:
        passing = (rows.flags["hcf_ok"] == 1).sum(axis=0)
        for label, k in zip(spec["labels"], passing.tolist()):
            if k:
                counts[f"hcf_ok@{label}"] = k
    return (text + "\n" if n else ""), counts


def split_counts(counts: dict) -> tuple[dict, dict]:
    """(designs per status, passing designs per force label) from a tally."""
    status = {k: v for k, v in counts.items() if not k.startswith("hcf_ok@")}
    passing = {k[len("hcf_ok@"):]: v for k, v in counts.items() if k.startswith("hcf_ok@")}
    return status, passing


def _jsonable(spec: dict) -> dict:
    return json.loads(json.dumps({k: spec.get(k) for k in _RUN_KEYS}, default=str))


class Output:
    """The CSV file of a run (and its meta file and Parquet copy), written in design order."""

    def __init__(self, out, spec: dict, values, format: str = "csv"):
        out = Path(out)
        if format not in FORMATS:
            raise InputError(f"--format must be one of {', '.join(FORMATS)}, got {format!r}")
        self.format = format
        #: Parquet alone: the chunks as Arrow batches, staged in FILE.rows.arrow (what
        #: --resume continues) and written to FILE when the run completes (udmap.doe.arrow).
        self.staging = None
        if format == "parquet":
            self.path, self.parquet_path = out.with_name(out.name + ".rows.arrow"), out
        elif out.suffix == ".parquet":
            self.path, self.parquet_path = out.with_suffix(".csv"), out
        else:
            self.path = out
            self.parquet_path = out.with_suffix(".parquet") if out.suffix else \
                out.with_name(out.name + ".parquet")
        if self.path == self.parquet_path:
            raise InputError(f"--out {out}: choose a name ending in .csv")
        #: The run's result: the CSV, or the Parquet file with --format parquet.
        self.result_path = self.parquet_path if format == "parquet" else self.path
        self.meta_path = self.result_path.with_name(self.result_path.name + ".meta.json")
        self.journal_path = self.path.with_name(self.path.name + ".pending")
        self.spec = spec
        self.values = values
        self.header = columns(spec)
        self.counts: dict = {}
        self.written = 0
        self._file = None
        self._journal = None
        self._pending: dict = {}
        #: (start, count) of the chunks a resumed run found in the journal (not to compute).
        self.held: list[tuple[int, int]] = []
        if format == "parquet":
            self.staging = Staging(self.path, spec, values)

    # -- opening
    def open(self, resume: bool = False, overwrite: bool = False) -> int:
        """Creates the file, or on ``resume`` checks it against this run and truncates it after
        its last complete line. Returns the first design still to compute. Raises InputError
        (before writing anything) when the file exists without ``resume``/``overwrite`` or
        belongs to another run."""
        if self.staging is not None and self.path.exists() and resume:
            self._check_meta()
            covered = self.staging.scan(self.counts)
            first = 0
            for start, count in covered:
                if start == first:
                    first += count
            self.held = [(s, c) for s, c in covered if s > first]
            self.written = self.staging.written()
            self.staging.open()
            return first
        if self.path.exists() and resume:
            first = self._scan()
            self._recover(first)
        else:
            if self.result_path.exists() and not overwrite:
                raise InputError(f"--out {self.result_path} exists: pass --resume to continue "
                                 "that run or --force to overwrite it")
            if self.path.exists() and not overwrite:
                raise InputError(f"--out {self.path} exists: pass --resume to continue that run "
                                 "or --force to overwrite it")
            if self.path.is_dir():
                raise InputError(f"--out {self.path} is a directory")
            try:
                self.path.parent.mkdir(parents=True, exist_ok=True)
                meta = {"format": META_FORMAT, "columns": self.header,
                        "units": column_units(self.spec), **_jsonable(self.spec)}
                tmp = self.meta_path.with_name(self.meta_path.name + ".tmp")
                tmp.write_text(json.dumps(meta, indent=1))
                os.replace(tmp, self.meta_path)
                if self.staging is not None:
                    self.staging.create()
                else:
                    with open(self.path, "w", newline="") as f:
                        f.write(_csv_line(self.header))
                if self.journal_path.exists():
                    self.journal_path.unlink()
            except OSError as exc:
                raise InputError(f"--out {self.path}: {exc.strerror}") from None
            first = 0
            if self.staging is not None:
                self.staging.open()
                return first
        self.written = first
        self._file = open(self.path, "a", newline="")
        self._journal = open(self.journal_path, "ab")
        if self._pending:  # rewrite the journal with what it still holds, then use it
            self._journal.truncate(0)
            for start, (count, text) in sorted(self._pending.items()):
                self._journal_append(start, count, text)
            self._drain()
        return first

    def _line_cells(self, raw: bytes, design: int):
        """The cells of a line if it is design ``design`` of this run, else None."""
        if design >= len(self.values):
            return None
        cells = next(csv.reader([raw.decode("utf-8", "replace")]), [])
        nparam = len(self.spec["params"])
        expect = [str(design)] + [cell(v) for v in self.values[design]]
        if len(cells) != len(self.header) or cells[:1 + nparam] != expect:
            return None
        return cells

    def _scan(self) -> int:
        """Checks an existing file against this run; truncates a partial last line."""
        self._check_meta()
        header = _csv_line(self.header).encode()
        design = 0
        with open(self.path, "r+b") as f:
            if f.readline() != header:
                raise InputError(f"--resume: {self.path} does not start with the expected "
                                 "header")
            offset = len(header)
            # Every line that ends with '\n' is complete; only the last one may be cut.
            for raw in f:
                if not raw.endswith(b"\n"):
                    break
                cells = self._line_cells(raw[:-1], design)
                if cells is None:
                    raise InputError(f"--resume: line {design + 2} of {self.path} does not "
                                     "belong to this run; use --force to start again")
                tally(self.spec, cells, self.counts)
                offset += len(raw)
                design += 1
            f.truncate(offset)
        return design

    def _check_meta(self) -> None:
        """A resumed run: FILE.meta.json must describe this run."""
        try:
            meta = json.loads(self.meta_path.read_text())
        except (OSError, ValueError):
            raise InputError(f"--resume: {self.meta_path} is missing or unreadable, so "
                             f"{self.path} cannot be continued safely (use --force)") from None
        mine = _jsonable(self.spec)
        diff = [k for k in _RUN_KEYS if meta.get(k) != mine[k]]
        if meta.get("format") != META_FORMAT or diff:
            raise InputError(f"--resume: {self.path} was written by a different run (differs in: "
                             f"{', '.join(diff) or 'format'}); use --force to start again")

    def _recover(self, first: int) -> None:
        """Loads the journal's lines of designs ``first`` and beyond that belong to this run
        (a record cut by the interruption, or lines already in FILE, are dropped), grouped in
        runs of consecutive designs: they are written in turn instead of being computed."""
        try:
            data = self.journal_path.read_bytes()
        except OSError:
            return
        found: dict[int, bytes] = {}
        for start, count, _, body in frames(data, _JOURNAL_TAG):
            lines = body.split(b"\n")
            if len(lines) != count + 1 or lines[-1] != b"":
                break
            for i, raw in enumerate(lines[:-1]):
                if start + i >= first and self._line_cells(raw, start + i) is not None:
                    found[start + i] = raw + b"\n"
        runs: list[tuple[int, list[bytes]]] = []
        for d in sorted(found):
            if runs and d == runs[-1][0] + len(runs[-1][1]):
                runs[-1][1].append(found[d])
            else:
                runs.append((d, [found[d]]))
        for start, lines in runs:
            self._hold(start, lines)

    def _hold(self, start: int, lines: list[bytes]) -> None:
        text = b"".join(lines).decode("utf-8")
        self._pending[start] = (len(lines), text)
        self.held.append((start, len(lines)))
        for raw in lines:
            tally(self.spec, next(csv.reader([raw.decode("utf-8")])), self.counts)

    # -- writing
    def _journal_append(self, start: int, count: int, text: str) -> None:
        data = text.encode("utf-8")
        self._journal.write(f"{_JOURNAL_TAG.decode()} {start} {count} {len(data)}\n".encode()
                            + data)
        self._journal.flush()
        os.fsync(self._journal.fileno())

    def put(self, start: int, count: int, text: str) -> None:
        """Accepts a finished chunk; appends every chunk that is next in design order (a chunk
        that must wait for an earlier one goes to the journal meanwhile); with Parquet alone
        ``text`` is the chunk's Arrow stream, staged at once whatever its order."""
        if self.staging is not None:
            self.staging.put(start, count, text)
            self.written = self.staging.written()
            return
        self._pending[start] = (count, text)
        if start != self.written:
            self._journal_append(start, count, text)
        self._drain()

    def _drain(self) -> None:
        wrote = False
        while self.written in self._pending:
            count, text = self._pending.pop(self.written)
            self._file.write(text)
            self.written += count
            wrote = True
        if wrote:
            self._file.flush()
            os.fsync(self._file.fileno())
            if not self._pending and self._journal.tell() > 0:
                self._journal.truncate(0)
                self._journal.seek(0)

    def close(self) -> None:
        """Closes the files; the journal goes once every design is in FILE."""
        if self.staging is not None:
            self.staging.close()
            return
        if self._file is not None:
            self._file.close()
            self._file = None
        if self._journal is not None:
            self._journal.close()
            self._journal = None
            if self.written >= len(self.values) and self.journal_path.exists():
                self.journal_path.unlink()

    def recorded(self, name: str, default=None):
        """A field of FILE.meta.json (``default`` when it has none or cannot be read)."""
        try:
            return json.loads(self.meta_path.read_text()).get(name, default)
        except (OSError, ValueError):
            return default

    def record(self, **fields) -> None:
        """Adds fields to FILE.meta.json (after the run: e.g. the traces it made)."""
        try:
            meta = json.loads(self.meta_path.read_text())
            meta.update(fields)
            tmp = self.meta_path.with_name(self.meta_path.name + ".tmp")
            tmp.write_text(json.dumps(meta, indent=1))
            os.replace(tmp, self.meta_path)
        except (OSError, ValueError) as exc:
            raise InputError(f"--out {self.meta_path}: {exc}") from None

    def finish(self) -> str | None:
        """After a complete run: the Parquet copy when pyarrow is installed (its path); with
        --format parquet the Parquet file, and the staged rows removed."""
        if self.staging is not None:
            return self.staging.finish(self.parquet_path)
        path = self._parquet()
        return path

    def _parquet(self) -> str | None:
        try:
            import pyarrow.csv as pacsv
            import pyarrow.parquet as pq
            import pyarrow as pa
        except ImportError:
            return None
        cols = self.header
        types = {c: pa.float64() for c in cols}
        types.update({"design": pa.int64(), "lift_off": pa.bool_(), "status": pa.string(),
                      "message": pa.string()})
        types = {c: t for c, t in types.items() if c in cols}
        for p, path in zip(self.spec["params"], self.spec["paths"]):
            if p["integer"]:
                types[p["name"]] = pa.int64()
        for label in self.spec["labels"]:
            for f in ("hcf_ok", "jump"):
                if f"{f}@{label}" in cols:
                    types[f"{f}@{label}"] = pa.bool_()
        reader = pacsv.open_csv(self.path, convert_options=pacsv.ConvertOptions(
            column_types=types, strings_can_be_null=False, true_values=["true"],
            false_values=["false"]))
        units = column_units(self.spec)
        schema = pa.schema([f.with_metadata({"unit": units[f.name]}) if f.name in units else f
                            for f in reader.schema])
        tmp = self.parquet_path.with_name(self.parquet_path.name + ".tmp")
        with pq.ParquetWriter(tmp, schema) as writer:  # batch by batch: bounded memory
            for batch in reader:
                writer.write_batch(pa.RecordBatch.from_arrays(batch.columns, schema=schema))
        os.replace(tmp, self.parquet_path)
        return str(self.parquet_path)


def read_csv(path) -> tuple[list[str], list[list[str]]]:
    """The header and the rows (as strings) of a doe CSV."""
    with open(path, newline="") as f:
        reader = csv.reader(f)
        header = next(reader)
        return header, list(reader)


def pass_shares(counts: dict, designs: int, labels) -> dict:
    """Designs per status, and the shares of all designs that are computed without error and
    that pass the HCF criterion at each force."""
    status, passing = split_counts(counts)
    return {"status": status, "ok_share": status.get("ok", 0) / designs,
            "hcf_share": {label: passing.get(label, 0) / designs for label in labels}}
