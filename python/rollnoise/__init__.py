"""rollnoise: tyre/road noise from first principles, from Python.

The functions mirror the command line's verbs and call the same library functions, with numpy
arrays in and out:

    simulate(case, set=None, out=None, cache=True, progress=None)   one case: contact, sound
    road(road, ...)                                                 a road and its texture
    analyse(recording, full_scale=None, out=None)                   spectra and levels of a recording
    greens(model, ...)                                              a tyre model's Green's functions
    calibrate(model, data, ...)                                     fit a tyre model to mobilities
    study(study, out, ...)                                          many cases, on threads
    read_wav(path)                                                  a WAV file rollnoise wrote, in Pa

Every function takes an optional output folder `out`: given, the function writes there what the
command line writes (atomically, replacing an earlier rollnoise output); not given, it leaves no
file behind. Runs release the GIL, so other Python threads go on meanwhile; Ctrl-C (or
"interrupt the kernel" in a notebook) stops a run, removes what it had begun to write and raises
KeyboardInterrupt; `progress`, when given, is called as progress(stage, done, total) from the
calling thread about ten times a second.

Bad input raises InputError (a ValueError) with the command line's message, naming the file or
argument, the key and what is allowed; a failed write raises OutputError (an OSError).

The manual's page "Python" (docs/python.md) has a tour; help(rollnoise.simulate) and the others
are the reference.
"""

from __future__ import annotations

import csv as _csv
import json as _json
import os as _os
import shutil as _shutil
import tempfile as _tempfile

import numpy as _np

from . import _rollnoise
from ._rollnoise import InputError, OutputError

__version__ = _rollnoise.__version__

__all__ = [
    "simulate",
    "road",
    "analyse",
    "greens",
    "calibrate",
    "study",
    "read_wav",
    "Result",
    "InputError",
    "OutputError",
]

InputError.__doc__ = """Bad input: a case, model, road or data file, or an argument.

A subclass of ValueError. str(error) is the message the command line prints after
"rollnoise: error: ": the file or argument, where in it, what is wrong and what is allowed.
The attributes source, key and problem hold the three parts."""

OutputError.__doc__ = """A write into the output folder failed (a full disk, a size limit, an I/O error).

A subclass of OSError; nothing is left half-written: the folder is as it was before the run."""


def _input_error(source, key, problem):
    """An InputError made here, worded as the library words its own."""
    error = InputError(": ".join(part for part in (source, key, problem) if part))
    error.source, error.key, error.problem = source, key, problem
    return error


class Result:
    """What a function returns: its arrays and dicts as attributes (see the function's help).

    `summary` is always there: the dict the command line writes as summary.json (report.json
    for calibrate). `out` is the output folder written, or None."""

    def __init__(self, **fields):
        self.__dict__.update(fields)

    def __repr__(self):
        def brief(value):
            if isinstance(value, _np.ndarray):
                return "array" + str(value.shape)
            if isinstance(value, dict):
                return "dict(" + ", ".join(str(k) for k in list(value)[:6]) + (", ..." if len(value) > 6 else "") + ")"
            return repr(value)

        fields = ", ".join(f"{k}={brief(v)}" for k, v in self.__dict__.items())
        return f"rollnoise.Result({fields})"


# ---------------------------------------------------------------------------------------------
# Arguments


def _toml_value(value):
    """A Python value written as the TOML text --set reads."""
    if isinstance(value, bool) or isinstance(value, _np.bool_):
        return "true" if value else "false"
    if isinstance(value, (int, _np.integer)):
        return str(int(value))
    if isinstance(value, (float, _np.floating)):
        value = float(value)
        if value != value:
            return "nan"
        if value in (float("inf"), float("-inf")):
            return "inf" if value > 0 else "-inf"
        return repr(value)
    if isinstance(value, (str, _os.PathLike)):
        return _json.dumps(_os.fspath(value))
    if isinstance(value, dict):
        return "{" + ", ".join(f"{_json.dumps(str(k))} = {_toml_value(v)}" for k, v in value.items()) + "}"
    if isinstance(value, (list, tuple, _np.ndarray)):
        return "[" + ", ".join(_toml_value(v) for v in value) + "]"
    raise _input_error("set", repr(value), "cannot be written in TOML (allowed: bool, int, float, str, list, dict)")


