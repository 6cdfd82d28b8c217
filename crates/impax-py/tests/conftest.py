"""Shared fixtures: the `impax` command-line tool (built by cargo) to compare against."""

from __future__ import annotations

import json
import os
import pathlib
import shutil
import subprocess

import numpy as np
import pytest

ROOT = pathlib.Path(__file__).resolve().parents[3]


def _find_cli() -> str:
    env = os.environ.get("IMPAX_BIN")
    if env:
        return env
    dirs = []
    if os.environ.get("CARGO_TARGET_DIR"):
        dirs.append(pathlib.Path(os.environ["CARGO_TARGET_DIR"]))
    dirs.append(ROOT / "target")
    for d in dirs:
        for profile in ("release", "debug"):
            p = d / profile / "impax"
            if p.exists():
                return str(p)
    found = shutil.which("impax")
    if found:
        return found
    raise RuntimeError(
        "the `impax` binary was not found: build it (`cargo build --bin impax`) or set IMPAX_BIN"
    )


class Cli:
    """Runs the `impax` binary."""

    def __init__(self, path: str):
        self.path = path

    def run(self, *args: str) -> subprocess.CompletedProcess:
        return subprocess.run([self.path, *args], capture_output=True, text=True, timeout=60)

    def json(self, *args: str):
        p = self.run(*args, "--json")
        assert p.returncode == 0, p.stderr
        return json.loads(p.stdout)

    def error(self, *args: str) -> str:
        """The one-line message of a rejected input (without the `error: ` prefix)."""
        p = self.run(*args)
        assert p.returncode == 2, (p.returncode, p.stdout, p.stderr)
        line = p.stderr.strip()
        assert line.startswith("error: "), line
        return line[len("error: ") :]


@pytest.fixture(scope="session")
def cli() -> Cli:
    return Cli(_find_cli())


def num(x: float) -> str:
    """A float as the CLI reads it back exactly."""
    return repr(float(x))


def assert_close(py, ref, path="", tol=1e-12):
    """Recursive comparison of a Python record with the CLI's JSON: equal keys, strings and
    booleans; numbers within `tol` (absolute below 1, relative above)."""
    if isinstance(ref, dict):
        assert isinstance(py, dict), f"{path}: {py!r} is not a dict"
        assert set(py) == set(ref), f"{path}: keys {sorted(py)} != {sorted(ref)}"
        for k in ref:
            assert_close(py[k], ref[k], f"{path}.{k}", tol)
    elif isinstance(ref, list):
        assert isinstance(py, (list, tuple)) and len(py) == len(ref), f"{path}: {py!r} != {ref!r}"
        for i, (a, b) in enumerate(zip(py, ref)):
            assert_close(a, b, f"{path}[{i}]", tol)
    elif isinstance(ref, bool) or isinstance(ref, str) or ref is None:
        assert py == ref, f"{path}: {py!r} != {ref!r}"
    else:
        assert py is not None and abs(py - ref) <= tol * max(1.0, abs(ref)), f"{path}: {py!r} != {ref!r}"


def random_planar(rng: np.random.Generator, n: int):
    """Random SPD planar W (a rigid body at a random contact point, random mass and
    inertia), approaching velocities, μ ∈ [0, 1.5], e ∈ [0, 1]."""
    m = rng.uniform(0.2, 5.0, n)
    inertia = rng.uniform(0.05, 3.0, n)
    rt = rng.uniform(-1.5, 1.5, n)
    rn = rng.uniform(-1.5, -0.1, n)
    w = np.stack([1 / m + rn * rn / inertia, -rt * rn / inertia, 1 / m + rt * rt / inertia], axis=1)
    v = np.stack([rng.uniform(-2, 2, n), rng.uniform(-2, -0.05, n)], axis=1)
    return w, v, rng.uniform(0, 1.5, n), rng.uniform(0, 1, n)


def random_spatial(rng: np.random.Generator, n: int):
    """Random SPD 3×3 W (upper triangles), approaching velocities, coefficients."""
    ws = []
    for _ in range(n):
        a = rng.normal(size=(3, 3))
        m = a @ a.T + 0.3 * np.eye(3)
        ws.append([m[0, 0], m[0, 1], m[0, 2], m[1, 1], m[1, 2], m[2, 2]])
    v = np.stack([rng.uniform(-2, 2, n), rng.uniform(-2, 2, n), rng.uniform(-2, -0.05, n)], axis=1)
    return np.array(ws), v, rng.uniform(0, 1.2, n), rng.uniform(0, 1, n)
