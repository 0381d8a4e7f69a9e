"""rollnoise.study against `rollnoise study`: the same cases, results and summary; a failing case."""
import numpy as np
import pytest

import rollnoise
from conftest import SOURCE, comparable, read_json

STUDY = f"""[study]
name = "sdof_speeds"
case = "{SOURCE / 'models' / 'cases' / 'larsson2000_sdof_sine.toml'}"
[set]
rolling.duration = 0.1
[vary]
rolling.speed = [1.0, 2.0]
rolling.static_load = [3.0, 4.0]
"""


def without_wall_times(table):
    """The columns as lists, NaN as None (NaN != NaN), without the wall times."""
    def cells(v):
        return [None if isinstance(x, float) and x != x else x for x in (v.tolist() if isinstance(v, np.ndarray) else v)]
    return {k: cells(v) for k, v in table.items() if k != "wall_time_s"}


def test_a_study_gives_the_command_lines_results(tmp_path):
    from conftest import run_cli
    (tmp_path / "study.toml").write_text(STUDY)
    run_cli("study", tmp_path / "study.toml", "--out", tmp_path / "cli", "--threads", "2")
    calls = []
    result = rollnoise.study(tmp_path / "study.toml", out=tmp_path / "py", threads=2,
                             progress=lambda *a: calls.append(a))
    assert result.out == str(tmp_path / "py")
    cli = rollnoise._table_csv(str(tmp_path / "cli" / "results.csv"))
    assert without_wall_times(result.results) == without_wall_times(cli)
    assert result.results["status"] == ["ok"] * 4
    assert comparable(result.summary) == comparable(read_json(tmp_path / "cli" / "summary.json"))
    for case in result.summary["case_list"]:
        folder = "cases/" + case["id"]
        assert (tmp_path / "py" / folder / "contact.csv").read_bytes() == \
            (tmp_path / "cli" / folder / "contact.csv").read_bytes()
    assert calls[-1] == ("study sdof_speeds", 4, 4)
    # A rerun keeps the finished cases.
    again = rollnoise.study(tmp_path / "study.toml", out=tmp_path / "py")
    assert again.summary["cases"]["from_earlier_run"] == 4


def test_a_failing_case_is_reported_not_raised(tmp_path):
    (tmp_path / "study.toml").write_text(STUDY.replace("[1.0, 2.0]", "[-1.0, 2.0]"))
    result = rollnoise.study(tmp_path / "study.toml", out=tmp_path / "s", threads=1)
    assert result.results["status"].count("failed") == 2
    failed = [c for c in result.summary["case_list"] if c["status"] == "failed"]
    assert all("[rolling] speed" in c["message"] for c in failed)


def test_a_bad_study_file_raises_input_error(tmp_path):
    (tmp_path / "study.toml").write_text(STUDY.replace("[vary]", "[vary]\nrolling.colour = [1, 2]"))
    with pytest.raises(rollnoise.InputError):
        rollnoise.study(tmp_path / "study.toml", out=tmp_path / "s")