def _overrides(set):
    """{'section.key': value} (or a list of 'section.key=value' strings) as --set strings."""
    if set is None:
        return []
    if isinstance(set, dict):
        return [f"{key}={_toml_value(value)}" for key, value in set.items()]
    if isinstance(set, str):
        return [set]
    return [str(item) for item in set]


def _source(value, what):
    """('path' | 'text' | 'dict', value, name) of a case, model, road or study argument."""
    if isinstance(value, _os.PathLike):
        return "path", _os.fspath(value), _os.fspath(value)
    if isinstance(value, dict):
        return "dict", value, f"<{what} dict>"
    if isinstance(value, str):
        if "\n" in value or "=" in value:
            return "text", value, f"<{what} text>"
        return "path", value, value
    raise TypeError(f"{what} must be a path, TOML text or a dict, not {type(value).__name__}")


def _folder(out):
    return "" if out is None else _os.fspath(out)


# ---------------------------------------------------------------------------------------------
# Reading the files a run wrote


def _csv_rows(path):
    with open(path, newline="") as f:
        rows = [row for row in _csv.reader(line for line in f if not line.startswith("#"))]
    return rows[0], rows[1:]


def _numeric_csv(path):
    """{column: array} of a numeric CSV rollnoise wrote (shortest round-trip numbers)."""
    header, rows = _csv_rows(path)
    table = _np.array([[float(cell) for cell in row] for row in rows if row], dtype=float).reshape(-1, len(header))
    return {name: table[:, i].copy() for i, name in enumerate(header)}


def _spectrum_csv(path):
    """{receiver: {'band_hz', 'Lp_dB', 'LpA_dB'}} of a spectrum.csv, receivers in file order."""
    header, rows = _csv_rows(path)
    spectra = {}
    for receiver, band, lp, lpa in rows:
        one = spectra.setdefault(receiver, ([], [], []))
        one[0].append(float(band))
        one[1].append(float(lp))
        one[2].append(float(lpa))
    return {
        r: {"band_hz": _np.array(b), "Lp_dB": _np.array(lp), "LpA_dB": _np.array(lpa)}
        for r, (b, lp, lpa) in spectra.items()
    }


def _columns(table, prefix, points):
    return _np.column_stack([table[f"{prefix}_{i}"] for i in range(1, points + 1)])


def _window_road(h5):
    """The road under each window point at each step, [steps][Ny][Nw], from /contact/road_strip."""
    if _rollnoise.h5_exists(h5, "/contact/road"):
        return _rollnoise.read_h5(h5, "/contact/road")
    strip = _rollnoise.read_h5(h5, "/contact/road_strip")
    force = _rollnoise.read_h5(h5, "/contact/force")
    samples, _, window = force.shape
    p = int(_rollnoise.h5_number_attribute(h5, "/", "substeps_per_cell"))
    index = _np.arange(window)[None, :] * p + _np.arange(samples)[:, None]
    return _np.transpose(strip[:, index], (1, 0, 2))


