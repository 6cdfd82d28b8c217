"""Parameter spaces of built-in scenarios, resolved in chunks and reduced.

A *space* maps a point index ``i`` to the parameters of a scenario, as a pure function of
``i``: a :class:`Grid` (the first axis varies slowest) or a :class:`RandomSample` (uniform
draws; point ``i`` depends only on the seed and ``i``, never on how the points are cut into
chunks). A *scenario* maps parameter arrays to contact-space problems ``(W, v, μ, e)`` for
:func:`impax.resolve_batch`:

* ``"sphere"`` — :func:`sphere_problems` (paper A's sphere: α, γ, v0, m, r);
* ``"rod"`` — :func:`rod_problems` (a uniform rod striking with its lower end);
* ``"contact"`` — :func:`contact_problems` (the entries of ``W`` and ``v⁻`` directly).

:func:`run` resolves a space chunk by chunk in this process and reduces it (counts by status:
the energy-gain fraction), optionally keeping one output column as a map over the space or
writing each chunk as a Parquet file; :func:`impax.dask.sweep` does the same on a Dask
cluster with the same chunk function, so both give identical numbers.
"""

from __future__ import annotations

import dataclasses
import inspect
import math
import os
import time
from typing import Callable, Mapping

import numpy as np

from . import _impax

def _arrays(*xs):
    return np.broadcast_arrays(*(np.asarray(x, dtype=np.float64) for x in xs))


def _pack(wtt, wtn, wnn, vt, vn, friction, restitution):
    n = wtt.size
    w = np.empty((n, 3))
    w[:, 0], w[:, 1], w[:, 2] = wtt.ravel(), wtn.ravel(), wnn.ravel()
    v = np.empty((n, 2))
    v[:, 0], v[:, 1] = vt.ravel(), vn.ravel()
    return w, v, friction.ravel(), restitution.ravel()


def _coefficients(n: int, friction, restitution):
    return (
        np.broadcast_to(np.asarray(friction, dtype=np.float64), (n,)),
        np.broadcast_to(np.asarray(restitution, dtype=np.float64), (n,)),
    )


def sphere_problems(alpha, spin_ratio=0.0, speed=1.0, mass=1.0, radius=1.0, friction=0.4, restitution=0.7):
    """Paper A's sphere on a plane, for many parameter values: ``W = (1/m) diag(7/2, 1)``,
    ``v⁻ = (v0 (sin α + γ), −v0 cos α)`` (eqs. 1 and 6; ``I = 2/5 m r²``, ``ω0 = γ v0 / r``).

    ``alpha`` in radians. Every argument is a number or a 1-D array of one common length.
    Returns ``(W, v, friction, restitution)`` with ``W`` of shape (N, 3) and ``v`` (N, 2),
    computed by the library's sphere in parallel: row ``i`` equals ``impax.sphere(...)`` at
    the same values bit for bit. A bad value raises ``ValueError("row I: ...")``.
    """
    w, v = _impax.sphere_rows(alpha, spin_ratio, speed, mass, radius)
    return (w, v, *_coefficients(len(w), friction, restitution))


def rod_problems(angle, speed=1.0, direction=0.0, omega=0.0, mass=1.0, length=1.0, friction=0.4, restitution=0.7):
    """Uniform rods at ``angle`` (radians, 0 < θ < π) from the surface striking with their
    lower end, for many parameter values: ``I = m L²/12``, contact at
    ``r = −(L/2)(cos θ, sin θ)``; the centre moves at ``speed`` along ``direction`` (radians
    from the downward normal: ``v = speed (sin d, −cos d)``) and spins at ``omega``, so
    ``W = [[1/m + r_n²/I, −r_t r_n/I], [·, 1/m + r_t²/I]]`` and ``v⁻ = (v_x − ω r_n, v_y + ω r_t)``.

    Returns ``(W, v, friction, restitution)`` as :func:`sphere_problems`; row ``i`` equals
    ``impax.rod(mass, length, angle, velocity=(vx, vy), omega=omega)`` bit for bit.
    """
    w, v = _impax.rod_rows(angle, speed, direction, omega, mass, length)
    return (w, v, *_coefficients(len(w), friction, restitution))


def contact_problems(wtt, wtn, wnn, vt, vn, friction=0.4, restitution=0.7):
    """Contact-space problems given entry by entry: ``W = [[W_tt, W_tn], [W_tn, W_nn]]``,
    ``v⁻ = (v_t, v_n)``."""
    return _pack(*_arrays(wtt, wtn, wnn, vt, vn, friction, restitution))


