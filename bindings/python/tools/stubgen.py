"""Writes the type stubs of the extension, ocean/_ocean.pyi, from its own signatures.

pybind11 puts each function's signature, with its types and defaults, on the first line of its
docstring (one numbered line per overload); this turns them into a stub that type checkers and
editors read: every function, class, method, property and constant of ocean._ocean, with the
methods the pure-Python package adds to its classes (Simulator.series). Defaults become `...`,
numpy arrays numpy.typing.NDArray. Run by the build after the module links:

    python3 stubgen.py PACKAGE_PARENT_DIR OUT.pyi
"""
import inspect
import re
import sys

HEADER = """# Type stubs of the extension ocean._ocean, generated from its signatures by
# bindings/python/tools/stubgen.py when the module is built: do not edit.
import os
from typing import Any, Dict, List, Optional, Tuple, Union, overload

import numpy
import numpy.typing

"""


def split_args(text):
    """The comma-separated parts of an argument list, commas inside brackets or quotes kept."""
    parts, depth, quote, start = [], 0, None, 0
    for i, ch in enumerate(text):
        if quote:
            quote = None if ch == quote else quote
        elif ch in "'\"":
            quote = ch
        elif ch in "([{":
            depth += 1
        elif ch in ")]}":
            depth -= 1
        elif ch == "," and depth == 0:
            parts.append(text[start:i].strip())
            start = i + 1
    if text[start:].strip():
        parts.append(text[start:].strip())
    return parts


def clean_type(t, argument=False):
    """A pybind11 type as a stub's: arrays an argument takes are anything numpy converts
    (ArrayLike: the extension converts lists and other dtypes, a copy), arrays it returns
    NDArray of their dtype."""
    t = t.replace("ocean._ocean.", "")
    t = re.sub(r"numpy\.ndarray\[([\w.]+)\]",
               "numpy.typing.ArrayLike" if argument else r"numpy.typing.NDArray[\1]", t)
    return t.strip()


def stub_args(args, method):
    out = []
    for i, arg in enumerate(split_args(args)):
        if arg in ("*", "/") or arg.startswith("*"):
            out.append(arg)
            continue
        name, _, rest = arg.partition(":")
        name = name.strip()
        annotation, eq, _default = rest.partition("=")
        if method and i == 0:
            out.append("self")
            continue
        piece = f"{name}: {clean_type(annotation, True)}" if annotation.strip() else name
        out.append(piece + (" = ..." if eq else ""))
    return ", ".join(out)


def signatures(doc, name):
    """(args, return type) of each signature line of a pybind11 docstring."""
    found = []
    for line in (doc or "").splitlines():
        m = re.match(rf"^(?:\d+\. )?{re.escape(name)}\((.*)\) -> (.+)$", line.strip())
        if m:
            found.append((m.group(1), m.group(2)))
    return found


def first_paragraph(doc):
    lines = [line for line in (doc or "").splitlines()]
    body = [line for line in lines if line.strip() and not re.match(r"^(\d+\. )?\w+\(.*\) ->", line)
            and line.strip() != "Overloaded function."]
    return body[0].strip() if body else ""


def emit_function(lines, obj, name, indent, method):
    sigs = signatures(obj.__doc__, name)
    if not sigs:
        return False
    summary = first_paragraph(obj.__doc__)
    for args, ret in sigs:
        if len(sigs) > 1:
            lines.append(f"{indent}@overload")
        ret = "None" if name == "__init__" else clean_type(ret)
        lines.append(f"{indent}def {name}({stub_args(args, method)}) -> {ret}:")
        if summary and len(sigs) == 1:
            lines.append(f"{indent}    {summary!r}")
        lines.append(f"{indent}    ...")
    return True


def emit_python_method(lines, fn, name, indent):
    """A method the pure-Python package adds: its signature from inspect."""
    sig = inspect.signature(fn)
    params, starred = [], False
    for p in sig.parameters.values():
        if p.kind == inspect.Parameter.VAR_POSITIONAL:
            params.append("*" + p.name)
            starred = True
        elif p.kind == inspect.Parameter.VAR_KEYWORD:
            params.append("**" + p.name)
        else:
            if p.kind == inspect.Parameter.KEYWORD_ONLY and not starred:
                params.append("*")
                starred = True
            params.append(p.name + (" = ..." if p.default is not inspect.Parameter.empty else ""))
    doc = (fn.__doc__ or "").strip().splitlines()
    lines.append(f"{indent}def {name}({', '.join(params)}) -> Any:")
    if doc:
        lines.append(f"{indent}    {doc[0].strip()!r}")
    lines.append(f"{indent}    ...")


def main(parent, out_path):
    sys.path.insert(0, parent)
    import ocean  # the package: its additions to the extension's classes included
    module = ocean._ocean
    lines = [HEADER]
    lines.append(f"__version__: str")
    for name in sorted(dir(module)):
        if name.startswith("_"):
            continue
        obj = getattr(module, name)
        if isinstance(obj, (int, float, str)):
            lines.append(f"{name}: {type(obj).__name__}")
    lines.append("")
    for name in sorted(dir(module)):
        obj = getattr(module, name)
        if name.startswith("_") or not inspect.isclass(obj):
            continue
        lines.append(f"class {name}:")
        if obj.__doc__:
            lines.append(f"    {obj.__doc__.strip().splitlines()[0]!r}")
        members = 0
        for attr, member in sorted(vars(obj).items()):
            if attr.startswith("_") and attr not in ("__init__", "__eq__", "__getitem__",
                                                     "__getstate__", "__setstate__"):
                continue
            if isinstance(member, staticmethod):
                fn = member.__func__
                lines.append("    @staticmethod")
                if type(fn).__name__ == "function" and not hasattr(fn, "__wrapped__"):
                    emit_python_method(lines, fn, attr, "    ")
                elif not emit_function(lines, getattr(fn, "__wrapped__", fn), attr, "    ",
                                       False):
                    raise SystemExit(f"stubgen: no signature in the docstring of {name}.{attr}")
                members += 1
            elif isinstance(member, property):
                ret = "Any"
                sig = re.match(r"^\(.*\) -> (.+)$", (member.fget.__doc__ or "").splitlines()[0]
                               if member.fget and member.fget.__doc__ else "")
                if sig:
                    ret = clean_type(sig.group(1))
                lines += ["    @property", f"    def {attr}(self) -> {ret}: ..."]
                members += 1
            elif callable(member) and (hasattr(member, "__wrapped__") or
                                       type(member).__name__ != "function"):
                # the extension's (possibly under the package's one-line TypeError wrapper)
                target = getattr(member, "__wrapped__", member)
                if emit_function(lines, target, attr, "    ", True):
                    members += 1
            elif type(member).__name__ == "function":
                emit_python_method(lines, member, attr, "    ")
                members += 1
        if members == 0:
            lines.append("    ...")
        lines.append("")
    for name in sorted(dir(module)):
        obj = getattr(module, name)
        if name.startswith("_") or inspect.isclass(obj) or not callable(obj):
            continue
        if not emit_function(lines, getattr(obj, "__wrapped__", obj), name, "", False):
            raise SystemExit(f"stubgen: no signature in the docstring of {name}")
        lines.append("")
    with open(out_path, "w", encoding="utf-8") as f:
        f.write("\n".join(lines).rstrip() + "\n")


if __name__ == "__main__":
    if len(sys.argv) != 3:
        raise SystemExit("usage: stubgen.py PACKAGE_PARENT_DIR OUT.pyi")
    main(sys.argv[1], sys.argv[2])