def _read_simulation(folder, summary):
    contact = _numeric_csv(_os.path.join(folder, "contact.csv"))
    fields = {}
    if "total_force" in contact:  # a tyre
        totals = {k: contact[k] for k in ("total_force", "contact_area", "contact_length")}
        h5 = _os.path.join(folder, "contact.h5")
        force = displacement = road = velocity = None
        if _os.path.exists(h5):
            force = _rollnoise.read_h5(h5, "/contact/force")
            road = _window_road(h5)
            velocity = _rollnoise.read_h5(h5, "/surface/velocity")
            if _rollnoise.h5_exists(h5, "/contact/displacement"):
                displacement = _rollnoise.read_h5(h5, "/contact/displacement")
        fields.update(force=force, displacement=displacement, road=road, velocity=velocity, totals=totals)
    else:
        points = sum(1 for k in contact if k.startswith("force_"))
        fields.update(
            force=_columns(contact, "force", points),
            displacement=_columns(contact, "displacement", points),
            road=_columns(contact, "road", points),
            velocity=None,
            totals=None,
        )
    spectrum_file = _os.path.join(folder, "spectrum.csv")
    power_file = _os.path.join(folder, "sound_power.csv")
    return dict(
        time=contact["time"],
        spectrum=_spectrum_csv(spectrum_file) if _os.path.exists(spectrum_file) else {},
        levels=summary.get("levels", {}),
        sound_power=_numeric_csv(power_file) if _os.path.exists(power_file) else {},
        **fields,
    )


# ---------------------------------------------------------------------------------------------
# The verbs


def simulate(case, set=None, out=None, cache=True, force=False, progress=None):
    """Run one case: roll a tyre model over a road, and for tyres radiate the sound.

    What `rollnoise simulate CASE --set KEY=VALUE ... --out OUT` does, through the same library
    function, with the results as numpy arrays.

    Parameters
    ----------
    case : str, os.PathLike or dict
        The case: the path of a case file; TOML text (a str holding a newline or '='); or a dict
        of its tables ({'tyre': {...}, 'road': {...}, 'rolling': {...}, ...}), every key as in a
        case file (docs/reference/case-files.md). Files a case names (`[tyre] file`, `[road]
        surface`) are found from the case file's folder, or for text and dicts from the current
        folder (and the folders above it).
    set : dict, optional
        Overrides, {'section.key': value}, applied in order as --set applies them
        ({'rolling.speed': 13.889, 'road.surface': 'models/surfaces/sma11.toml'}).
    out : str or os.PathLike, optional
        The output folder: given, every file the command line writes is written there
        (atomically; an earlier rollnoise output is replaced). Not given, no file is left behind
        (the run works in a temporary folder, without plots, removed before returning).
    cache : bool or str, default True
        True: the cache folder ($ROLLNOISE_CACHE, else ~/.cache/rollnoise); False: no cache; a
        path: that folder. The numbers are the same either way.
    force : bool, default False
        Run even when the estimate of the run's memory or output exceeds what the machine has
        (--force); otherwise such a run raises InputError before it starts.
    progress : callable, optional
        Called as progress(stage, done, total) about ten times a second from the calling thread
        ('simulate NAME' over the time steps, 'radiation NAME' over the anchor frequencies).
        An exception it raises stops the run and is raised.

    Returns
    -------
    Result with
        summary : dict
            What summary.json holds (docs/reference/outputs.md).
        time : ndarray [steps + 1]
            t = n·Δt, s.
        force, displacement, road : ndarray
            Point models (sdof, coupled_sdof): [steps + 1, points], N and m, the columns of
            contact.csv (point 1 leads). Tyres: the fields of contact.h5 (32-bit values),
            [steps + 1, Ny, Nw] over the contact window: the contact forces, N; the road under
            each window point, m; the tread's displacement, m (only with [output] fields =
            "all", else None). None with fields = "none".
        velocity : ndarray or None
            Tyres: contact.h5's /surface/velocity, the belt's radial velocity, m/s.
        totals : dict or None
            Tyres: contact.csv's 'total_force' (N), 'contact_area' (m²), 'contact_length' (m).
        spectrum : dict
            Tyres with radiation: {receiver: {'band_hz', 'Lp_dB', 'LpA_dB'}} of spectrum.csv
            (third octaves, dB re 20 µPa), including 'spb_passby'. Empty otherwise.
        levels : dict
            {receiver: {'Leq_dB', 'LAeq_dB', 'LAFmax_dB', ...}}, summary['levels'].
        sound_power : dict
            sound_power.csv as arrays: 'band_hz', 'Lw_dB', 'LwA_dB' (dB re 1 pW).
        wav : dict
            {receiver: path} of the WAV files written into `out` (empty without `out`).
        out : str or None
            The output folder written.

    Raises
    ------
    InputError
        Bad input (a ValueError), with the command line's message.
    OutputError
        A failed write into `out` (an OSError).
    KeyboardInterrupt
        Ctrl-C: the run stops and `out` is left as it was.

    Example
    -------
    >>> r = rollnoise.simulate("models/cases/larsson2000_sdof_sine.toml", set={"rolling.static_load": 3})
    >>> r.force.shape, r.summary["points"][0]["max_force_N"]
    """
    overrides = _overrides(set)
    kind, value, name = _source(case, "case")
    temporary = None
    folder = _folder(out)
    if not folder:
        temporary = _tempfile.mkdtemp(prefix="rollnoise-")
        folder = _os.path.join(temporary, "run")
        if not any(o.startswith("output.plots=") for o in overrides):
            overrides = overrides + ["output.plots=false"]
    try:
        answer = _rollnoise.simulate(kind, value, name, overrides, folder, cache, bool(force), progress)
        summary = _json.loads(answer["summary"])
        fields = _read_simulation(answer["out"], summary)
        wav = {}
        if temporary is None:
            wav = {
                entry[: -len(".wav")]: _os.path.join(answer["out"], entry)
                for entry in sorted(_os.listdir(answer["out"]))
                if entry.endswith(".wav")
            }
        return Result(summary=summary, wav=wav, out=None if temporary else answer["out"], **fields)
    finally:
        if temporary is not None:
            _shutil.rmtree(temporary, ignore_errors=True)


