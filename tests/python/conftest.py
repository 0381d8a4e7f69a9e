"""Shared helpers of the Python module's tests (run by ctest from the source folder, with
PYTHONPATH at the build tree's package and ROLLNOISE_BINARY the program, as tests/python/CMakeLists.txt
sets them)."""
import csv
import json
import os
import pathlib
import subprocess

import numpy as np
import pytest

SOURCE = pathlib.Path(__file__).resolve().parents[2]
BINARY = os.environ.get("ROLLNOISE_BINARY", str(SOURCE / "build" / "tools" / "rollnoise" / "rollnoise"))


def run_cli(*args, cwd=None, check=True):
    """Runs the program as a user does; returns the CompletedProcess (text)."""
    result = subprocess.run([BINARY, *map(str, args)], cwd=cwd or SOURCE, capture_output=True, text=True,
                            env=dict(os.environ, CI="1"))
    if check:
        assert result.returncode == 0, result.stderr
    return result


def read_columns(path):
    """{column: array} of a numeric CSV (comment lines '#' skipped)."""
    with open(path, newline="") as f:
        rows = list(csv.reader(line for line in f if not line.startswith("#")))
    header, body = rows[0], rows[1:]
    return {name: np.array([float(r[i]) for r in body]) for i, name in enumerate(header)}


def read_spectrum(path):
    """{receiver: (band_hz, Lp_dB, LpA_dB)} of a spectrum.csv."""
    with open(path, newline="") as f:
        rows = list(csv.reader(f))[1:]
    out = {}
    for receiver, band, lp, lpa in rows:
        out.setdefault(receiver, ([], [], []))
        for column, value in zip(out[receiver], (band, lp, lpa)):
            column.append(float(value))
    return {r: tuple(np.array(c) for c in cols) for r, cols in out.items()}


def read_json(path):
    with open(path) as f:
        return json.load(f)


# Keys of summary.json that are wall-clock times or say where the cache came in: they differ
# between two runs of the same case.
VOLATILE = ("time_s", "wall_time_s", "from_cache", "stage_times_s", "cache")


def comparable(summary):
    """summary.json without its timings (recursively)."""
    if isinstance(summary, dict):
        return {k: comparable(v) for k, v in summary.items()
                if not any(k.endswith(v_) or k == v_ for v_ in VOLATILE)}
    if isinstance(summary, list):
        return [comparable(v) for v in summary]
    return summary


@pytest.fixture
def workspace(tmp_path, monkeypatch):
    """A fresh folder as the current folder; files the tests name are under SOURCE."""
    monkeypatch.chdir(tmp_path)
    return tmp_path
