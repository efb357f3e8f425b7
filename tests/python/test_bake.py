"""ocean.bake / ocean.merge / ocean.shards: shards joined by merge, in-process and over a Dask
LocalCluster of 2 workers, are byte for byte the one-machine bake; a missing shard is named."""
import filecmp
import os

import pytest

import ocean
import ocean.shards

FRAMES = 5


def tree(folder):
    """Every file under folder, relative, sorted."""
    return sorted(os.path.relpath(os.path.join(d, f), folder)
                  for d, _, files in os.walk(folder) for f in files)


def assert_same_bake(a, b):
    files = tree(a)
    assert files == tree(b)
    assert "manifest.json" in files and len(files) > FRAMES
    _, mismatch, errors = filecmp.cmpfiles(a, b, files, shallow=False)
    assert mismatch == [] and errors == []


@pytest.fixture
def preset(storm_16):
    return storm_16


@pytest.fixture
def one_machine(tmp_path, preset):
    out = tmp_path / "whole"
    ocean.bake(preset, out, frames=FRAMES, fps=10.0, formats=["npy", "png"])
    return out


def test_shard_frames_cover_the_bake():
    blocks = [ocean.shard_frames(FRAMES, i, 3) for i in range(3)]
    assert blocks[0][0] == 0 and blocks[-1][1] == FRAMES
    assert all(a[1] == b[0] for a, b in zip(blocks, blocks[1:]))


def test_shards_merged_in_process(tmp_path, preset, one_machine):
    dirs = [tmp_path / f"s{i}" for i in range(3)]
    for i, d in enumerate(dirs):
        ocean.bake(preset, d, frames=FRAMES, fps=10.0, formats=["npy", "png"], shard=f"{i}/3")
    with pytest.raises(ValueError, match=r"shard 1 of 3 is missing \(frames 1 to 2;"):
        ocean.merge([dirs[0], dirs[2]], tmp_path / "partial")
    ocean.merge(dirs, tmp_path / "merged")
    assert_same_bake(one_machine, tmp_path / "merged")


def test_shards_on_a_dask_local_cluster(tmp_path, preset, one_machine):
    distributed = pytest.importorskip("distributed")
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=None) as cluster, \
            distributed.Client(cluster) as client:
        folders = ocean.shards.bake_on_dask(client, preset, tmp_path / "dask", frames=FRAMES,
                                            shards=4, fps=10.0, formats=("npy", "png"))
        # Both workers took part.
        assert len(client.scheduler_info()["workers"]) == 2
    assert len(folders) == 4
    assert_same_bake(one_machine, tmp_path / "dask")