def road(road, set=None, out=None, length=7.0, spacing=None, lines=1, width=0.16, force=False, progress=None,
         ground_effect=None):
    """Generate or read a road and analyse its texture (ISO 13473-1, -4; ISO 8608).

    What `rollnoise road INPUT` does, through the same library function.

    Parameters
    ----------
    road : str, os.PathLike, dict or array
        The road: a file (a case, whose [road] is used; a surface file such as
        models/surfaces/dac11.toml; or a profile file: profile CSV, HDF5 height map, laser
        profilometer export, line laser CSV); TOML text (a str holding a newline or '='); a dict
        holding the keys of a [road] table ({'type': 'sine', 'amplitude': 1e-3, ...} or
        {'surface': 'models/surfaces/dac11.toml'}) or a case's tables ({'road': {...}}); or the
        heights themselves, an array in m of one line [samples] or of lines [lines, samples],
        with `spacing`. Heights are cleaned (NaN marks a dropout) and analysed as a profile
        file's are.
    set : dict, optional
        Overrides of the road's keys, {'road.key': value} ({'key': value} for a surface file, as
        --set takes them); TOML input only.
    out : str or os.PathLike, optional
        Given: road.csv, texture.csv (target.csv), summary.json and the plots are written there.
    length : float, default 7.0
        Length of a generated road, m.
    spacing : float, optional
        Sample spacing of a generated road, m (default 0.0002, a texture road its own), at most
        0.001. Required with heights: their spacing.
    lines : int, default 1
        Lateral lines of a generated road, spread over `width` (m, default 0.16).
    force : bool, default False
        Generate the road even when the estimate of its size exceeds what the machine has.
    progress : callable, optional
        progress(stage, done, total) while a generated road is sampled.
    ground_effect : (float, float, float), optional
        (source height, horizontal distance, receiver height), m, all > 0: the level of a point
        source over this surface minus that over a rigid road, per third octave (what
        `--ground-effect HS,D,HR` writes to ground_effect.csv). TOML input only.

    Returns
    -------
    Result with
        x : ndarray [samples]           positions along the road, m
        z : ndarray [lines, samples]    heights, m (road.csv's z or z_1 ...)
        y : ndarray [lines]             lateral positions of the lines, m
        mpd_m, etd_m : float or None    mean profile depth and estimated texture depth, m
        texture : dict                  'wavelength_m' and 'Ltx_dB' (dB re 1 µm), texture.csv
        target : dict                   a texture road's target levels, as texture (else empty)
        absorption : dict               an absorbing surface's 'band_hz', 'alpha', 'z_re', 'z_im'
                                        (absorption.csv; empty for a rigid one)
        ground_effect : dict            with ground_effect: 'band_hz', 'delta_dB', 'delta_band_dB'
                                        (ground_effect.csv; else empty)
        summary : dict                  summary.json
        out : str or None

    Raises InputError on bad input, OutputError on a failed write.
    """
    if isinstance(road, (_np.ndarray, list, tuple)) and not isinstance(road, str):
        if spacing is None:
            raise _input_error("heights", "spacing", "give the heights' sample spacing in m (spacing=...)")
        if set:
            raise _input_error("heights", "set", "applies to a TOML road; heights have no keys to set")
        if ground_effect is not None:
            raise _input_error("heights", "ground_effect", "needs a surface with [road.absorption]; heights are rigid")
        z = _np.asarray(road, dtype=float)
        answer = _rollnoise.road_heights(z, float(spacing), [], "heights", _folder(out))
    else:
        kind, value, name = _source(road, "road")
        if kind == "dict" and "road" not in value:
            value = {"road": value}
        if ground_effect is not None:
            ground_effect = [float(v) for v in ground_effect]
            if len(ground_effect) != 3:
                raise _input_error(name, "ground_effect", "give (source height, horizontal distance, receiver height) in m, each > 0")
        answer = _rollnoise.road(
            kind, value, name, _overrides(set), float(length),
            None if spacing is None else float(spacing), int(lines), float(width), bool(force), _folder(out), progress,
            ground_effect,
        )
    summary = _json.loads(answer["summary"])
    target = {}
    if len(answer["target_wavelength_m"]):
        target = {"wavelength_m": answer["target_wavelength_m"], "Ltx_dB": answer["target_Ltx_dB"]}
    return Result(
        x=answer["x"],
        z=answer["z"],
        y=answer["y"],
        mpd_m=summary["mpd_m"],
        etd_m=summary["etd_m"],
        texture={"wavelength_m": answer["wavelength_m"], "Ltx_dB": answer["Ltx_dB"]},
        target=target,
        absorption={} if len(answer["alpha"]) == 0 else {
            "band_hz": answer["absorption_band_hz"], "alpha": answer["alpha"], "z_re": answer["z_re"], "z_im": answer["z_im"]},
        ground_effect={} if len(answer["delta_dB"]) == 0 else {
            "band_hz": answer["ground_band_hz"], "delta_dB": answer["delta_dB"], "delta_band_dB": answer["delta_band_dB"]},
        summary=summary,
        out=None if out is None else _os.fspath(out),
    )


