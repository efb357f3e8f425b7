"""ocean: spectral ocean surface simulation (the C++ library, wrapped with pybind11).

Spectra, spreading and dispersion vectorised over numpy arrays, presets, the simulator with its
fields as numpy views, batched height queries, surface statistics and bakes. Errors raise the
exception of the library's status with the one-line message the `ocean` tool prints:
ValueError (bad input), OSError (files), NotImplementedError (not built in), in Python's names
(`hs = -1 is out of range: ...`). docs/python.md.
"""
import difflib as _difflib
import functools as _functools
import re as _re

from ._ocean import __version__  # noqa: F401
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


# A call the extension cannot match (a misspelt keyword, a value of the wrong type) raises
# pybind11's TypeError, which lists every overload with its full types. It becomes one line
# naming what was wrong.
def _keywords(function):
    """The keyword names in the signatures of a pybind11 function's docstring."""
    names = []
    for line in (function.__doc__ or "").splitlines():
        m = _re.match(r"^(?:\d+\. )?\w+\((.*)\)", line)
        if m:
            names += [n for n in _re.findall(r"(?:^|, )\*?(\w+):", m.group(1))
                      if n != "self" and n not in names]
    return names


def _short_type_error(function, name):
    @_functools.wraps(function)
    def call(*args, **kwargs):
        try:
            return function(*args, **kwargs)
        except TypeError as e:
            if "incompatible function arguments" not in str(e) and \
                    "incompatible constructor arguments" not in str(e):
                raise
            known = _keywords(function)
            for k in kwargs:
                if k not in known:
                    close = _difflib.get_close_matches(k, known, n=1)
                    hint = f"; did you mean '{close[0]}'?" if close else ""
                    raise TypeError(f"{name}() got an unexpected keyword argument '{k}'{hint} "
                                    f"(keywords: {', '.join(known)})") from None
            given = ", ".join([type(a).__name__ for a in args] +
                              [f"{k}={type(v).__name__}" for k, v in kwargs.items()])
            raise TypeError(f"{name}(): arguments of the wrong type ({given}); "
                            f"help(ocean.{name}) shows the types") from None
    return call


for _name in ("bake", "depth_factor", "dispersion", "merge", "shard_frames", "spectrum",
              "spectrum_info", "spreading", "surface_stats"):
    globals()[_name] = _short_type_error(globals()[_name], _name)
for _cls in (Preset, SeaState, Simulator):
    for _attr, _member in list(vars(_cls).items()):
        if callable(_member) and (_attr == "__init__" or not _attr.startswith("_")) and \
                type(_member).__name__ == "instancemethod":
            setattr(_cls, _attr, _short_type_error(_member, f"{_cls.__name__}.{_attr}"
                                                   if _attr != "__init__" else _cls.__name__))
del _name, _cls, _attr, _member
