"""A study's table as a file: CSV or Parquet, in the units a person reads (the spec's own,
:mod:`govopt.study.shown`), each heading naming its unit (``omega_inner [rpm]``).

The table is read and written a batch at a time (:meth:`Store.batches`): a million-point study
is never held; the Pareto front is found first. A Parquet file's fields also carry, as
metadata, each column's unit, SI unit, factor and what it is (the database's ``columns``).
The workbook (a summary sheet, the printable table and the data) is
:mod:`govopt.report.study_workbook`'s. Files are written atomically
(:func:`govopt.report.files.atomic_write`: never a partial file; an existing file replaced
only with ``overwrite``).
"""

from __future__ import annotations

from pathlib import Path

import pandas as pd

from .errors import StudyError
from .store import BATCH
from .summary import heading, pareto_points

#: numbers in a CSV file: 12 significant digits (the database keeps every digit; a value
#: read in another unit than its own, 1.7 cm from 0.017 m, is not shown as 1.7000000000000002)
CSV_FLOAT = "%.12g"
#: the formats :func:`export` writes (the workbook's is the report's)
FORMATS = (".csv", ".parquet")


def shown_batches(store, *, batch: int = BATCH, columns=None):
    """``(headings, batches)``: the table's columns headed with their units, and its batches
    in those units (a ``pareto`` column where the study names objectives)."""
    info = store.columns().set_index("name")
    names = store.names() if columns is None else [c for c in store.names() if c in columns]
    front = pareto_points(store, batch=batch) if store.study().get("pareto") else None
    scale = {n: float(info.at[n, "shown_factor"]) for n in names
             if info.at[n, "type"] == "REAL" and float(info.at[n, "shown_factor"]) != 1.0}
    headings = {n: heading(n, info.at[n, "shown_unit"]) for n in names}

    def batches():
        for part in store.batches(names, batch=batch):
            for n, f in scale.items():
                part[n] = part[n].to_numpy(dtype=float) / f
            if front is not None:
                part["pareto"] = part["point"].isin(front).to_numpy()
            yield part.rename(columns=headings)

    out = [headings[n] for n in names] + (["pareto"] if front is not None else [])
    return out, batches()


def export(store, path: str | Path, *, overwrite: bool = False, batch: int = BATCH) -> Path:
    """Write the study's table as CSV or Parquet (by the file's extension), in the spec's
    units, atomically."""
    from ..report.files import atomic_write

    path = Path(path)
    kind = path.suffix.lower()
    if kind not in FORMATS:
        raise StudyError("expected a .csv or .parquet file (or .xlsx: the workbook)",
                         file=path)
    headings, batches = shown_batches(store, batch=batch)
    write = _csv if kind == ".csv" else _parquet
    return atomic_write(path, lambda tmp: write(tmp, store, headings, batches),
                        overwrite=overwrite, what="study table")


def _csv(tmp: Path, store, headings: list[str], batches) -> None:
    with open(tmp, "w", newline="", encoding="utf-8") as f:
        first = True
        for part in batches:
            part.to_csv(f, header=first, index=False, float_format=CSV_FLOAT)
            first = False
        if first:
            pd.DataFrame(columns=headings).to_csv(f, index=False)


def schema(store, headings: list[str]):
    """The Parquet schema of the table: each column's type from the database's, its units
    and meaning as field metadata."""
    import pyarrow as pa

    info = store.columns()
    kinds = {"REAL": pa.float64(), "TEXT": pa.string()}
    fields = []
    for row, name in zip(info.itertuples(index=False), headings, strict=False):
        kind = (pa.bool_() if row.role == "check passed" else
                kinds.get(row.type, pa.int64()))
        fields.append(pa.field(name, kind, metadata={
            "unit": row.shown_unit, "si_unit": row.unit, "factor": repr(row.shown_factor),
            "role": row.role, "label": row.label, "about": row.about}))
    if "pareto" in headings:
        fields.append(pa.field("pareto", pa.bool_()))
    return pa.schema(fields)


def _parquet(tmp: Path, store, headings: list[str], batches) -> None:
    import pyarrow as pa
    import pyarrow.parquet as pq

    sch = schema(store, headings)
    with pq.ParquetWriter(tmp, sch) as writer:
        for part in batches:  # texts are texts or None already (the database's TEXT)
            writer.write_table(pa.Table.from_pandas(part, schema=sch, preserve_index=False))