def analyse(recording, full_scale=None, out=None):
    """Spectra and levels of a recording, computed as simulate computes its microphones'.

    What `rollnoise analyse FILE` does: third-octave band levels (IEC 61260-1 filters),
    A-weighting (IEC 61672-1), Leq, LAeq and LAFmax, through the same library function.

    Parameters
    ----------
    recording : str, os.PathLike or tuple
        A WAV file (each channel a receiver 'ch1', 'ch2', ...) or a UFF file (.uff, .unv) of
        dataset 58/58b time records of sound pressure in Pa; or (signal, sample_rate): the
        sound pressure in Pa as an array [samples] (receiver 'ch1') or [channels, samples]
        ('ch1', 'ch2', ...), or a dict {receiver: array}, with the sample rate in Hz.
    full_scale : float, optional
        The pressure in Pa of WAV sample value 1.0 (default: the WAV's comment, as simulate
        writes it). Ignored for UFF files and arrays.
    out : str or os.PathLike, optional
        Given: spectrum.csv, summary.json and the plot are written there.

    Returns
    -------
    Result with
        spectrum : dict     {receiver: {'band_hz', 'Lp_dB', 'LpA_dB'}} (spectrum.csv)
        levels : dict       {receiver: {'Leq_dB', 'LAeq_dB', 'LAFmax_dB', 'sample_rate_hz', 'duration_s'}}
        summary : dict      summary.json
        out : str or None

    Raises InputError on bad input (a recording too short for the band filters, a WAV without
    its full scale), OutputError on a failed write.
    """
    if isinstance(recording, tuple):
        if len(recording) != 2:
            raise _input_error("recording", "", "give (signal, sample_rate)")
        signal, rate = recording
        if isinstance(signal, dict):
            names = [str(k) for k in signal]
            arrays = [_np.asarray(v, dtype=float) for v in signal.values()]
        else:
            signal = _np.asarray(signal, dtype=float)
            arrays = [signal] if signal.ndim == 1 else list(signal)
            names = [f"ch{i + 1}" for i in range(len(arrays))]
        answer = _rollnoise.analyse_signals(arrays, names, float(rate), "signal", _folder(out))
    else:
        path = _os.fspath(recording)
        answer = _rollnoise.analyse_file(path, 0.0 if full_scale is None else float(full_scale), _folder(out))
    summary = _json.loads(answer["summary"])
    return Result(
        spectrum=answer["spectrum"],
        levels=summary["levels"],
        summary=summary,
        out=None if out is None else _os.fspath(out),
    )


