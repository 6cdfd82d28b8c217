"""Bad input raises ValueError with the command line's message (a batch names the first bad
row); nothing panics, and no invalid row yields numbers."""

from __future__ import annotations

import math
import warnings

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
    with pytest.raises(ValueError, match=r"^threads: must be between 1 and 256, got 0$"):
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
    with pytest.raises(ValueError) as err:
        impax.body("cube")
    assert str(err.value) == "shape: unknown shape `cube` (known: " + ", ".join(impax.SHAPES) + ")"
    with pytest.raises(ValueError, match=r"^mass: -1(\.0)? is out of range: must be > 0$"):
        impax.body("disc", -1.0, radius=1.0)
    # B moving down faster than A: the contact separates, no impact.
    with pytest.raises(ValueError, match=r"^v: the normal contact velocity must be negative"):
        impax.sphere(other=impax.body("disc", radius=1.0, velocity=(0.0, -5.0)))


# Regressions of issue 17 ("No silent wrong answers"), items 10 and 12.

PLANAR_W, PLANAR_V = [3.5, 0.0, 1.0], [0.5, -1.0]


def test_threads_outside_1_to_256_are_refused():
    """`resolve_batch(..., threads=10**6)` started a pool of that many threads (the machine's
    load went to 900), `threads=-1` raised pyo3's `OverflowError` ("can't convert negative int
    to unsigned"). Expected: `ValueError` naming `threads` with the limit for any integer
    outside 1..=256, `TypeError` for a non-integer, checked before any work; `impax.study.run`
    checks it before its first chunk."""
    w, v, f, r = random_planar(np.random.default_rng(7), 8)
    for bad in (-1, 0, 257, 10**6):
        with pytest.raises(ValueError, match=rf"^threads: must be between 1 and 256, got {bad}$"):
            impax.resolve_batch(w, v, f, r, threads=bad)
    with pytest.raises(ValueError, match=r"^threads: must be between 1 and 256, got an integer of 31 digits$"):
        impax.resolve_batch(w, v, f, r, threads=10**30)
    for bad in (2.0, True, "4"):
        with pytest.raises(TypeError, match=r"^threads: must be between 1 and 256 \(an integer\) or None"):
            impax.resolve_batch(w, v, f, r, threads=bad)
    assert impax.MAX_THREADS == 256
    reference = impax.resolve_batch(w, v, f, r)
    for good in (1, np.int64(2), 256, None):
        out = impax.resolve_batch(w, v, f, r, threads=good)
        assert np.array_equal(out["impulse"], reference["impulse"])
    space = impax.study.Grid("sphere", {"alpha": np.linspace(0.1, 1.0, 4)})
    with pytest.raises(ValueError, match=r"^threads: must be between 1 and 256, got 1000000$"):
        impax.study.run(space, threads=10**6)


def test_numbers_too_large_for_a_float_are_named():
    """`friction=10**400` raised `OverflowError` ("int too large to convert to float") without
    naming the argument, and a `W` holding 10**400 was reported as "an object of type list".
    Expected: `ValueError` naming the argument (and the entry of a sequence). (No `$` in the
    patterns: pytest also matches the note pyo3 adds, "while processing 'friction'".)"""
    too_big = r"an integer of 401 digits is not representable as a float"
    with pytest.raises(ValueError, match=r"^friction: " + too_big):
        impax.resolve(PLANAR_W, PLANAR_V, 10**400, 0.7)
    with pytest.raises(ValueError, match=r"^restitution: a negative integer of 401 digits is not representable as a float"):
        impax.resolve(PLANAR_W, PLANAR_V, 0.4, -(10**400))
    with pytest.raises(ValueError, match=r"^w\[0\]: " + too_big):
        impax.resolve([10**400, 0.0, 1.0], PLANAR_V, 0.4, 0.7)
    with pytest.raises(ValueError, match=r"^w\[1\]\[1\]: " + too_big):
        impax.resolve([[3.5, 0.0], [0.0, 10**400]], PLANAR_V, 0.4, 0.7)
    with pytest.raises(ValueError, match=r"^v\[1\]: a negative integer of 401 digits"):
        impax.resolve(PLANAR_W, [0.5, -(10**400)], 0.4, 0.7)
    with pytest.raises(ValueError, match=r"^friction: " + too_big):
        impax.resolve_batch([PLANAR_W], [PLANAR_V], 10**400, 0.7)
    with pytest.raises(ValueError, match=r"^w: a number is not representable as a float"):
        impax.resolve_batch([[10**400, 0.0, 1.0]], [PLANAR_V], 0.4, 0.7)
    with pytest.raises(ValueError, match=r"^friction: " + too_big):
        impax.sphere(friction=10**400)
    with pytest.raises(ValueError, match=r"^velocity\[0\]: " + too_big):
        impax.rod(velocity=(10**400, -1.0))
    with pytest.raises(ValueError, match=r"^angles\[1\]: " + too_big):
        impax.mechanism("double-pendulum", angles=[0.5, 10**400])
    with pytest.raises(ValueError, match=r"^masses\[0\]: " + too_big):
        impax.double_pendulum(masses=(10**400, 1.0))
    # Python ints that fit are still numbers.
    assert impax.resolve([4, 0, 1], [1, -1], 0, 1).impulse[1] == 2.0


