"""Bad input raises ValueError with the command line's message (a batch names the first bad
row); nothing panics, and no invalid row yields numbers."""

from __future__ import annotations

import math

import numpy as np
import pytest

import impax
from conftest import num, random_planar, random_spatial
from test_cli_agreement import resolve_args


def batch_with(row: int, w_row, v_row, mu=0.4, e=0.7, n=40):
    rng = np.random.default_rng(1)
    w, v, f, r = random_planar(rng, n)
    w[row], v[row], f[row], r[row] = w_row, v_row, mu, e
    return w, v, f, r


@pytest.mark.parametrize(
    "w_row, v_row, mu, e",
    [
        ([1.0, 2.0, 1.0], [0.5, -1.0], 0.4, 0.7),  # det W < 0: not positive definite
        ([-1.0, 0.0, 1.0], [0.5, -1.0], 0.4, 0.7),  # W_tt < 0
        ([1.0, 0.0, 0.0], [0.5, -1.0], 0.4, 0.7),  # W_nn = 0
        ([3.5, 0.0, 1.0], [0.5, 0.2], 0.4, 0.7),  # separating, not approaching
        ([3.5, 0.0, 1.0], [0.5, -1.0], -0.1, 0.7),  # μ < 0
        ([3.5, 0.0, 1.0], [0.5, -1.0], 0.4, 1.5),  # e > 1
        ([1e300, 0.0, 1e-300], [1e300, -1e300], 0.4, 0.7),  # approach energy not representable
    ],
)
def test_bad_row_is_named_with_the_cli_message(cli, w_row, v_row, mu, e):
    message = cli.error(*resolve_args(w_row, v_row, mu, e))
    w, v, f, r = batch_with(17, w_row, v_row, mu, e)
    with pytest.raises(ValueError) as err:
        impax.resolve_batch(w, v, f, r, "energetic")
    assert str(err.value) == f"row 17: {message}"
    with pytest.raises(ValueError) as err:
        impax.resolve(w_row, v_row, mu, e)
    assert str(err.value) == message
    # Marked instead of raised: that row is invalid with no numbers, the others unchanged.
    marked = impax.resolve_batch(w, v, f, r, "energetic", on_invalid="mark")
    assert impax.STATUSES[marked["status"][17]] == "invalid"
    assert np.all(np.isnan(marked["impulse"][17])) and np.isnan(marked["energy_change"][17])
    good = np.arange(len(w)) != 17
    clean = impax.resolve_batch(w[good], v[good], f[good], r[good], "energetic")
    assert np.array_equal(marked["impulse"][good], clean["impulse"])


def test_first_bad_row_is_the_one_named():
    rng = np.random.default_rng(2)
    w, v, f, r = random_planar(rng, 50_000)
    w[40_123, 1] = 10.0  # not positive definite
    w[30_001, 0] = np.nan
    v[45_000, 1] = 1.0
    with pytest.raises(ValueError, match=r"^row 30001: w\[t,t\]: must be a finite number, got NaN$"):
        impax.resolve_batch(w, v, f, r, "whittaker")
    w[30_001, 0] = 1.0
    with pytest.raises(ValueError, match=r"^row 40123: w: must be positive definite"):
        impax.resolve_batch(w, v, f, r, "whittaker")


def test_nan_and_inf_are_named():
    w, v, f, r = batch_with(5, [1.0, 0.0, 1.0], [np.nan, -1.0])
    with pytest.raises(ValueError, match=r"^row 5: v\[t\]: must be a finite number, got NaN$"):
        impax.resolve_batch(w, v, f, r)
    w, v, f, r = batch_with(3, [1.0, np.inf, 1.0], [0.1, -1.0])
    with pytest.raises(ValueError, match=r"^row 3: w\[t,n\]: must be a finite number, got inf$"):
        impax.resolve_batch(w, v, f, r)
    f[9] = np.nan
    w[3, 1] = 0.0
    with pytest.raises(ValueError, match=r"^row 9: friction: must be a finite number, got NaN$"):
        impax.resolve_batch(w, v, f, r)
    with pytest.raises(ValueError, match=r"^v\[n\]: must be a finite number, got NaN$"):
        impax.resolve([[1, 0], [0, 1]], [0.0, float("nan")], 0.4, 0.7)