def read_wav(path):
    """A WAV file as sound pressure: (signals, sample_rate, full_scale).

    signals is {'ch1': array, ...} in Pa (the samples times the full scale), sample_rate in Hz,
    full_scale the pressure in Pa of sample value 1.0 from the file's comment (as simulate writes
    it; None when the file does not say: the signals are then the raw sample values).
    """
    channels, rate, full_scale = _rollnoise.read_wav(_os.fspath(path))
    scale = 1.0 if full_scale is None else full_scale
    return {f"ch{i + 1}": c * scale for i, c in enumerate(channels)}, rate, full_scale


def _table_csv(path):
    """{column: array or list of str} of a CSV with text columns (results.csv, spectra.csv)."""
    header, rows = _csv_rows(path)
    table = {}
    for i, name in enumerate(header):
        cells = [row[i] if i < len(row) else "" for row in rows]
        try:
            table[name] = _np.array([float(c) if c != "" else _np.nan for c in cells])
        except ValueError:
            table[name] = cells
    return table


def study(study, out=None, threads=None, cache=True, fail_fast=False, restart=False, yes=False, progress=None):
    """Run a study: the product of a study file's [vary] lists on a base case, on threads.

    What `rollnoise study STUDY --out OUT` does (on one machine), through the same library
    function: every case a normal simulation written atomically into OUT/cases/<id>/ with its
    case.toml, then results.csv, spectra.csv, summary.json and the plots. Resumable: a case
    finished by an earlier run into the same folder is kept.

    Parameters
    ----------
    study : str or os.PathLike
        The study file ([study], [set], [vary]: docs/reference/study-files.md).
    out : str or os.PathLike, optional
        The study's folder (default out/<[study] name>). A study always writes its folder.
    threads : int, optional
        Cases side by side (default one per core).
    cache : bool or str, default True
        As for simulate.
    fail_fast, restart, yes : bool
        As --fail-fast (start no more cases after one fails), --restart (run every case again)
        and --yes (run more than 200 cases).
    progress : callable, optional
        progress('study NAME', cases done, cases) as cases end.

    Returns
    -------
    Result with
        summary : dict      summary.json (cases, case_list, level_fits, ...)
        results : dict      results.csv by column: the varied keys (lists of str or arrays),
                            'LAeq_<receiver>_dB', 'LWA_dB', ... (arrays, NaN for a failed
                            case), 'status' (list of str)
        spectra : dict      spectra.csv by column, the same way
        out : str           the study's folder

    A case that fails does not raise: its row says 'failed' and summary['case_list'] why.
    Raises InputError on a bad study file, KeyboardInterrupt on Ctrl-C (the finished cases are
    kept for a rerun, no results are written).
    """
    path = _os.fspath(study)
    answer = _rollnoise.study(path, _folder(out), 0 if threads is None else int(threads), bool(fail_fast),
                              bool(restart), bool(yes), cache, progress)
    folder = answer["out"]
    return Result(
        summary=_json.loads(answer["summary"]),
        results=_table_csv(_os.path.join(folder, "results.csv")),
        spectra=_table_csv(_os.path.join(folder, "spectra.csv")),
        out=folder,
    )


