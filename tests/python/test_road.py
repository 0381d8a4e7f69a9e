"""rollnoise.road against `rollnoise road`: a library surface, a measured laser profile, heights
given as an array, a [road] dict."""
import numpy as np

import rollnoise
from conftest import SOURCE, comparable, read_columns, read_json, run_cli

DAC11 = SOURCE / "models" / "surfaces" / "dac11.toml"
LASER = SOURCE / "data" / "surfaces" / "captif" / "20211011_aylesbury_dec_station_0.dat"


def assert_road_equal(result, folder):
    road = read_columns(folder / "road.csv")
    texture = read_columns(folder / "texture.csv")
    summary = read_json(folder / "summary.json")
    np.testing.assert_array_equal(result.x, road["x"])
    np.testing.assert_array_equal(result.z[0], road["z"] if "z" in road else road["z_1"])
    np.testing.assert_array_equal(result.texture["wavelength_m"], texture["wavelength_m"])
    np.testing.assert_array_equal(result.texture["Ltx_dB"], texture["Ltx_dB"])
    assert result.mpd_m == summary["mpd_m"] and result.etd_m == summary["etd_m"]
    return summary


def test_a_library_surface_gives_the_command_lines_road(tmp_path):
    run_cli("road", DAC11, "--length", "1", "--out", tmp_path / "cli")
    result = rollnoise.road(DAC11, length=1.0)
    summary = assert_road_equal(result, tmp_path / "cli")
    assert comparable(result.summary) == comparable(summary)
    assert result.z.shape == (1, len(result.x)) and result.target == {}


def test_several_lines_and_overrides(tmp_path):
    run_cli("road", DAC11, "--length", "0.3", "--lines", "3", "--set", "road.seed=7", "--out", tmp_path / "cli")
    result = rollnoise.road(DAC11, length=0.3, lines=3, set={"road.seed": 7}, out=tmp_path / "py")
    road = read_columns(tmp_path / "cli" / "road.csv")
    for j in range(3):
        np.testing.assert_array_equal(result.z[j], road[f"z_{j + 1}"])
    np.testing.assert_array_equal(result.y, read_json(tmp_path / "cli" / "summary.json")["settings"]["y_m"])
    assert (tmp_path / "py" / "road.csv").read_bytes() == (tmp_path / "cli" / "road.csv").read_bytes()
    assert (tmp_path / "py" / "texture.csv").read_bytes() == (tmp_path / "cli" / "texture.csv").read_bytes()


def test_a_measured_profile_gives_the_command_lines_analysis(tmp_path):
    run_cli("road", LASER, "--out", tmp_path / "cli")
    result = rollnoise.road(LASER)
    summary = assert_road_equal(result, tmp_path / "cli")
    assert result.summary["spikes_removed"] == summary["spikes_removed"]
    assert result.summary["dropouts_filled"] == summary["dropouts_filled"]


def test_heights_are_analysed_as_a_profile_file(tmp_path):
    # The laser profile as the command line wrote it (cleaned), given back as an array.
    run_cli("road", LASER, "--out", tmp_path / "cli")
    road = read_columns(tmp_path / "cli" / "road.csv")
    spacing = read_json(tmp_path / "cli" / "summary.json")["settings"]["spacing_m"]
    result = rollnoise.road(road["z"], spacing=spacing)
    assert result.summary["spikes_removed"] == 0 and result.summary["dropouts_filled"] == 0
    np.testing.assert_array_equal(result.z[0], road["z"])
    texture = read_columns(tmp_path / "cli" / "texture.csv")
    np.testing.assert_allclose(result.texture["Ltx_dB"], texture["Ltx_dB"], rtol=0, atol=1e-9)
    np.testing.assert_allclose(result.mpd_m, read_json(tmp_path / "cli" / "summary.json")["mpd_m"], rtol=1e-12)


def test_a_road_dict_is_its_surface_file():
    from_file = rollnoise.road(DAC11, length=0.5)
    from_dict = rollnoise.road({"surface": str(DAC11)}, length=0.5)
    np.testing.assert_array_equal(from_dict.z, from_file.z)
    np.testing.assert_array_equal(from_dict.texture["Ltx_dB"], from_file.texture["Ltx_dB"])
    sine = rollnoise.road({"type": "sine", "amplitude": 1e-3, "wavelength": 0.05}, length=1.0)
    np.testing.assert_allclose(sine.z[0], 1e-3 * np.sin(2 * np.pi * sine.x / 0.05), atol=1e-12)


PA16 = SOURCE / "models" / "surfaces" / "pa16.toml"


def test_an_absorbing_surface_and_its_ground_effect_as_the_command_line_writes_them(tmp_path):
    run_cli("road", PA16, "--length", "0.3", "--ground-effect", "0.05,7.5,1.2", "--out", tmp_path / "cli")
    result = rollnoise.road(PA16, length=0.3, ground_effect=(0.05, 7.5, 1.2))
    absorption = read_columns(tmp_path / "cli" / "absorption.csv")
    for key in ("band_hz", "alpha", "z_re", "z_im"):
        np.testing.assert_array_equal(result.absorption[key], absorption[key])
    ground = read_columns(tmp_path / "cli" / "ground_effect.csv")
    for key in ("band_hz", "delta_dB", "delta_band_dB"):
        np.testing.assert_array_equal(result.ground_effect[key], ground[key])
    assert rollnoise.road(DAC11, length=0.3).absorption == {}  # a rigid surface
    assert rollnoise.road(DAC11, length=0.3).ground_effect == {}


def test_a_ground_effect_geometry_must_be_three_positive_lengths():
    for geometry in ((0.05, 7.5), (0.05, -7.5, 1.2)):
        try:
            rollnoise.road(PA16, length=0.3, ground_effect=geometry)
        except rollnoise.InputError as error:
            assert "ground_effect" in str(error)
        else:
            raise AssertionError(f"{geometry} was accepted")
