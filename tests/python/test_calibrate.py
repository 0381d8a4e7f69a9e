"""rollnoise.calibrate against `rollnoise calibrate`: the paper's SDOF fitted to its synthetic
point mobility; bad options."""
import numpy as np
import pytest

import rollnoise
from conftest import SOURCE, comparable, read_columns, read_json, run_cli

MODEL = SOURCE / "models" / "tyres" / "larsson2000_sdof.toml"
DATA = SOURCE / "data" / "mobility" / "sdof_point_mobility.csv"


def test_a_fit_equals_the_command_lines(tmp_path):
    run_cli("calibrate", MODEL, "--data", DATA, "--starts", "2", "--out", tmp_path / "cli")
    calls = []
    result = rollnoise.calibrate(MODEL, DATA, starts=2, out=tmp_path / "py", progress=lambda *a: calls.append(a))
    report = read_json(tmp_path / "cli" / "report.json")
    assert comparable(result.summary) == comparable(report)
    assert result.parameters == {k: v["value"] for k, v in report["parameters"].items()}
    assert result.calibrated == (tmp_path / "cli" / "calibrated.toml").read_text()
    fit = read_columns(tmp_path / "cli" / "fit.csv")
    frf = result.frfs[0]
    np.testing.assert_array_equal(frf["frequency_hz"], fit["frequency_hz"])
    np.testing.assert_array_equal(frf["measured"].real, fit["measured_re"])
    np.testing.assert_array_equal(frf["fitted"].imag, fit["fitted_im"])
    np.testing.assert_array_equal(frf["weight"], fit["weight"])
    assert (tmp_path / "py" / "fit.csv").read_bytes() == (tmp_path / "cli" / "fit.csv").read_bytes()
    assert calls and calls[-1][0] == "calibrate larsson2000_sdof.toml" and calls[-1][1] == calls[-1][2]


def test_bad_options_give_the_command_lines_message():
    for kwargs, args in [({"fit": ["colour"]}, ["--fit", "colour"]),
                         ({"frequency_range": (10.0, 5.0)}, ["--frequency-range", "10.0:5.0"]),
                         ({"response": (0.1,)}, None)]:
        if args is None:
            with pytest.raises(rollnoise.InputError, match=r"^--response: 0\.1: expected \(x, y\) in m"):
                rollnoise.calibrate(MODEL, DATA, **kwargs)
            continue
        with pytest.raises(rollnoise.InputError) as caught:
            rollnoise.calibrate(MODEL, DATA, **kwargs)
        expected = run_cli("calibrate", MODEL, "--data", DATA, *args, check=False)
        assert expected.returncode == 2
        assert "rollnoise: error: " + str(caught.value) == expected.stderr.strip().splitlines()[-1]