def greens(model, frequencies=None, distances=None, out=None, cache=True, force=False):
    """A tyre model's receptance, mobility and Green's function in time.

    What `rollnoise greens MODEL` does, through the same library function: the receptance and
    mobility between a force at the belt's centre (x = 0, mid-width) and responses on the
    centre line at `distances` along the circumference, and the Green's function in time (the
    displacement per unit impulse).

    Parameters
    ----------
    model : str, os.PathLike or dict
        A tyre model file (models/tyres/NAME.toml: sdof, coupled_sdof, plate, two_layer,
        tabulated), TOML text, or a dict of its keys ({'model': 'sdof', 'mass': 1.0, ...}).
    frequencies : array, optional
        The frequencies, Hz (at least 0, at most 100000 of them). Default: 501 from 0 Hz to
        the model's top frequency (5 kHz in 10 Hz steps for a tyre).
    distances : array, optional
        The response points, m along the circumference (default: 0, 0.05, 0.1, 0.2, 0.5 for a
        tyre; a point model's points).
    out : str or os.PathLike, optional
        Given: receptance.csv, mobility.csv, greens.h5, summary.json, the plots (and
        modal_receptance.h5 for two_layer) are written there.
    cache : bool or str, default True
        As for simulate (a two-layer tyre's modal table, a tabulated model's mode fits).
    force : bool, default False
        Run even when the estimate of the tables' size exceeds what the machine has.

    Returns
    -------
    Result with
        frequency_hz : ndarray [F]
        distance_m : ndarray [D]
        receptance : complex ndarray [F, D]     u/F, m/N (0 Hz: the static compliance)
        mobility : complex ndarray [F, D]       iω·u/F, m/(N·s)
        time : ndarray [200]                    s after the impulse
        green_distance_m : ndarray [P]          the Green's function's points: one revolution
                                                (512) for a tyre, the model's points otherwise
        green : ndarray [200, P]                m/(N·s), without the instantaneous part
        summary : dict                          summary.json
        out : str or None

    Raises InputError on bad input, OutputError on a failed write.
    """
    kind, value, name = _source(model, "model")
    answer = _rollnoise.greens(
        kind, value, name,
        [] if frequencies is None else [float(f) for f in _np.atleast_1d(frequencies)],
        [] if distances is None else [float(d) for d in _np.atleast_1d(distances)],
        cache, bool(force), _folder(out),
    )
    return Result(
        frequency_hz=answer["frequency_hz"],
        distance_m=answer["distance_m"],
        receptance=answer["receptance"],
        mobility=answer["mobility"],
        time=answer["time"],
        green_distance_m=answer["green_distance_m"],
        green=answer["green"],
        summary=_json.loads(answer["summary"]),
        out=None if out is None else _os.fspath(out),
    )


def _position(value, option):
    """(x, y) in m, or "X,Y", as the --response/--excitation/--node text."""
    if isinstance(value, str):
        return value
    try:
        x, y = value
        return f"{float(x)!r},{float(y)!r}"
    except (TypeError, ValueError):
        raise _input_error(option, repr(value),
                           "expected (x, y) in m (x along the circumference, y across the belt from one edge)") from None


def _positions(value, option):
    """None, one position, or one per data file."""
    if value is None:
        return []
    if isinstance(value, str) or (len(value) == 2 and all(_np.isscalar(v) for v in value)):
        return [_position(value, option)]
    return [_position(v, option) for v in value]