def test_complex_numbers_are_refused():
    """A complex `W` (a numpy complex array) was cast to its real part with at most a
    `ComplexWarning`. Expected: `TypeError` naming the argument, and no warning."""
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        with pytest.raises(TypeError, match=r"^w: expected real numbers, got complex numbers \(dtype complex128\)$"):
            impax.resolve(np.array([3.5, 0.0, 1.0 + 2.0j]), PLANAR_V, 0.4, 0.7)
        with pytest.raises(TypeError, match=r"^w: expected real numbers, got complex numbers \(dtype complex64\)$"):
            impax.resolve(np.array([[3.5, 0.0], [0.0, 1.0]], dtype=np.complex64), PLANAR_V, 0.4, 0.7)
        with pytest.raises(TypeError, match=r"^w\[2\]: expected a real number, got a complex number \(1\+2j\)$"):
            impax.resolve([3.5, 0.0, 1 + 2j], PLANAR_V, 0.4, 0.7)
        with pytest.raises(TypeError, match=r"^w\[2\]: expected a real number, got a complex number"):
            impax.resolve([3.5, 0.0, np.complex64(1.0)], PLANAR_V, 0.4, 0.7)
        with pytest.raises(TypeError, match=r"^friction: expected a real number, got a complex number"):
            impax.resolve(PLANAR_W, PLANAR_V, 0.4 + 0j, 0.7)
        w, v, f, r = random_planar(np.random.default_rng(8), 6)
        with pytest.raises(TypeError, match=r"^w: expected real numbers, got complex numbers \(dtype complex128\)$"):
            impax.resolve_batch(w + 1j, v, f, r)
        with pytest.raises(TypeError, match=r"^w: expected real numbers, got complex numbers"):
            impax.resolve_batch([list(x) for x in w.astype(complex)], v, f, r)
        with pytest.raises(TypeError, match=r"^restitution: expected real numbers, got complex numbers"):
            impax.resolve_batch(w, v, f, r.astype(complex))
        with pytest.raises(TypeError, match=r"^speed: expected a real number, got a complex number"):
            impax.sphere(speed=1j)
        with pytest.raises(TypeError, match=r"^omega: expected a real number, got an object of type str\b"):
            impax.rod(omega="fast")


def test_large_numbers_in_messages_are_short(cli):
    """1e308 was printed as a 309-digit decimal in messages. Expected: the shortest round-trip
    form, in scientific notation for large and small magnitudes, as the command line prints."""
    for w, v, mu, e, text in [
        (PLANAR_W, PLANAR_V, -1e308, 0.7, "friction: -1e308 is out of range"),
        ([-1.5e-200, 0.0, 1.0], PLANAR_V, 0.4, 0.7, "W_tt = -1.5e-200 is not positive"),
        (PLANAR_W, [0.5, 1e300], 0.4, 0.7, "(approach), got 1e300"),
        (PLANAR_W, PLANAR_V, 0.4, 12.0, "restitution: 12 is out of range"),
    ]:
        message = cli.error(*resolve_args(w, v, mu, e))
        with pytest.raises(ValueError) as err:
            impax.resolve(w, v, mu, e)
        assert str(err.value) == message
        assert text in message and len(message) < 200, message
    with pytest.raises(ValueError, match=r"^speed: must be > 0, got -1e300$"):
        impax.sphere(speed=-1e300)
