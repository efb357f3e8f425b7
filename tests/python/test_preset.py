"""ocean.Preset: built-in presets, files, key=value overrides, JSON and pickling round trips."""
import json
import pickle
import pytest

import ocean


def test_builtins_and_overrides():
    assert ocean.Preset.builtin_names() == ["calm", "moderate", "storm"]
    storm = json.loads(ocean.Preset("storm").to_json())
    assert storm["sea"]["wind_sea"]["model"] == "jonswap"
    p = ocean.Preset("storm").set("resolution=64").set("sea.wind_sea.wind_speed_mps=30")
    d = json.loads(p.to_json())
    assert d["resolution"] == 64 and d["sea"]["wind_sea"]["wind_speed_mps"] == 30
    assert ocean.Simulator(p.set("resolution=16")).resolution == 16


def test_save_load_and_pickle_round_trips(tmp_path):
    p = ocean.Preset("moderate").set("seed=7").set("cascades_m=[300.0, 70.0]")
    path = tmp_path / "mine.json"
    p.save(str(path))
    assert ocean.Preset(str(path)).to_json() == p.to_json()
    assert ocean.Preset.from_json(p.to_json()).to_json() == p.to_json()
    assert pickle.loads(pickle.dumps(p)).to_json() == p.to_json()
    # A file merged over a built-in replaces only the keys it holds.
    path.write_text('{"choppiness": 0.5}')
    q = ocean.Preset("storm").merge(str(path))
    assert json.loads(q.to_json())["choppiness"] == 0.5
    assert json.loads(q.to_json())["sea"] == json.loads(ocean.Preset("storm").to_json())["sea"]


def test_a_null_in_a_file_is_unset_as_in_from_json(tmp_path):
    # A Pierson-Moskowitz sea given by its wind has no fetch: saved from a dict, "fetch_m" is
    # null in the file, and loading the file must not give it the default 100 km fetch (which
    # the spectrum's check refuses for Pierson-Moskowitz).
    sea = {"model": "pierson-moskowitz", "wind_speed_mps": 12.0, "fetch_m": None}
    p = ocean.Preset.from_dict({"sea": {"wind_sea": sea, "swell": None}})
    path = tmp_path / "pm.json"
    p.save(str(path))
    assert json.loads(path.read_text())["sea"]["wind_sea"]["fetch_m"] is None
    loaded = ocean.Preset(str(path))
    assert loaded == ocean.Preset.from_json(path.read_text()) == p
    assert loaded["sea.wind_sea.fetch_m"] is None
    # Merged over a preset with a fetch and a swell, the nulls unset both.
    over = ocean.Preset("calm").merge(str(path))
    assert over["sea.wind_sea.fetch_m"] is None and over["sea.swell"] is None
    assert ocean.Simulator(over.set("resolution=16")).resolution == 16


def test_presets_compare_by_value():
    assert ocean.Preset("moderate") == ocean.Preset("moderate")
    assert ocean.Preset("moderate") != ocean.Preset("storm")
    assert ocean.Preset("calm") != "calm"
    with pytest.raises(TypeError):
        hash(ocean.Preset())  # mutable (set, merge): not hashable


def test_values_by_dotted_key():
    p = ocean.Preset("moderate")
    assert p.get("sea.wind_sea.wind_speed_mps") == 10.0
    assert p["resolution"] == json.loads(p.to_json())["resolution"]
    assert p["sea.swell"] is None
    with pytest.raises(KeyError, match="did you mean 'sea.wind_sea.wind_speed_mps'"):
        p.get("sea.wind_sea.wind_speed")
    with pytest.raises(KeyError, match="no key 'resolution.x'"):
        p.get("resolution.x")


def test_dicts_and_keywords_configure_as_set_does():
    base = ocean.Preset("moderate")
    changed = base.updated({"sea.wind_sea.wind_speed_mps": 12.5, "foam": {"source": "ramp"}},
                           resolution=64, seed=7)
    expected = ocean.Preset("moderate").set("sea.wind_sea.wind_speed_mps=12.5") \
        .set("foam.source=ramp").set("resolution=64").set("seed=7")
    assert changed == expected
    assert base == ocean.Preset("moderate")  # unchanged
    assert changed["foam.breaking_acceleration"] == base["foam.breaking_acceleration"]
    assert ocean.Preset.from_dict(changed.to_dict()) == changed
    assert ocean.Preset.from_dict({"resolution": 32}) == ocean.Preset().set("resolution=32")
    with pytest.raises(ValueError, match="resolution"):
        base.updated(resolution=-3)


@pytest.mark.parametrize("assignment, shown", [
    ("resolution=-3", "resolution = -3 is out of range"),
    ("resolution=99999999999", "resolution = 99999999999 is out of range"),
    ("far_noise.resolution=-5", "far_noise.resolution = -5 is out of range"),
    ("far_noise.resolution=99999999999", "far_noise.resolution = 99999999999 is out of range"),
])
def test_a_bad_resolution_is_named_as_given(assignment, shown):
    with pytest.raises(ValueError, match=shown):
        ocean.Preset().set(assignment)