def calibrate(model, data, fit=None, out=None, data_type=None, response=None, excitation=None, nodes=None,
              transducer_mass=0.0, frequency_range=None, starts=None, seed=1, loss_scale=0.25, first_stage=None,
              force=False, progress=None):
    """Fit a tyre model's parameters to measured mobilities (Ceres).

    What `rollnoise calibrate MODEL --data FILE...` does, through the same library function: the
    unknowns are the logarithms of the parameters within three decades of the model file's
    values; each frequency line's residual is the complex log ratio of the model's FRF to the
    measured one, every third-octave band of every FRF weighing the same, under a Cauchy loss;
    several seeded starts, the lowest cost wins (docs/physics/calibration.md).

    Parameters
    ----------
    model : str or os.PathLike
        The model file to start from (its values: the first start and the bounds' centre).
    data : str, os.PathLike or list of them
        The measured FRFs: CSV files (one FRF each) or UFF 58/58b files, fitted together.
    fit : list of str, optional
        The parameters to fit, by model-file key (default: the model's; the list is in
        docs/reference/commands.md).
    out : str or os.PathLike, optional
        Given: calibrated.toml, fit.csv, report.json and fit.png are written there.
    data_type : str, optional
        'mobility' (default), 'receptance' or 'accelerance' for files that do not say; given, a
        file that says otherwise is an error.
    response, excitation : (x, y), or a list of them, one per data file, optional
        Where the response was measured and the force applied, m.
    nodes : dict, optional
        {UFF node number: (x, y)}.
    transducer_mass : float, default 0
        kg at each response point (the starting value when 'transducer_mass' is fitted).
    frequency_range : (lo, hi), optional
        Fit only the lines from lo to hi Hz.
    starts : int, optional
        The number of starts (default 8; 1 for two_layer).
    seed : int, default 1
        The seed of the starts' draws; the same data and seed give the same result.
    loss_scale : float, default 0.25
        The Cauchy loss's scale on the log residual.
    first_stage : float, optional
        Fit the lines up to this frequency first, then twice it, ... (0: the whole band at once;
        default: the model's choice).
    force : bool, default False
        Run even when the estimate of the fit's size exceeds what the machine has.
    progress : callable, optional
        progress('calibrate NAME', done, total) over the starts.

    Returns
    -------
    Result with
        parameters : dict       {name: fitted value}
        summary : dict          report.json: values, standard errors, correlations, conditioning,
                                residual, starts, warnings
        calibrated : str        calibrated.toml: the model file with the fitted values
        frfs : list of dict     per FRF: 'name', 'frequency_hz', 'measured' and 'fitted'
                                (complex mobility, m/(N·s)), 'weight' (fit.csv's rows)
        notes : list of str     what the readers left out or assumed
        out : str or None

    Raises InputError on bad input, OutputError on a failed write.
    """
    files = [_os.fspath(data)] if isinstance(data, (str, _os.PathLike)) else [_os.fspath(d) for d in data]
    node_list = [] if nodes is None else [f"{int(n)}={_position(p, '--node')}" for n, p in nodes.items()]
    band = ""
    if frequency_range is not None:
        band = frequency_range if isinstance(frequency_range, str) else "{!r}:{!r}".format(*map(float, frequency_range))
    answer = _rollnoise.calibrate(
        _os.fspath(model), files, [] if fit is None else [fit] if isinstance(fit, str) else list(fit),
        "mobility" if data_type is None else str(data_type), data_type is not None,
        _positions(response, "--response"), _positions(excitation, "--excitation"), node_list, float(transducer_mass), band,
        0 if starts is None else int(starts), int(seed), float(loss_scale),
        -1.0 if first_stage is None else float(first_stage), bool(force), _folder(out), progress,
    )
    report = _json.loads(answer["report"])
    return Result(
        parameters={name: p["value"] for name, p in report["parameters"].items()},
        summary=report,
        calibrated=answer["calibrated"],
        frfs=answer["frfs"],
        notes=list(answer["notes"]),
        out=None if out is None else _os.fspath(out),
    )
