"""rollnoise.simulate on a tyre with its sound, and rollnoise.analyse on the recording it made,
against the command line: the totals, the contact fields, the spectra, the sound power, the
levels; the WAV analysed from its file and from its samples."""
import numpy as np
import pytest

import rollnoise
from rollnoise import _rollnoise
from conftest import SOURCE, comparable, read_columns, read_json, read_spectrum, run_cli

# The passenger tyre on DAC 11 for 20 ms, on a coarse radiation mesh (as the command line's own
# sound test): seconds, not minutes.
CASE = SOURCE / "models" / "cases" / "plate_rough_80kmh.toml"
SETTINGS = {
    "tyre.file": str(SOURCE / "models" / "tyres" / "passenger_205_55R16.toml"),
    "road.surface": str(SOURCE / "models" / "surfaces" / "dac11.toml"),
    "rolling.duration": 0.02,
    "radiation.mesh_around": 32,
    "radiation.mesh_across": 4,
    "radiation.sidewall_rings": 4,
    "radiation.max_frequency": 1500,
    "radiation.anchor_spacing": 250,
    "radiation.contact_refinement": 3,
}


@pytest.fixture(scope="module")
def runs(tmp_path_factory):
    folder = tmp_path_factory.mktemp("tyre")
    sets = []
    for key, value in SETTINGS.items():
        sets += ["--set", f"{key}={rollnoise._toml_value(value)}"]
    run_cli("simulate", CASE, "--out", folder / "cli", *sets)
    stages = []
    result = rollnoise.simulate(CASE, set=SETTINGS, out=folder / "py",
                                progress=lambda stage, done, total: stages.append((stage, done, total)))
    return folder, result, stages


def test_totals_and_fields_equal_the_command_lines(runs):
    folder, result, _ = runs
    cli = read_columns(folder / "cli" / "contact.csv")
    np.testing.assert_array_equal(result.time, cli["time"])
    for key in ("total_force", "contact_area", "contact_length"):
        np.testing.assert_array_equal(result.totals[key], cli[key])
    h5 = str(folder / "cli" / "contact.h5")
    force = _rollnoise.read_h5(h5, "/contact/force")
    np.testing.assert_array_equal(result.force, force)
    np.testing.assert_array_equal(result.velocity, _rollnoise.read_h5(h5, "/surface/velocity"))
    assert result.force.shape[0] == len(result.time) and result.road.shape == result.force.shape
    assert result.displacement is None  # [output] fields = "contact"
    # The window's road read back from the strip: window point (i, j) at step n is strip[j][i·p + n].
    strip = _rollnoise.read_h5(h5, "/contact/road_strip")
    p = int(_rollnoise.h5_number_attribute(h5, "/", "substeps_per_cell"))
    n, j, i = len(result.time) - 1, 2, 5
    assert result.road[n, j, i] == strip[j, i * p + n]
    # The forces sum to the total force (32-bit fields).
    np.testing.assert_allclose(result.force.sum(axis=(1, 2)), result.totals["total_force"], rtol=1e-5)


def test_sound_equals_the_command_lines(runs):
    folder, result, _ = runs
    spectra = read_spectrum(folder / "cli" / "spectrum.csv")
    assert list(result.spectrum) == list(spectra) == ["cpx_front", "cpx_rear", "spb", "spb_passby"]
    for receiver, (band, lp, lpa) in spectra.items():
        np.testing.assert_array_equal(result.spectrum[receiver]["band_hz"], band)
        np.testing.assert_array_equal(result.spectrum[receiver]["Lp_dB"], lp)
        np.testing.assert_array_equal(result.spectrum[receiver]["LpA_dB"], lpa)
    power = read_columns(folder / "cli" / "sound_power.csv")
    for key in ("band_hz", "Lw_dB", "LwA_dB"):
        np.testing.assert_array_equal(result.sound_power[key], power[key])
    summary = read_json(folder / "cli" / "summary.json")
    assert result.levels == summary["levels"]
    assert comparable(result.summary) == comparable(summary)
    assert sorted(result.wav) == ["cpx_front", "cpx_rear", "spb", "spb_passby"]
    # The samples (the files' PEAK chunks carry the time they were written).
    for receiver in result.wav:
        ours, theirs = rollnoise.read_wav(result.wav[receiver]), rollnoise.read_wav(folder / "cli" / f"{receiver}.wav")
        np.testing.assert_array_equal(ours[0]["ch1"], theirs[0]["ch1"])
        assert ours[1:] == theirs[1:]


def test_progress_reports_the_steps_and_the_anchors(runs):
    _, result, stages = runs
    names = {stage for stage, _, _ in stages}
    assert "simulate plate_rough_80kmh.toml" in names, names
    assert all(0 <= done <= total for _, done, total in stages)
    steps = result.summary["settings"]["steps"] + 1
    assert ("simulate plate_rough_80kmh.toml", steps, steps) in stages


def test_analysing_the_recording_equals_the_command_line(runs, tmp_path):
    folder, result, _ = runs
    wav = folder / "py" / "cpx_front.wav"
    run_cli("analyse", wav, "--out", tmp_path / "cli")
    from_file = rollnoise.analyse(wav, out=tmp_path / "py")
    spectra = read_spectrum(tmp_path / "cli" / "spectrum.csv")
    band, lp, lpa = spectra["ch1"]
    np.testing.assert_array_equal(from_file.spectrum["ch1"]["band_hz"], band)
    np.testing.assert_array_equal(from_file.spectrum["ch1"]["Lp_dB"], lp)
    np.testing.assert_array_equal(from_file.spectrum["ch1"]["LpA_dB"], lpa)
    summary = read_json(tmp_path / "cli" / "summary.json")
    assert from_file.levels == summary["levels"]
    assert comparable(from_file.summary) == comparable(summary)
    assert (tmp_path / "py" / "spectrum.csv").read_bytes() == (tmp_path / "cli" / "spectrum.csv").read_bytes()
    # The simulation's own levels at the microphone, read back from its WAV (as the command line's test).
    assert abs(from_file.levels["ch1"]["LAeq_dB"] - result.levels["cpx_front"]["LAeq_dB"]) < 0.05
    # The same samples given as an array.
    signals, rate, full_scale = rollnoise.read_wav(wav)
    assert full_scale == result.summary["full_scale_pa"] and rate == 48000
    from_array = rollnoise.analyse((signals["ch1"], rate))
    for key in ("band_hz", "Lp_dB", "LpA_dB"):
        np.testing.assert_array_equal(from_array.spectrum["ch1"][key], from_file.spectrum["ch1"][key])
    assert from_array.levels == from_file.levels
    named = rollnoise.analyse(({"front": signals["ch1"], "again": signals["ch1"]}, rate))
    assert list(named.spectrum) == ["front", "again"]
