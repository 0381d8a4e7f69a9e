"""rollnoise.simulate against `rollnoise simulate`: the paper's point-model cases (Larsson 2000,
§4), overrides, a case given as text or a dict, the output folder."""
import os
import tempfile

import numpy as np
import pytest

import rollnoise
from conftest import SOURCE, comparable, read_columns, read_json, run_cli

PAPER_CASES = ["larsson2000_sdof_sine", "larsson2000_sdof_random", "larsson2000_coupled_sine",
               "larsson2000_coupled_random", "larsson2000_uncoupled_sine"]


def assert_point_arrays_equal(result, contact_csv):
    cli = read_columns(contact_csv)
    np.testing.assert_array_equal(result.time, cli["time"])
    points = result.force.shape[1]
    assert result.force.shape == (len(cli["time"]), points)
    assert f"force_{points}" in cli and f"force_{points + 1}" not in cli
    for i in range(points):
        np.testing.assert_array_equal(result.force[:, i], cli[f"force_{i + 1}"])
        np.testing.assert_array_equal(result.displacement[:, i], cli[f"displacement_{i + 1}"])
        np.testing.assert_array_equal(result.road[:, i], cli[f"road_{i + 1}"])


@pytest.mark.parametrize("name", PAPER_CASES)
def test_paper_cases_give_the_command_lines_arrays(name, tmp_path):
    case = SOURCE / "models" / "cases" / f"{name}.toml"
    run_cli("simulate", case, "--out", tmp_path / "cli")
    result = rollnoise.simulate(str(case))
    assert result.out is None and result.wav == {} and result.spectrum == {}
    assert_point_arrays_equal(result, tmp_path / "cli" / "contact.csv")
    assert comparable(result.summary) == comparable(read_json(tmp_path / "cli" / "summary.json"))


def test_overrides_are_the_command_lines_set(tmp_path):
    case = SOURCE / "models" / "cases" / "larsson2000_sdof_sine.toml"
    run_cli("simulate", case, "--out", tmp_path / "cli", "--set", "rolling.static_load=3",
            "--set", "road.wavelength=0.05", "--set", "rolling.duration=0.2")
    result = rollnoise.simulate(case, set={"rolling.static_load": 3, "road.wavelength": 0.05, "rolling.duration": 0.2})
    assert_point_arrays_equal(result, tmp_path / "cli" / "contact.csv")
    assert result.summary["settings"]["static_load_N"] == 3


def test_a_case_as_text_or_dict_runs_as_its_file():
    case = SOURCE / "models" / "cases" / "larsson2000_coupled_sine.toml"
    from_file = rollnoise.simulate(case)
    text = case.read_text()
    from_text = rollnoise.simulate(text)
    import tomllib
    from_dict = rollnoise.simulate(tomllib.loads(text))
    for other, name in ((from_text, "<case text>"), (from_dict, "<case dict>")):
        np.testing.assert_array_equal(other.force, from_file.force)
        np.testing.assert_array_equal(other.displacement, from_file.displacement)
        np.testing.assert_array_equal(other.road, from_file.road)
        assert other.summary["case"] == name
        assert comparable({**other.summary, "case": ""}) == comparable({**from_file.summary, "case": ""})


def test_out_holds_what_the_command_line_writes(tmp_path):
    case = SOURCE / "models" / "cases" / "larsson2000_sdof_sine.toml"
    run_cli("simulate", case, "--out", tmp_path / "cli")
    result = rollnoise.simulate(case, out=tmp_path / "py")
    assert result.out == str(tmp_path / "py")
    assert sorted(os.listdir(tmp_path / "py")) == sorted(os.listdir(tmp_path / "cli"))
    assert (tmp_path / "py" / "contact.csv").read_bytes() == (tmp_path / "cli" / "contact.csv").read_bytes()
    # A second run replaces the folder, as the command line does.
    rollnoise.simulate(case, set={"rolling.duration": 0.1}, out=tmp_path / "py")
    assert read_json(tmp_path / "py" / "summary.json")["settings"]["duration_s"] == 0.1


def test_without_out_no_file_is_left(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    monkeypatch.setattr(tempfile, "tempdir", str(tmp_path / "temp"))
    (tmp_path / "temp").mkdir()
    # (without the cache, whose folder a run creates when it is missing)
    rollnoise.simulate(SOURCE / "models" / "cases" / "larsson2000_sdof_sine.toml", cache=False)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["temp"]
    assert list((tmp_path / "temp").iterdir()) == []