#: The built-in scenarios by name: parameter arrays ↦ ``(W, v, friction, restitution)``.
SCENARIOS: dict[str, Callable] = {
    "sphere": sphere_problems,
    "rod": rod_problems,
    "contact": contact_problems,
}


def _scenario(name: str) -> Callable:
    try:
        return SCENARIOS[name]
    except KeyError:
        raise ValueError(f"scenario: unknown scenario `{name}` (known: {', '.join(SCENARIOS)})") from None


def _check_names(scenario: str, names) -> None:
    params = inspect.signature(_scenario(scenario)).parameters
    for name in names:
        if name not in params:
            raise ValueError(
                f"{name}: not a parameter of scenario `{scenario}` (parameters: {', '.join(params)})"
            )


class Grid:
    """A regular grid over parameters of a scenario.

    ``axes`` maps parameter names to 1-D arrays of values; point ``i`` is the ``i``-th point of
    the grid in C order (the first axis varies slowest), so a map reshapes to ``grid.shape``.
    ``fixed`` gives the other parameters one value each.

    >>> g = Grid("sphere", {"alpha": np.radians(np.linspace(0, 90, 91)), "spin_ratio": np.linspace(-3, 3, 121)},
    ...          fixed={"friction": 0.4, "restitution": 0.7})
    >>> g.shape, len(g)
    ((91, 121), 11011)
    """

    def __init__(self, scenario: str, axes: Mapping[str, np.ndarray], fixed: Mapping[str, float] | None = None):
        self.scenario = scenario
        self.axes = {k: np.asarray(v, dtype=np.float64).ravel() for k, v in axes.items()}
        self.fixed = dict(fixed or {})
        _check_names(scenario, list(self.axes) + list(self.fixed))
        for k, v in self.axes.items():
            if v.size == 0:
                raise ValueError(f"{k}: an axis needs at least one value")
        self.shape = tuple(v.size for v in self.axes.values())

    def __len__(self) -> int:
        return math.prod(self.shape)

    def params(self, start: int, stop: int) -> dict[str, np.ndarray]:
        """The parameters of points ``start..stop``."""
        coords = np.unravel_index(np.arange(start, stop), self.shape)
        out = {k: axis[c] for (k, axis), c in zip(self.axes.items(), coords)}
        out.update(self.fixed)
        return out

    def problems(self, start: int = 0, stop: int | None = None):
        """``(W, v, friction, restitution)`` of points ``start..stop`` (default: all)."""
        p = self.params(start, len(self) if stop is None else stop)
        return _scenario(self.scenario)(**p)

    def __repr__(self) -> str:
        return f"Grid({self.scenario!r}, shape={self.shape}, axes={list(self.axes)}, fixed={self.fixed})"


