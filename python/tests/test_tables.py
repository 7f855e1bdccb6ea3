"""The tables of runs with and without pandas: DataFrame, numpy arrays."""

import math

from conftest import CROSSING, require

import vorrt
from vorrt import _tables


def test_tracks_are_a_dataframe_with_pandas():
    pandas = require("pandas")
    run = vorrt.simulate(vorrt.Scenario.load(CROSSING), seed=1)
    tracks = run.tracks
    assert isinstance(tracks, pandas.DataFrame)
    assert tracks["vessel"].unique().tolist() == ["ownship", "TS1"]
    # Read in full: the CSV written back gives the same numbers.
    again = _tables.table_from_csv(_tables.table_to_csv(tracks))
    assert again.equals(tracks)


def test_without_pandas_columns_are_numpy_arrays(monkeypatch):
    numpy = require("numpy")
    run = vorrt.simulate(vorrt.Scenario.load(CROSSING), seed=1)
    import builtins

    real_import = builtins.__import__

    def no_pandas(name, *args, **kwargs):
        if name == "pandas":
            raise ImportError("no pandas here")
        return real_import(name, *args, **kwargs)

    monkeypatch.setattr(builtins, "__import__", no_pandas)
    columns = _tables.table_from_csv(run.trajectory_csv())
    assert isinstance(columns["east_m"], numpy.ndarray)
    assert columns["vessel"][0] == "ownship"
    assert math.isclose(columns["north_m"][0], -5556.0)
    text = _tables.table_to_csv({name: list(values) for name, values in columns.items()})
    assert text.splitlines()[0] == run.trajectory_csv().splitlines()[0]
    judged = vorrt.judge(columns, vorrt.Scenario.load(CROSSING))
    assert judged.safe_and_compliant is True


def test_findings_flatten_the_report():
    report = {"findings": ["weave"], "targets": [{"name": "A", "findings": ["late"]}]}
    assert _tables.findings(report) == [
        {"target": None, "finding": "weave"},
        {"target": "A", "finding": "late"},
    ]
