"""ocean: spectral ocean surface simulation (the C++ library, wrapped with pybind11).

Spectra, spreading and dispersion vectorised over numpy arrays, presets, the simulator with its
fields as numpy views, batched height queries, surface statistics and bakes. Errors raise the
exception of the library's status with the one-line message the `ocean` tool prints:
ValueError (bad input), OSError (files), NotImplementedError (not built in), in Python's names
(`hs = -1 is out of range: ...`). docs/python.md.
"""
import difflib as _difflib
import functools as _functools
import json as _json
import math as _math
import re as _re

import numpy as _np

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
    "spectrum", "spectrum_hz", "spectrum_info", "spreading", "surface_stats",
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


def spectrum_hz(model, f, **parameters):
    """The frequency spectrum S(f) in m²/Hz at frequencies f in Hz.

    The same spectrum as ``spectrum(model, omega=2*pi*f, ...)``, expressed per hertz:
    S(f) = 2·π·S(ω) with ω = 2·π·f, so that the integral of S(f) df is the same variance m0.

    Parameters
    ----------
    model : str
        A spectrum model, as for ``spectrum`` (pierson-moskowitz, jonswap, tma, phillips).
    f : array_like of float
        Frequencies, Hz, any shape; finite and non-negative.
    **parameters
        The keywords of ``spectrum`` (hs=, tp=, wind_speed=, fetch=, gamma=, depth=, ...).

    Returns
    -------
    numpy.ndarray
        S(f), m²/Hz, shaped like ``f``.
    """
    f = _np.asarray(f, dtype=float)
    if not _np.all(_np.isfinite(f)) or _np.any(f < 0):
        raise ValueError("f must be finite and >= 0 (Hz)")
    return 2.0 * _math.pi * spectrum(model, omega=2.0 * _math.pi * f, **parameters)


def _series(self, points, times, as_xarray=False):
    """Heights at fixed points over a sequence of times: a wave-gauge record.

    Steps this simulator to each time in turn (``step(t)``) and queries the heights at every
    point after each step (``heights``, the GIL released); the simulator is left at
    ``times[-1]``. Cost: one step and one batched query per time.

    Parameters
    ----------
    points : array_like of float, shape (P, 2)
        World positions (x, z), m.
    times : array_like of float, shape (T,)
        Simulation times, s, finite and non-negative.
    as_xarray : bool, optional
        Return an ``xarray.DataArray`` with dimensions ("time", "point") and coordinates
        time (s), x and z (m) instead of an array; ImportError where xarray is not installed
        (Debian: python3-xarray).

    Returns
    -------
    numpy.ndarray, shape (T, P)
        The surface height above the mean level, m, at each time (row) and point (column).
    """
    xz = _np.asarray(points, dtype=float)
    if xz.ndim != 2 or xz.shape[1] != 2:
        raise ValueError(f"points must be an (n, 2) array of (x, z), not shape {xz.shape}")
    t = _np.asarray(times, dtype=float)
    if t.ndim != 1 or t.size == 0:
        raise ValueError(f"times must be a non-empty 1-D array, not shape {t.shape}")
    if not _np.all(_np.isfinite(t)) or _np.any(t < 0):
        raise ValueError("times must be finite and >= 0 (s)")
    if not _np.all(_np.isfinite(xz)):
        raise ValueError("points must be finite (m)")
    if as_xarray:
        import xarray  # noqa: F401  (fails before any stepping where it is missing)
    out = _np.empty((t.size, xz.shape[0]))
    for i, ti in enumerate(t):
        self.step(float(ti))
        out[i] = self.heights(xz)
    if not as_xarray:
        return out
    import xarray
    return xarray.DataArray(
        out, dims=("time", "point"),
        coords={"time": ("time", t, {"units": "s"}), "x": ("point", xz[:, 0], {"units": "m"}),
                "z": ("point", xz[:, 1], {"units": "m"})},
        name="height", attrs={"units": "m", "long_name": "surface height above the mean level"})


Simulator.series = _series
del _series


# Presets as Python values: equality, getters by dotted key, dicts and keyword updates. Each
# builds on the preset document (Preset.to_json / Preset.from_json), so a value means what the
# same key means in a preset file and is validated by the library the same way.
def _preset_eq(self, other):
    if not isinstance(other, Preset):
        return NotImplemented
    return self.to_json() == other.to_json()


def _preset_to_dict(self):
    """The preset document as nested dicts.

    Returns
    -------
    dict
        The JSON of ``to_json``, every key.
    """
    return _json.loads(self.to_json())


def _preset_from_dict(document):
    """A preset from a (possibly partial) preset document given as nested dicts.

    Parameters
    ----------
    document : dict
        Keys of the preset document, merged over the defaults as ``Preset.from_json`` merges its
        text.

    Returns
    -------
    Preset
        The preset; ValueError for an invalid configuration.
    """
    return Preset.from_json(_json.dumps(document))


def _preset_get(self, key):
    """The value at a dotted key, e.g. ``p.get("sea.wind_sea.wind_speed_mps")``.

    Parameters
    ----------
    key : str
        Keys of the preset document joined by dots.

    Returns
    -------
    float, int, str, bool, list, dict or None
        The value as the document holds it.
    """
    value = self.to_dict()
    walked = []
    for part in key.split("."):
        if not isinstance(value, dict) or part not in value:
            known = list(value) if isinstance(value, dict) else []
            close = _difflib.get_close_matches(part, known, n=1)
            hint = f"; did you mean '{'.'.join(walked + [close[0]])}'?" if close else ""
            raise KeyError(f"the preset has no key '{key}'{hint}")
        walked.append(part)
        value = value[part]
    return value


def _nested(changes):
    """{"a.b": 1, "c": {"d": 2}} as {"a": {"b": 1}, "c": {"d": 2}}."""
    out = {}
    for key, value in changes.items():
        parts = key.split(".")
        node = out
        for part in parts[:-1]:
            node = node.setdefault(part, {})
        if isinstance(value, dict) and isinstance(node.get(parts[-1]), dict):
            _merge_into(node[parts[-1]], _nested(value))
        else:
            node[parts[-1]] = _nested(value) if isinstance(value, dict) else value
    return out


def _merge_into(base, changes):
    for key, value in changes.items():
        if isinstance(value, dict) and isinstance(base.get(key), dict):
            _merge_into(base[key], value)
        else:
            base[key] = value
    return base


def _preset_updated(self, changes=None, **keywords):
    """A new preset: this one with some values changed; this one stays as it is.

    Parameters
    ----------
    changes : dict, optional
        Values by dotted key or as nested dicts, e.g. ``{"sea.wind_sea.wind_speed_mps": 12}``
        or ``{"foam": {"source": "ramp"}}``.
    **keywords
        Top-level keys, e.g. ``resolution=128, seed=3``.

    Returns
    -------
    Preset
        The changed preset, validated as a whole (ValueError names the first bad value).
    """
    merged = dict(changes or {})
    merged.update(keywords)
    return Preset.from_dict(_merge_into(self.to_dict(), _nested(merged)))


Preset.__eq__ = _preset_eq
Preset.__hash__ = None
Preset.to_dict = _preset_to_dict
Preset.from_dict = staticmethod(_preset_from_dict)
Preset.get = _preset_get
Preset.__getitem__ = _preset_get
Preset.updated = _preset_updated
del _preset_eq, _preset_to_dict, _preset_from_dict, _preset_get, _preset_updated
