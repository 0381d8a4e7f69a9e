"""rollnoise.greens against `rollnoise greens`: a point model and the plate tyre."""
import numpy as np
import pytest

import rollnoise
from rollnoise import _rollnoise
from conftest import SOURCE, comparable, read_columns, read_json, run_cli

SDOF = SOURCE / "models" / "tyres" / "larsson2000_sdof.toml"
PLATE = SOURCE / "models" / "tyres" / "passenger_205_55R16.toml"


def assert_table(result, csv, key):
    table = read_columns(csv)
    nf, nd = len(result.frequency_hz), len(result.distance_m)
    # Rows distance by distance, each a block of the frequencies.
    np.testing.assert_array_equal(table["frequency_hz"], np.tile(result.frequency_hz, nd))
    np.testing.assert_array_equal(table["distance_m"], np.repeat(result.distance_m, nf))
    values = getattr(result, key)
    np.testing.assert_array_equal(table["re"], values.real.T.reshape(-1))
    np.testing.assert_array_equal(table["im"], values.imag.T.reshape(-1))


@pytest.mark.parametrize("model,args,kwargs", [
    (SDOF, [], {}),
    (PLATE, ["--frequencies", "0:2000:201", "--distances", "0,0.1"],
     {"frequencies": np.linspace(0.0, 2000.0, 201), "distances": [0.0, 0.1]}),
])
def test_tables_equal_the_command_lines(model, args, kwargs, tmp_path):
    run_cli("greens", model, "--out", tmp_path / "cli", *args)
    result = rollnoise.greens(model, **kwargs)
    assert_table(result, tmp_path / "cli" / "receptance.csv", "receptance")
    assert_table(result, tmp_path / "cli" / "mobility.csv", "mobility")
    h5 = str(tmp_path / "cli" / "greens.h5")
    np.testing.assert_array_equal(result.time, _rollnoise.read_h5(h5, "/time_domain/time"))
    np.testing.assert_array_equal(result.green, _rollnoise.read_h5(h5, "/time_domain/green"))
    np.testing.assert_array_equal(result.green_distance_m, _rollnoise.read_h5(h5, "/time_domain/distance"))
    assert comparable(result.summary) == comparable(read_json(tmp_path / "cli" / "summary.json"))


def test_out_and_a_model_dict(tmp_path):
    run_cli("greens", SDOF, "--out", tmp_path / "cli")
    result = rollnoise.greens(SDOF, out=tmp_path / "py")
    assert (tmp_path / "py" / "receptance.csv").read_bytes() == (tmp_path / "cli" / "receptance.csv").read_bytes()
    import tomllib
    from_dict = rollnoise.greens(tomllib.loads(SDOF.read_text()))
    np.testing.assert_array_equal(from_dict.receptance, result.receptance)
    with pytest.raises(rollnoise.InputError) as caught:
        rollnoise.greens(SDOF, distances=[0.3])
    expected = run_cli("greens", SDOF, "--distances", "0.3", check=False).stderr.strip()
    assert "rollnoise: error: " + str(caught.value) == expected
