"""Every public function and method of the package documents itself in the numpy style: a
summary line, a "Parameters" section where it takes arguments and a "Returns" section where it
returns a value, each entry naming a real argument. The list of callables and their signatures is
the package's own stub (ocean/_ocean.pyi, written from the extension's signatures), so a new
function without them fails here."""
import ast
import inspect
import os
import re

import ocean

STUB = os.path.join(os.path.dirname(ocean.__file__), "_ocean.pyi")


def stub_callables():
    """(qualified name, object, argument names, returns a value) of each public callable."""
    with open(STUB, encoding="utf-8") as f:
        tree = ast.parse(f.read())
    found = {}

    def add(qualname, obj, node):
        args = [a.arg for a in node.args.args + node.args.kwonlyargs if a.arg != "self"]
        if node.args.vararg:
            args.append(node.args.vararg.arg)
        if node.args.kwarg:
            args.append(node.args.kwarg.arg)
        returns = node.name != "__init__" and ast.unparse(node.returns) != "None"
        old = found.get(qualname, (qualname, obj, [], False))
        found[qualname] = (qualname, obj, sorted(set(old[2]) | set(args)), old[3] or returns)

    for node in tree.body:
        if isinstance(node, ast.FunctionDef) and not node.name.startswith("_"):
            add(node.name, getattr(ocean, node.name), node)
        elif isinstance(node, ast.ClassDef):
            cls = getattr(ocean, node.name)
            for member in node.body:
                if not isinstance(member, ast.FunctionDef):
                    continue
                if member.name.startswith("_") and member.name != "__init__":
                    continue
                if any(isinstance(d, ast.Name) and d.id == "property" for d in member.decorator_list):
                    continue
                add(f"{node.name}.{member.name}", getattr(cls, member.name), member)
    # The package's own functions (ocean/__init__.py), outside the extension's stub.
    for name, fn in inspect.getmembers(ocean, inspect.isfunction):
        if fn.__module__ == "ocean" and not name.startswith("_") and name not in found:
            found[name] = (name, fn, list(inspect.signature(fn).parameters), True)
    return list(found.values())


def sections(doc):
    """The numpy-style sections of a docstring: {"Parameters": [entry names], "Returns": [...]}."""
    out = {}
    lines = doc.splitlines()
    for i, line in enumerate(lines[:-1]):
        if re.fullmatch(r"-{3,}", lines[i + 1].strip()) and line.strip() in ("Parameters",
                                                                             "Returns"):
            names = []
            for entry in lines[i + 2:]:
                if not entry.strip() or re.fullmatch(r"-{3,}", entry.strip()):
                    break
                if not entry.startswith(" ") and entry.strip() not in ("Parameters", "Returns"):
                    names.append(entry)
            out[line.strip()] = names
    return out


def test_the_stub_lists_the_package_callables():
    names = {q for q, *_ in stub_callables()}
    assert {"spectrum", "bake", "Simulator.step", "Simulator.heights", "Preset.set",
            "spectrum_hz", "Simulator.series", "Preset.updated"} <= names


def test_every_public_callable_documents_its_parameters_and_result():
    missing = []
    for qualname, obj, args, returns in stub_callables():
        doc = inspect.getdoc(obj) or ""
        found = sections(doc)
        if args and "Parameters" not in found:
            missing.append(f"{qualname}: no Parameters section")
        if returns and "Returns" not in found:
            missing.append(f"{qualname}: no Returns section")
        for entry in found.get("Parameters", []):
            # "name : type", "a, b : type" or "**keywords"
            named = [n.strip().lstrip("*") for n in entry.split(":")[0].split(",")]
            for n in named:
                if n not in args:
                    missing.append(f"{qualname}: Parameters names '{n}', not an argument")
    assert not missing, "\n".join(missing)


def test_every_public_property_says_what_it_is():
    for cls in (ocean.Simulator, ocean.SeaState):
        for name, member in vars(cls).items():
            if isinstance(member, property) and not name.startswith("_"):
                assert (member.__doc__ or "").strip(), f"{cls.__name__}.{name}"
