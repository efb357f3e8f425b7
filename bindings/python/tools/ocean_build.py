"""The build backend of `pip install .` (PEP 517, pyproject.toml at the repository's root).

It needs nothing beyond the standard library, so pip's isolated build environment installs
nothing and no package index is asked: CMake (with Debian's compilers, pybind11-dev, python3-dev
and python3-numpy, which ./dev installs) builds the extension for the interpreter that runs pip,
and the wheel is written here with zipfile.

- The build folder is build/pip (configured for the Python package alone: no tool, tests or
  benchmarks; minutes on two cores the first time, then only what changed), or the configured
  build folder named by the environment variable OCEAN_BUILD_DIR (e.g. build/release).
- The wheel holds the package ocean/ (the extension, its .pyi stubs, py.typed and the Python
  modules) and its .dist-info; its version is the project's (CMakeLists.txt).
"""

import base64
import csv
import hashlib
import io
import os
import re
import subprocess
import sys
import sysconfig
import zipfile

_ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..", ".."))
_NAME = "ocean"
_SUMMARY = "Real-time spectral ocean surface simulation"


def _version():
    with open(os.path.join(_ROOT, "CMakeLists.txt"), encoding="utf-8") as f:
        match = re.search(r"project\(ocean VERSION ([0-9.]+)", f.read())
    if match is None:
        raise RuntimeError("ocean build: no 'project(ocean VERSION x.y.z' in CMakeLists.txt")
    return match.group(1)


def _tag():
    """cp311-cp311-linux_x86_64 for the interpreter running the build."""
    impl = "cp%d%d" % sys.version_info[:2]
    platform = sysconfig.get_platform().replace("-", "_").replace(".", "_")
    return "%s-%s-%s" % (impl, impl + sys.abiflags, platform)


def _say(text):
    print("ocean build: " + text, file=sys.stderr, flush=True)


# What pip's isolated build environment sets for the interpreter it runs: CMake's checks of Debian's
# interpreter (numpy, pybind11) must see that interpreter as it is.
_PIP_ISOLATION = ("PYTHONPATH", "PYTHONNOUSERSITE", "PYTHONHOME", "PYTHONSTARTUP")


def _run(command):
    _say(" ".join(command))
    env = {k: v for k, v in os.environ.items() if k not in _PIP_ISOLATION}
    result = subprocess.run(command, cwd=_ROOT, env=env)
    if result.returncode != 0:
        raise RuntimeError("ocean build: '%s' failed (exit %d)" % (" ".join(command), result.returncode))


def _build_package():
    """Builds the extension and its stubs; returns the folder holding the package ocean/."""
    build = os.environ.get("OCEAN_BUILD_DIR")
    if build:
        build = os.path.abspath(build)
        if not os.path.isfile(os.path.join(build, "CMakeCache.txt")):
            raise RuntimeError("ocean build: OCEAN_BUILD_DIR = '%s' is not a configured build folder" % build)
    else:
        build = os.path.join(_ROOT, "build", "pip")
        _say("configuring %s for %s (the first build takes minutes)" % (build, sys.executable))
        _run(["cmake", "-S", _ROOT, "-B", build, "-G", "Ninja", "-DCMAKE_BUILD_TYPE=Release",
              "-DOCEAN_BUILD_TESTS=OFF", "-DOCEAN_BUILD_BENCH=OFF", "-DOCEAN_BUILD_APPS=OFF",
              "-DPython3_EXECUTABLE=" + sys.executable])
    _run(["cmake", "--build", build, "--target", "ocean_python", "ocean_python_stubs"])
    package = os.path.join(build, "python", _NAME)
    if not os.path.isfile(os.path.join(package, "__init__.py")):
        raise RuntimeError("ocean build: %s holds no package (is the Python package enabled? "
                           "CMake says why not)" % package)
    return os.path.dirname(package)


def _metadata(version):
    return ("Metadata-Version: 2.1\nName: %s\nVersion: %s\nSummary: %s\nRequires-Python: >=3.9\n"
            "Requires-Dist: numpy\n" % (_NAME, version, _SUMMARY))


def _record_line(path, data):
    digest = base64.urlsafe_b64encode(hashlib.sha256(data).digest()).rstrip(b"=").decode()
    return [path, "sha256=" + digest, str(len(data))]


def _write_wheel(wheel_directory, tree, version, tag):
    dist_info = "%s-%s.dist-info" % (_NAME, version)
    name = "%s-%s-%s.whl" % (_NAME, version, tag)
    files = []
    for folder, _, names in os.walk(os.path.join(tree, _NAME)):
        for file_name in sorted(names):
            if file_name.endswith(".pyc") or file_name == "__pycache__":
                continue
            full = os.path.join(folder, file_name)
            files.append((os.path.relpath(full, tree).replace(os.sep, "/"), full))
    files.sort()
    generated = [
        (dist_info + "/METADATA", _metadata(version).encode()),
        (dist_info + "/WHEEL", ("Wheel-Version: 1.0\nGenerator: ocean_build\nRoot-Is-Purelib: false\n"
                                "Tag: %s\n" % tag).encode()),
        (dist_info + "/top_level.txt", (_NAME + "\n").encode()),
    ]
    record = io.StringIO()
    writer = csv.writer(record, lineterminator="\n")
    target = os.path.join(wheel_directory, name)
    partial = target + ".partial"
    try:
        with zipfile.ZipFile(partial, "w", compression=zipfile.ZIP_DEFLATED) as wheel:
            for arcname, full in files:
                with open(full, "rb") as f:
                    data = f.read()
                wheel.writestr(arcname, data)
                writer.writerow(_record_line(arcname, data))
            for arcname, data in generated:
                wheel.writestr(arcname, data)
                writer.writerow(_record_line(arcname, data))
            writer.writerow([dist_info + "/RECORD", "", ""])
            wheel.writestr(dist_info + "/RECORD", record.getvalue())
        os.replace(partial, target)  # whole or not at all
    finally:
        if os.path.exists(partial):
            os.remove(partial)
    _say("wrote %s (%d files)" % (target, len(files) + len(generated) + 1))
    return name


# PEP 517 hooks.
def get_requires_for_build_wheel(config_settings=None):
    return []


def build_wheel(wheel_directory, config_settings=None, metadata_directory=None):
    version = _version()
    tree = _build_package()
    return _write_wheel(wheel_directory, tree, version, _tag())