def test_wrong_shapes():
    w, v, f, r = random_planar(np.random.default_rng(3), 10)
    with pytest.raises(ValueError, match=r"^w: expected shape \(N, 3\) .* got \(10, 4\)$"):
        impax.resolve_batch(np.ones((10, 4)), v, f, r)
    with pytest.raises(ValueError, match=r"^w: expected shape .* got \(30,\)$"):
        impax.resolve_batch(w.ravel(), v, f, r)
    with pytest.raises(ValueError, match=r"^v: expected shape \(10, 2\) \(v_t, v_n\) for W of shape \(10, 3\), got \(9, 2\)$"):
        impax.resolve_batch(w, v[:9], f, r)
    with pytest.raises(ValueError, match=r"^v: expected shape \(10, 3\)"):
        impax.resolve_batch(np.ones((10, 6)), v, f, r, "whittaker")
    with pytest.raises(ValueError, match=r"^friction: expected a number or shape \(10,\), got \(11,\)$"):
        impax.resolve_batch(w, v, np.ones(11), r)
    with pytest.raises(ValueError, match=r"^restitution: expected a number or shape \(10,\), got \(10, 1\)$"):
        impax.resolve_batch(w, v, f, r.reshape(10, 1))
    with pytest.raises(ValueError, match=r"^w: expected a 2×2 or 3×3 matrix"):
        impax.resolve([[1, 0, 0], [0, 1, 0]], [0, -1], 0.4, 0.7)
    with pytest.raises(ValueError, match=r"^v: expected 2 numbers \(v_t, v_n\) for a planar W, got shape \(3,\)$"):
        impax.resolve([[1, 0], [0, 1]], [0, 0, -1], 0.4, 0.7)
    with pytest.raises(ValueError, match=r"^w: expected .* got an object of type str$"):
        impax.resolve("W", [0, -1], 0.4, 0.7)
    with pytest.raises(ValueError, match=r"^on_invalid: expected"):
        impax.resolve_batch(w, v, f, r, on_invalid="skip")
    with pytest.raises(ValueError, match=r"^threads: must be ≥ 1$"):
        impax.resolve_batch(w, v, f, r, threads=0)


def test_asymmetric_matrix_is_refused():
    # A full W is read as given: a symmetric one is fine, an asymmetric one refused (the CLI
    # takes only the upper triangle, so it cannot express this error).
    assert impax.resolve(np.array([[1, 0.2, 0], [0.2, 1, 0], [0, 0, 1.0]]), [0.1, 0, -1], 0.4, 0.7).law == "energetic"
    with pytest.raises(ValueError, match=r"^w: must be symmetric, but entry \(t,n\) = 0.2 differs from \(n,t\) = 0.3$"):
        impax.resolve([[1, 0.2], [0.3, 1]], [0.1, -1], 0.4, 0.7)


def test_law_errors_are_the_cli_messages(cli):
    base = resolve_args([3.5, 0.0, 1.0], [0.5, -0.8], 0.4, 0.7)
    w, v, f, r = random_planar(np.random.default_rng(4), 5)
    for law in ("kane", "Energetic"):
        message = cli.error(*base, "--law", law)
        with pytest.raises(ValueError) as err:
            impax.resolve_batch(w, v, f, r, law)
        assert str(err.value) == message
        with pytest.raises(ValueError) as err:
            impax.resolve([3.5, 0, 1], [0.5, -0.8], 0.4, 0.7, law)
        assert str(err.value) == message
    spatial = resolve_args([1.0, 0.0, 0.0, 1.0, 0.0, 1.0], [0.1, 0.0, -1.0], 0.4, 0.7)
    message = cli.error(*spatial, "--law", "two-phase")
    w3, v3, f3, r3 = random_spatial(np.random.default_rng(5), 3)
    with pytest.raises(ValueError) as err:
        impax.resolve_batch(w3, v3, f3, r3, "two-phase")
    assert str(err.value) == message
    with pytest.raises(ValueError, match=r"^law: `smith-centre` needs a body"):
        impax.resolve_batch(w, v, f, r, "smith-centre")
    # With a body, smith-centre is a law like the others.
    assert impax.sphere().resolve("smith-centre").verdict == "energy-gained"


