"""Bad input raises rollnoise.InputError (a ValueError) with the command line's message; a failed
write raises rollnoise.OutputError (an OSError) and leaves nothing half-written."""
import os
import subprocess
import sys

import pytest

import rollnoise
from conftest import SOURCE, run_cli

SDOF = SOURCE / "models" / "cases" / "larsson2000_sdof_sine.toml"


def cli_message(*args):
    """The command line's error line, without 'rollnoise: error: ', and its exit status 2."""
    result = run_cli(*args, check=False)
    assert result.returncode == 2, result.stderr
    line = result.stderr.strip().splitlines()[-1]
    assert line.startswith("rollnoise: error: "), line
    return line[len("rollnoise: error: "):]


def test_input_error_is_a_value_error():
    assert issubclass(rollnoise.InputError, ValueError)
    assert issubclass(rollnoise.OutputError, OSError)


@pytest.mark.parametrize("overrides", [
    ["rolling.speed=-1"],
    ["tyre.colour=\"red\""],
    ["road.type=\"zigzag\""],
    ["rolling.duration=nan"],
])
def test_bad_case_values_give_the_command_lines_message(overrides):
    sets = [a for o in overrides for a in ("--set", o)]
    expected = cli_message("simulate", SDOF, *sets, "--out", "/nonexistent/never")
    with pytest.raises(rollnoise.InputError) as caught:
        rollnoise.simulate(SDOF, set=list(overrides))
    assert str(caught.value) == expected
    assert caught.value.problem and caught.value.problem in expected


def test_a_bad_case_file_gives_the_command_lines_message(tmp_path):
    case = tmp_path / "bad.toml"
    case.write_text(SDOF.read_text().replace("mass = 1.0", "mass = -1.0"))
    expected = cli_message("simulate", case, "--out", tmp_path / "out")
    with pytest.raises(rollnoise.InputError) as caught:
        rollnoise.simulate(case, out=tmp_path / "py")
    assert str(caught.value) == expected and "[tyre] mass" in expected
    assert not (tmp_path / "py").exists() and not (tmp_path / "out").exists()
    case.write_text("[tyre\nmodel = 1")
    expected = cli_message("simulate", case)
    with pytest.raises(rollnoise.InputError, match="malformed TOML") as caught:
        rollnoise.simulate(case)
    assert str(caught.value) == expected


def test_a_missing_file_and_a_bad_dict():
    assert str(pytest.raises(rollnoise.InputError, rollnoise.simulate, "no_such_case.toml").value) == \
        cli_message("simulate", "no_such_case.toml")
    with pytest.raises(rollnoise.InputError, match=r"^<case dict>: \[tyre\]: section is required"):
        rollnoise.simulate({"road": {"type": "flat"}})
    with pytest.raises(rollnoise.InputError, match="cannot be written in TOML"):
        rollnoise.simulate({"tyre": {"mass": object()}})


def test_road_and_analyse_errors_give_the_command_lines_message(tmp_path):
    dac11 = SOURCE / "models" / "surfaces" / "dac11.toml"
    with pytest.raises(rollnoise.InputError) as caught:
        rollnoise.road(dac11, spacing=0.01)
    assert str(caught.value) == cli_message("road", dac11, "--spacing", "0.01")
    with pytest.raises(rollnoise.InputError) as caught:
        rollnoise.road(dac11, set={"road.max_chip_size": -1}, length=0.2)
    assert str(caught.value) == cli_message("road", dac11, "--set", "road.max_chip_size=-1", "--length", "0.2")
    wav = SOURCE / "tests" / "corpus" / "wav" / "ok_mono_16bit_8khz.wav"
    with pytest.raises(rollnoise.InputError) as caught:
        rollnoise.analyse(wav)
    assert str(caught.value) == cli_message("analyse", wav, "--out", tmp_path / "a")
    with pytest.raises(rollnoise.InputError, match="^signal: ch1: holds a value that is not a finite number$"):
        rollnoise.analyse(([0.0, float("nan")] * 100, 48000.0))
    with pytest.raises(rollnoise.InputError, match="sample_rate"):
        rollnoise.analyse(([0.0] * 100, -1.0))
    with pytest.raises(rollnoise.InputError, match="spacing"):
        rollnoise.road([0.0, 1.0, 2.0])


def test_a_folder_that_is_not_an_output_is_refused(tmp_path):
    (tmp_path / "mine").mkdir()
    (tmp_path / "mine" / "notes.txt").write_text("mine")
    expected = cli_message("simulate", SDOF, "--out", tmp_path / "mine")
    with pytest.raises(rollnoise.InputError) as caught:
        rollnoise.simulate(SDOF, out=tmp_path / "mine")
    assert str(caught.value) == expected
    assert (tmp_path / "mine" / "notes.txt").read_text() == "mine"


def test_a_failed_write_is_an_output_error_and_leaves_nothing(tmp_path):
    # A file-size limit (as a full disk): contact.csv cannot be written. force=True: the size
    # estimate would refuse the run before it starts (an InputError, as without --force).
    script = f"""
import resource, signal, rollnoise
signal.signal(signal.SIGXFSZ, signal.SIG_IGN)
resource.setrlimit(resource.RLIMIT_FSIZE, (20000, 20000))
try:
    rollnoise.simulate({str(SDOF)!r}, out={str(tmp_path / 'out')!r}, force=True)
except rollnoise.OutputError as error:
    print("OutputError", isinstance(error, OSError), error)
"""
    result = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, env=os.environ)
    assert result.stdout.startswith("OutputError True cannot write"), result.stdout + result.stderr
    assert os.listdir(tmp_path) == []
