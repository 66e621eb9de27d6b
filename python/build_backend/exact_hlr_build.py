"""The build backend of `pip install .` and `python3 -m build` (PEP 517), in the tree.

It drives the project's CMake build and packs the Python package it lays out
(BUILD/python/exact_hlr: the compiled module _core, __init__.py, the type stubs) and the `hlr`
program into a wheel. It needs nothing but the standard library, so a machine with Debian's
packages and no package index installs it (pip's isolated build environment is empty).

Settings (pip --config-settings KEY=VALUE, build -C KEY=VALUE):
  build-dir=PATH   a CMake build folder to use; an existing one is only brought up to date
                   (default: build/, the README's commands' Release build, when it is there;
                   else build-wheel/ in the source tree, configured Release without tests)
  jobs=N           parallel compile jobs (default: every core)
"""
from __future__ import annotations

import base64
import csv
import hashlib
import io
import os
import re
import subprocess
import sys
import sysconfig
import tarfile
import tomllib
import zipfile

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))


def _project():
    with open(os.path.join(ROOT, "pyproject.toml"), "rb") as f:
        return tomllib.load(f)["project"]


def _version():
    """The version of CMakeLists.txt's project(): the same as `hlr --version`."""
    text = open(os.path.join(ROOT, "CMakeLists.txt"), encoding="utf-8").read()
    return re.search(r"project\(\s*\w+\s+VERSION\s+([0-9.]+)", text).group(1)


def _tag():
    impl = "cp" + "".join(map(str, sys.version_info[:2]))
    return f"{impl}-{impl}-" + sysconfig.get_platform().replace("-", "_").replace(".", "_")


def _dist_name():
    return _project()["name"].replace("-", "_")


def _metadata():
    p = _project()
    lines = ["Metadata-Version: 2.1", f"Name: {p['name']}", f"Version: {_version()}", f"Summary: {p['description']}",
             f"Requires-Python: {p['requires-python']}"]
    for dep in p.get("dependencies", []):
        lines.append(f"Requires-Dist: {dep}")
    for name, url in p.get("urls", {}).items():
        lines.append(f"Project-URL: {name}, {url}")
    lines.append("Description-Content-Type: text/markdown")
    readme = open(os.path.join(ROOT, p["readme"]), encoding="utf-8").read()
    return "\n".join(lines) + "\n\n" + readme


def _setting(config_settings, key, default=None):
    value = (config_settings or {}).get(key, default)
    return value[-1] if isinstance(value, list) else value


def _build(config_settings):
    build = _setting(config_settings, "build-dir")
    if not build:
        readme_build = os.path.join(ROOT, "build")
        release = os.path.exists(os.path.join(readme_build, "CMakeCache.txt")) and \
            "CMAKE_BUILD_TYPE:STRING=Release" in open(os.path.join(readme_build, "CMakeCache.txt")).read()
        build = readme_build if release else os.path.join(ROOT, "build-wheel")
    build = os.path.abspath(build)
    jobs = str(_setting(config_settings, "jobs") or os.cpu_count() or 2)
    if not os.path.exists(os.path.join(build, "CMakeCache.txt")):
        subprocess.run(["cmake", "-S", ROOT, "-B", build, "-DCMAKE_BUILD_TYPE=Release", "-DHLR_BUILD_TESTS=OFF",
                        "-DHLR_BUILD_BENCHMARKS=OFF", "-DHLR_BUILD_PYTHON=ON"], check=True, stdout=sys.stderr)
    subprocess.run(["cmake", "--build", build, "-j", jobs, "--target", "_core", "hlr"], check=True, stdout=sys.stderr)
    package = os.path.join(build, "python", "exact_hlr")
    if not any(f.startswith("_core") for f in os.listdir(package)):
        raise RuntimeError(f"no compiled module in {package}: is pybind11 installed (python3-pybind11)?")
    return build, package


def _record_line(name, data):
    digest = base64.urlsafe_b64encode(hashlib.sha256(data).digest()).rstrip(b"=").decode()
    return [name, f"sha256={digest}", str(len(data))]


def _dist_info(dist, tag):
    wheel = f"Wheel-Version: 1.0\nGenerator: exact_hlr_build\nRoot-Is-Purelib: false\nTag: {tag}\n"
    return {f"{dist}.dist-info/METADATA": _metadata().encode(), f"{dist}.dist-info/WHEEL": wheel.encode(),
            f"{dist}.dist-info/top_level.txt": b"exact_hlr\n"}


def get_requires_for_build_wheel(config_settings=None):
    return []


def get_requires_for_build_sdist(config_settings=None):
    return []


def prepare_metadata_for_build_wheel(metadata_directory, config_settings=None):
    dist = f"{_dist_name()}-{_version()}"
    for name, data in _dist_info(dist, _tag()).items():
        path = os.path.join(metadata_directory, name)
        os.makedirs(os.path.dirname(path), exist_ok=True)
        with open(path, "wb") as f:
            f.write(data)
    return f"{dist}.dist-info"


def build_wheel(wheel_directory, config_settings=None, metadata_directory=None):
    build, package = _build(config_settings)
    dist, tag = f"{_dist_name()}-{_version()}", _tag()
    files = {}
    for name in sorted(os.listdir(package)):
        if name.endswith((".py", ".pyi", ".so")) or name == "py.typed":
            files[f"exact_hlr/{name}"] = open(os.path.join(package, name), "rb").read()
    files[f"{dist}.data/scripts/hlr"] = open(os.path.join(build, "hlr"), "rb").read()
    files.update(_dist_info(dist, tag))
    record_name = f"{dist}.dist-info/RECORD"
    rows = [_record_line(n, d) for n, d in files.items()] + [[record_name, "", ""]]
    out = io.StringIO()
    csv.writer(out, lineterminator="\n").writerows(rows)
    files[record_name] = out.getvalue().encode()
    wheel_name = f"{dist}-{tag}.whl"
    with zipfile.ZipFile(os.path.join(wheel_directory, wheel_name), "w", zipfile.ZIP_DEFLATED) as z:
        for name, data in files.items():
            info = zipfile.ZipInfo(name, date_time=(2020, 1, 1, 0, 0, 0))
            info.external_attr = (0o100755 if name.endswith("/hlr") or name.endswith(".so") else 0o100644) << 16  # regular files
            info.compress_type = zipfile.ZIP_DEFLATED
            z.writestr(info, data)
    return wheel_name


def build_sdist(sdist_directory, config_settings=None):
    """The tracked source files (git ls-files) as NAME-VERSION.tar.gz."""
    dist = f"{_dist_name()}-{_version()}"
    names = subprocess.run(["git", "-C", ROOT, "ls-files", "-z"], check=True, capture_output=True).stdout.decode().split("\0")
    path = os.path.join(sdist_directory, f"{dist}.tar.gz")
    with tarfile.open(path, "w:gz") as t:
        for n in filter(None, names):
            if os.path.isfile(os.path.join(ROOT, n)):
                t.add(os.path.join(ROOT, n), arcname=f"{dist}/{n}")
        meta = _metadata().encode()
        info = tarfile.TarInfo(f"{dist}/PKG-INFO")
        info.size = len(meta)
        t.addfile(info, io.BytesIO(meta))
    return os.path.basename(path)