def test_body_and_mechanism_errors():
    with pytest.raises(ValueError, match=r"^radius: -1(\.0)? is out of range: must be > 0$"):
        impax.sphere(radius=-1.0)
    with pytest.raises(ValueError, match=r"^angle: .* a rod touches with one end only for 0 < angle < 180°$"):
        impax.rod(angle=math.pi)
    with pytest.raises(ValueError, match=r"^v: the normal contact velocity must be negative \(approach\), got"):
        impax.rod(velocity=(0.0, 1.0))
    with pytest.raises(ValueError, match=r"^speed: give either speed/alpha/spin_ratio or velocity/omega, not both$"):
        impax.sphere(speed=1.0, velocity=(0.0, -1.0))
    with pytest.raises(ValueError, match=r"^mechanism: unknown mechanism `pendulum` \(known: double-pendulum, "):
        impax.mechanism("pendulum")
    with pytest.raises(ValueError, match=r"^ring-pendulum: has no contact point to strike"):
        impax.mechanism("ring-pendulum")
    with pytest.raises(ValueError, match=r"^masses: needs 2 value\(s\), got 3$"):
        impax.mechanism("double-pendulum", masses=[1, 1, 1])
    with pytest.raises(ValueError, match=r"^radius: not a parameter of double-pendulum$"):
        impax.mechanism("double-pendulum", radius=1.0)
    with pytest.raises(ValueError, match=r"^impact: expected a body"):
        impax.compare(42)
    with pytest.raises(ValueError, match=r"^rows 3: |^row 3: angle"):
        impax.study.rod_problems(np.array([0.5, 1.0, 2.0, 0.0]))


def test_edge_arrays_do_not_panic():
    empty = impax.resolve_batch(np.empty((0, 3)), np.empty((0, 2)), 0.4, 0.7)
    assert empty["impulse"].shape == (0, 2) and empty["status"].shape == (0,)
    # Integer and non-contiguous inputs are converted.
    w, v, f, r = random_planar(np.random.default_rng(6), 200)
    a = impax.resolve_batch(w[::2], v[::2], f[::2], r[::2], "newton")
    b = impax.resolve_batch(np.ascontiguousarray(w[::2]), np.ascontiguousarray(v[::2]), f[::2].copy(), r[::2].copy(), "newton")
    assert np.array_equal(a["impulse"], b["impulse"])
    ints = impax.resolve_batch(np.array([[4, 0, 1]]), np.array([[1, -1]]), 0, 1)
    assert ints["impulse"][0, 1] == 2.0
    # Fortran-ordered W.
    c = impax.resolve_batch(np.asfortranarray(w), v, f, r, "poisson")
    d = impax.resolve_batch(w, v, f, r, "poisson")
    assert np.array_equal(c["energy_change"], d["energy_change"], equal_nan=True)


def test_struck_body_errors():
    with pytest.raises(ValueError, match=r"^length: required for shape `rod`$"):
        impax.body("rod", 1.0, angle=1.0)
    with pytest.raises(ValueError, match=r"^radius: not a parameter of shape `rod`$"):
        impax.body("rod", 1.0, length=1.0, angle=1.0, radius=1.0)
    with pytest.raises(ValueError, match=r"^shape: unknown shape `cube` \(known: sphere, disc, rod, ellipse, rigid\)$"):
        impax.body("cube")
    with pytest.raises(ValueError, match=r"^mass: -1(\.0)? is out of range: must be > 0$"):
        impax.body("disc", -1.0, radius=1.0)
    # B moving down faster than A: the contact separates, no impact.
    with pytest.raises(ValueError, match=r"^v: the normal contact velocity must be negative"):
        impax.sphere(other=impax.body("disc", radius=1.0, velocity=(0.0, -5.0)))
