"""ocean: spectral ocean surface simulation (the C++ library, wrapped with pybind11).

Spectra, spreading and dispersion vectorised over numpy arrays, presets, the simulator with its
fields as numpy views, batched height queries, surface statistics and bakes. Errors raise the
exception of the library's status with the one-line message the `ocean` tool prints:
ValueError (bad input), OSError (files), NotImplementedError (not built in). docs/python.md.
"""
from ._ocean import (  # noqa: F401
    FrameView,
    Preset,
    SeaState,
    Simulator,
    bake,
    depth_factor,
    dispersion,
    merge,
    shard_frames,
    spectrum,
    spectrum_info,
    spreading,
    surface_stats,
)

__all__ = [
    "Preset", "SeaState", "Simulator", "bake", "depth_factor", "dispersion", "merge", "shard_frames",
    "spectrum", "spectrum_info", "spreading", "surface_stats",
]
