"""Tables of runs for Python: ``trajectory.csv`` as a pandas ``DataFrame``
(or numpy arrays without pandas), the findings of a report, and back from
a table to the CSV ``vorrt judge`` reads."""

import csv
import io
from typing import Any, Dict, List, Optional

# Every column of trajectory.csv but ``vessel`` is a number.
TEXT_COLUMNS = ("vessel",)


def table_from_csv(text: str) -> Any:
    """The columns of a CSV text: a pandas ``DataFrame`` when pandas is
    installed, else a dict of numpy arrays (of lists without numpy)."""
    try:
        import pandas
    except ImportError:
        pandas = None
    if pandas is not None:
        # Numbers read back exactly as written: pandas 3 parses round trip by
        # default (and deprecates the option), pandas 1-2 only when asked.
        major = int(pandas.__version__.split(".")[0])
        options = {} if major >= 3 else {"float_precision": "round_trip"}
        # A vessel named by its MMSI stays text.
        dtype = {name: str for name in TEXT_COLUMNS}
        return pandas.read_csv(io.StringIO(text), dtype=dtype, **options)
    rows = list(csv.reader(io.StringIO(text)))
    header, body = rows[0], rows[1:]
    columns: Dict[str, List[Any]] = {}
    for index, name in enumerate(header):
        values = [row[index] for row in body]
        if name not in TEXT_COLUMNS:
            values = [float(value) for value in values]
        columns[name] = values
    try:
        import numpy
    except ImportError:
        return columns
    return {name: numpy.asarray(values) for name, values in columns.items()}


def table_to_csv(tracks: Any) -> str:
    """CSV text of a table: a ``DataFrame``, a dict of columns (lists or
    arrays), or CSV text as it is."""
    if isinstance(tracks, str):
        return tracks
    if hasattr(tracks, "to_csv"):
        # Numbers in full (the shortest text that reads back the same).
        return tracks.to_csv(index=False, float_format=None)
    if isinstance(tracks, dict):
        names = list(tracks)
        columns = [list(tracks[name]) for name in names]
        lengths = {len(column) for column in columns}
        if len(lengths) > 1:
            raise ValueError(
                "tracks: the columns have different lengths "
                + ", ".join(f"{name}={len(column)}" for name, column in zip(names, columns))
            )
        out = io.StringIO()
        writer = csv.writer(out, lineterminator="\n")
        writer.writerow(names)
        for row in zip(*columns):
            writer.writerow([repr(float(v)) if isinstance(v, float) else v for v in row])
        return out.getvalue()
    raise TypeError(
        "tracks must be a pandas DataFrame, a dict of columns or CSV text, not "
        + type(tracks).__name__
    )


def findings(report: Dict[str, Any]) -> List[Dict[str, Optional[str]]]:
    """The COLREGs findings of a report: ownship's track findings (target
    ``None``) then each target's, in the report's order."""
    found: List[Dict[str, Optional[str]]] = [
        {"target": None, "finding": text} for text in report.get("findings", [])
    ]
    for target in report.get("targets", []):
        found.extend(
            {"target": target["name"], "finding": text} for text in target.get("findings", [])
        )
    return found
