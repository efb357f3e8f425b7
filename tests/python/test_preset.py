"""ocean.Preset: built-in presets, files, key=value overrides, JSON and pickling round trips."""
import json
import pickle

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