class RandomSample:
    """``n`` points with parameters drawn uniformly from ``ranges`` (``name: (low, high)``).

    Points are drawn in blocks of :attr:`BLOCK`; block ``b`` uses the generator
    ``numpy.random.default_rng([seed, b])`` (PCG64) and draws every ranged parameter for its
    points, so point ``i`` depends only on ``seed`` and ``i`` — the same on one machine or on a
    cluster, whatever the chunk size.
    """

    #: Points per random block.
    BLOCK = 1 << 16

    def __init__(
        self,
        scenario: str,
        n: int,
        ranges: Mapping[str, tuple[float, float]],
        fixed: Mapping[str, float] | None = None,
        seed: int = 0,
    ):
        if int(n) < 0:
            raise ValueError(f"n: must be ≥ 0, got {n}")
        self.scenario = scenario
        self.n = int(n)
        self.ranges = {k: (float(lo), float(hi)) for k, (lo, hi) in ranges.items()}
        self.fixed = dict(fixed or {})
        self.seed = int(seed)
        _check_names(scenario, list(self.ranges) + list(self.fixed))
        for k, (lo, hi) in self.ranges.items():
            if not (math.isfinite(lo) and math.isfinite(hi) and lo <= hi):
                raise ValueError(f"{k}: a range needs finite low ≤ high, got ({lo}, {hi})")
        self.shape = (self.n,)

    def __len__(self) -> int:
        return self.n

    def params(self, start: int, stop: int) -> dict[str, np.ndarray]:
        """The parameters of points ``start..stop``."""
        k = len(self.ranges)
        u = np.empty((k, stop - start))
        blocks = range(start // self.BLOCK, (stop - 1) // self.BLOCK + 1) if stop > start else range(0)
        for b in blocks:
            block = np.random.default_rng([self.seed, b]).random((k, self.BLOCK))
            lo = max(start, b * self.BLOCK)
            hi = min(stop, (b + 1) * self.BLOCK)
            u[:, lo - start : hi - start] = block[:, lo - b * self.BLOCK : hi - b * self.BLOCK]
        out = {name: low + (high - low) * u[j] for j, (name, (low, high)) in enumerate(self.ranges.items())}
        out.update(self.fixed)
        return out

    def problems(self, start: int = 0, stop: int | None = None):
        """``(W, v, friction, restitution)`` of points ``start..stop`` (default: all)."""
        p = self.params(start, self.n if stop is None else stop)
        return _scenario(self.scenario)(**p)

    def __repr__(self) -> str:
        return f"RandomSample({self.scenario!r}, n={self.n}, ranges={self.ranges}, fixed={self.fixed}, seed={self.seed})"


@dataclasses.dataclass
class Summary:
    """Counts of a batch by status (``impax.STATUSES``), and the fractions that follow."""

    law: str
    counts: np.ndarray = dataclasses.field(default_factory=lambda: np.zeros(len(_impax.STATUSES), dtype=np.int64))

    @classmethod
    def of(cls, law: str, result: Mapping[str, np.ndarray]) -> "Summary":
        """The summary of one result of :func:`impax.resolve_batch`."""
        return cls(law, np.bincount(result["status"], minlength=len(_impax.STATUSES)).astype(np.int64))

    def __add__(self, other: "Summary") -> "Summary":
        return Summary(self.law, self.counts + other.counts)

    def count(self, status: str) -> int:
        """Number of points with this status (``consistent``, ``energy-gained``, …)."""
        return int(self.counts[_impax.STATUSES.index(status)])

    @property
    def points(self) -> int:
        """Every point, invalid ones included."""
        return int(self.counts.sum())

    @property
    def valid(self) -> int:
        """Points that are impacts (valid problems: approaching, ``W`` positive definite, …)."""
        return self.points - self.count("invalid")

    @property
    def energy_gained(self) -> int:
        """Impacts whose kinetic energy rose (Kane's paradox)."""
        return self.count("energy-gained")

    @property
    def energy_gain_fraction(self) -> float:
        """``energy_gained / valid`` (NaN when there is no valid point)."""
        return self.energy_gained / self.valid if self.valid else float("nan")

    @property
    def breakdown_fraction(self) -> float:
        """Fraction of the valid points where the law gives no admissible result."""
        return self.count("breakdown") / self.valid if self.valid else float("nan")

    def as_dict(self) -> dict[str, int]:
        """Counts by status id."""
        return {s: int(c) for s, c in zip(_impax.STATUSES, self.counts)}


@dataclasses.dataclass
class SweepResult:
    """What :func:`run` and :func:`impax.dask.sweep` return."""

    law: str
    summary: Summary
    #: The ``map`` column over the space (shape ``space.shape``), or None.
    map: np.ndarray | None
    #: Parquet files written, in point order (empty without ``parquet``).
    files: list[str]
    chunks: int
    seconds: float
    #: Dask workers used (0 when run in this process).
    workers: int = 0

    @property
    def points(self) -> int:
        return self.summary.points

    @property
    def throughput(self) -> float:
        """Points per second, wall clock."""
        return self.points / self.seconds if self.seconds > 0 else float("nan")


#: Output columns of :func:`impax.resolve_batch` that can be kept as a map (one value per point).
MAP_COLUMNS = (
    "energy_change",
    "work_compression",
    "work_restitution",
    "work_friction",
    "compression_impulse",
    "status",
    "sequence",
    "energy_gained",
)


def chunks(n: int, chunk_size: int) -> list[tuple[int, int]]:
    """``[(start, stop), ...]`` covering ``0..n`` in chunks of ``chunk_size`` points."""
    if chunk_size < 1:
        raise ValueError(f"chunk_size: must be ≥ 1, got {chunk_size}")
    return [(s, min(s + chunk_size, n)) for s in range(0, n, chunk_size)]


def _write_parquet(path: str, params: Mapping[str, np.ndarray], n: int, result: Mapping[str, np.ndarray]) -> None:
    try:
        import pyarrow as pa
        import pyarrow.parquet as pq
    except ImportError as e:  # pragma: no cover - depends on the environment
        raise ValueError("parquet: writing Parquet needs pyarrow (pip install pyarrow)") from e
    cols: dict[str, object] = {}
    for k, v in params.items():
        cols[k] = np.broadcast_to(np.asarray(v, dtype=np.float64), (n,)).copy()
    dim = result["impulse"].shape[1]
    axes = ("t", "n") if dim == 2 else ("t1", "t2", "n")
    for j, a in enumerate(axes):
        cols[f"p_{a}"] = result["impulse"][:, j]
    for j, a in enumerate(axes):
        cols[f"v_{a}_after"] = result["velocity_after"][:, j]
    for k in ("energy_change", "work_compression", "work_restitution", "work_friction", "compression_impulse"):
        cols[k] = result[k]
    sequences = _impax.SEQUENCES if dim == 2 else _impax.SEQUENCES_3D
    cols["status"] = pa.DictionaryArray.from_arrays(
        pa.array(result["status"].astype(np.int8)), pa.array(list(_impax.STATUSES))
    )
    cols["sequence"] = pa.DictionaryArray.from_arrays(pa.array(result["sequence"].astype(np.int8)), pa.array(list(sequences)))
    cols["energy_gained"] = result["energy_gained"]
    pq.write_table(pa.table(cols), path)


def run_chunk(
    index: int,
    space,
    law: str,
    chunk_size: int,
    map: str | None = None,
    parquet: str | None = None,
    on_invalid: str = "mark",
    threads: int | None = None,
) -> dict:
    """Resolve chunk ``index`` of ``space`` (points ``index·chunk_size`` onward) with
    :func:`impax.resolve_batch`: its summary, its slice of the ``map`` column, and the Parquet
    file it wrote. The unit of work of :func:`run` and of :func:`impax.dask.sweep`."""
    start = index * chunk_size
    stop = min(start + chunk_size, len(space))
    params = space.params(start, stop)
    w, v, friction, restitution = _scenario(space.scenario)(**params)
    result = _impax.resolve_batch(w, v, friction, restitution, law, on_invalid=on_invalid, threads=threads)
    out = {"index": index, "start": start, "stop": stop, "summary": Summary.of(law, result), "map": None, "file": None}
    if map is not None:
        out["map"] = result[map]
    if parquet is not None:
        path = os.path.join(parquet, f"part-{index:06d}.parquet")
        _write_parquet(path, params, stop - start, result)
        out["file"] = path
    return out


def _check(space, law: str, map: str | None, parquet: str | None, threads: int | None = None) -> None:
    _impax._check_threads(threads)
    if law not in _impax.LAWS:
        raise ValueError(f"law: unknown impact law `{law}` (known: {', '.join(_impax.LAWS)})")
    if map is not None and map not in MAP_COLUMNS:
        raise ValueError(f"map: expected one of {', '.join(MAP_COLUMNS)}, got {map!r}")
    if parquet is not None:
        os.makedirs(parquet, exist_ok=True)


class _Collector:
    """Reduces chunk results in any order into a :class:`SweepResult`."""

    def __init__(self, space, law: str, chunk_size: int, map: str | None):
        self.space, self.law, self.chunk_size = space, law, chunk_size
        self.summary = Summary(law)
        self.map = None
        self.map_name = map
        self.files: dict[int, str] = {}
        self.count = 0

    def add(self, r: dict) -> None:
        self.summary = self.summary + r["summary"]
        if r["map"] is not None:
            if self.map is None:
                self.map = np.empty(len(self.space), dtype=r["map"].dtype)
            self.map[r["start"] : r["stop"]] = r["map"]
        if r["file"] is not None:
            self.files[r["index"]] = r["file"]
        self.count += 1

    def result(self, seconds: float, workers: int) -> SweepResult:
        m = self.map.reshape(self.space.shape) if self.map is not None else None
        if self.map_name is not None and m is None:
            m = np.empty(self.space.shape)
        files = [self.files[k] for k in sorted(self.files)]
        return SweepResult(self.law, self.summary, m, files, self.count, seconds, workers)


def run(
    space,
    law: str = "energetic",
    *,
    chunk_size: int = 1 << 18,
    map: str | None = None,
    parquet: str | None = None,
    on_invalid: str = "mark",
    threads: int | None = None,
) -> SweepResult:
    """Resolve every point of ``space`` with ``law`` in this process, chunk by chunk (each
    chunk in parallel inside :func:`impax.resolve_batch`), and reduce.

    ``map``: keep this output column (one of :data:`MAP_COLUMNS`) over the space, shaped as
    the space. ``parquet``: a directory; chunk ``k`` is written to ``part-{k:06d}.parquet``
    (needs pyarrow). ``on_invalid="mark"`` counts invalid points (e.g. not approaching) as
    ``invalid`` instead of raising. ``threads``: the worker threads of each chunk's batch, 1 to
    ``impax.MAX_THREADS`` (256; default: one per core); checked before the first chunk.
    """
    _check(space, law, map, parquet, threads)
    t = time.perf_counter()
    c = _Collector(space, law, chunk_size, map)
    for index in range(len(chunks(len(space), chunk_size))):
        c.add(run_chunk(index, space, law, chunk_size, map, parquet, on_invalid, threads))
    return c.result(time.perf_counter() - t, 0)
