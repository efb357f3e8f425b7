"""Bakes spread over a Dask cluster: each worker bakes one shard (ocean.bake with shard='I/N'),
then ocean.merge joins the shard folders into a folder byte for byte the one-machine bake.

    from distributed import Client, LocalCluster
    import ocean, ocean.shards
    with LocalCluster(n_workers=2) as cluster, Client(cluster) as client:
        ocean.shards.bake_on_dask(client, ocean.Preset("storm"), "out", frames=240, shards=8)

Every worker must import the same `ocean` package (the same build) and see the same file system
as the merge (a shared folder on a farm). Shards are frame blocks (src/bake/README.md): shard i of
n steps through the frames before its block so that foam accumulates as on one machine.
For Slurm job arrays, which need no Python on the head node, see src/bake/README.md.
"""
import os

import ocean


def shard_dirs(root, count):
    """The folder of each shard of `count` under `root`: root/shard-0000-of-0008, ..."""
    return [os.path.join(root, f"shard-{i:04d}-of-{count:04d}") for i in range(count)]


def bake_shard(preset, folder, index, count, frames, fps=30.0, time=0.0, formats=("npy",),
               backend="cpu"):
    """Bakes shard index of count into folder (what one worker runs); returns the folder."""
    ocean.bake(preset, folder, frames=frames, fps=fps, time=time, formats=list(formats),
               backend=backend, shard=f"{index}/{count}")
    return folder


def bake_on_dask(client, preset, out, *, frames, shards, fps=30.0, time=0.0, formats=("npy",),
                 backend="cpu", shard_root=None):
    """Bakes `frames` frames of `preset` (an ocean.Preset, picklable) as `shards` shards on the
    workers of a dask.distributed `client`, into shard_root (default out + '.shards'), then
    merges them into `out`. Raises the first shard's error (as ocean.bake raises it) or the
    merge's. Returns the list of shard folders (kept: delete them once the merge is checked)."""
    if not 1 <= shards <= frames:
        raise ValueError(f"shards = {shards} must be 1 to frames = {frames}")
    folders = shard_dirs(shard_root or os.fspath(out) + ".shards", shards)
    futures = client.map(bake_shard, [preset] * shards, folders, range(shards),
                         [shards] * shards, frames=frames, fps=fps, time=time,
                         formats=tuple(formats), backend=backend, pure=False)
    client.gather(futures)
    ocean.merge(folders, out)
    return folders
