"""Type stubs of the compiled core ``impax._impax`` (re-exported by ``impax``)."""

import os
from typing import Any, Literal, Sequence, TypedDict, overload

import numpy as np
import numpy.typing as npt

__version__: str
#: Every law id, in presentation order (``smith-centre`` needs a body).
LAWS: list[str]
#: The laws defined in contact space (every law but ``smith-centre``).
CONTACT_SPACE_LAWS: list[str]
#: The laws defined for spatial (3D) problems.
SPATIAL_LAWS: list[str]
#: The laws for several contacts at once (``lcp``, ``sequential``).
MULTI_CONTACT_LAWS: list[str]
#: ``resolve_batch`` status codes, by index: consistent, energy-gained,
#: inconsistent-assumption, breakdown, invalid.
STATUSES: list[str]
#: ``resolve_batch`` phase-sequence codes of planar problems, by index.
SEQUENCES: list[str]
#: ``resolve_batch`` phase-sequence codes of spatial problems, by index.
SEQUENCES_3D: list[str]
#: Planar body shape names (the core's), for :func:`body_impact` and :func:`body`.
SHAPES: list[str]
#: Built-in mechanism names.
MECHANISMS: list[str]
#: The most worker threads ``resolve_batch(..., threads=)`` accepts (256).
MAX_THREADS: int

ArrayLike = npt.ArrayLike

class Outcome:
    """The result of one impact law on one impact.

    Attributes are ``None`` where the law broke down (``verdict == "breakdown"``, the reason in
    ``breakdown``): a breakdown never carries numbers. ``to_dict()`` gives the entry of the
    command line's ``--json`` output for the same impact, key for key.
    """

    @property
    def law(self) -> str:
        """The law's stable id, e.g. ``"energetic"``."""
    @property
    def verdict(self) -> Literal["consistent", "energy-gained", "inconsistent-assumption", "breakdown"]:
        """``energy-gained`` is Kane's paradox; ``inconsistent-assumption``: the law's own
        assumption is contradicted by its result (see ``inconsistency``)."""
    @property
    def energy_gained(self) -> bool:
        """Whether the kinetic energy rose."""
    @property
    def breakdown(self) -> dict[str, str] | None:
        """``{"id", "message"}`` when the law gives no admissible result (e.g. Whittaker's
        ``p_n = −(1+e) v_n⁻ / (W_nn − μ s₀ W_tn)`` with a denominator ≤ 0)."""
    @property
    def impulse(self) -> tuple[float, ...] | None:
        """Impulse on body A, ``(p_t, p_n)`` or ``(p_t1, p_t2, p_n)``."""
    @property
    def velocity_after(self) -> tuple[float, ...] | None:
        """Contact velocity after, ``v⁺ = v⁻ + W p``."""
    @property
    def energy_change(self) -> float | None:
        """``ΔT = v⁻·p + ½ pᵀ W p`` (exact for any impulse; theory §1)."""
    @property
    def energy_before(self) -> float | None:
        """Kinetic energy before: of the bodies, or ``½ u⁻ᵀ M u⁻`` of a mechanism (``None`` in
        contact space)."""
    @property
    def approach_energy(self) -> float:
        """``½ v⁻ᵀ W⁻¹ v⁻``: the most energy any impulse can remove."""
    @property
    def hodograph(self) -> list[tuple[float, float, float, float]] | None:
        """``(p_n, v_t1, v_t2, v_n)`` at every accepted point of the Darboux–Keller
        integration (``newton``, ``poisson``, ``energetic`` on a spatial contact problem;
        ``None`` otherwise or on a breakdown). Computed when read."""
    @property
    def invariant_rays(self) -> list[dict[str, Any]] | Literal["all"] | None:
        """The spatial problem's invariant rays, ``{"angle_deg", "kind", "rate"}`` each
        (``kind`` ``centripetal`` or ``centrifugal``), or ``"all"`` (isotropic ``W_tt``,
        ``w_tn = 0``); ``None`` for other records."""
    @property
    def all_solutions(self) -> list[dict[str, Any]] | None:
        """Every solution of the spatial LCP, least kinetic energy after first (``lcp`` on
        a spatial contact problem; ``None`` otherwise)."""
    @property
    def compression_impulse(self) -> float | None:
        """Normal impulse ``p_c`` at the end of compression (``v_n = 0``), if reached."""
    @property
    def work(self) -> dict[str, float] | None:
        """``{"compression", "restitution", "friction"}``; they sum to ``ΔT``."""
    @property
    def phases(self) -> list[dict[str, Any]]:
        """``[{"kind", "ends_at"}, …]``: ``slip+``, ``slip-``, ``stick``, ``no-slip`` (3D:
        ``slip`` with ``from_deg``/``to_deg``, ``stick``, ``resumed-slip`` with ``angle_deg``)."""
    @property
    def inconsistency(self) -> dict[str, str] | None:
        """``{"id", "message"}``: ``slip-reversed``, ``reversal-did-not-happen``,
        ``multiple-solutions``, ``still-approaching``."""
    @property
    def detail(self) -> dict[str, Any] | None:
        """Law-specific numbers (two-phase ``switch_impulse``; smith ``eta``, ``roots``,
        ``reading``; brach ``ratio``, ``capped``; Darboux–Keller ``slip_halt``; lcp ``ratio``,
        ``consistent_candidates`` / ``solutions``)."""
    @property
    def body_velocity_after(self) -> dict[str, float] | None:
        """Body A after, ``{"vx", "vy", "omega"}`` (bodies only)."""
    @property
    def other_body_velocity_after(self) -> dict[str, float] | None:
        """Body B after (two free bodies only)."""
    @property
    def energy_split(self) -> dict[str, float] | None:
        """``ΔT`` split into ``{"translational", "rotational"}`` (paper A §5; bodies only)."""
    @property
    def energy_change_ratio(self) -> float | None:
        """``ΔT / T0``, ``T0`` the translational kinetic energy before (bodies only)."""
    @property
    def velocities_after(self) -> tuple[float, ...] | None:
        """Generalized velocities after, ``u⁺ = u⁻ + M⁻¹ Jᵀ p`` (mechanisms only)."""
    @property
    def energy_after(self) -> float | None:
        """``T⁻ + ΔT`` (mechanisms only)."""
    @property
    def energy_ratio(self) -> float | None:
        """``T⁺ / T⁻`` (mechanisms only)."""
    @property
    def energy_change_from_velocities(self) -> float | None:
        """``½ u⁺ᵀ M u⁺ − ½ u⁻ᵀ M u⁻`` (mechanisms only; equals ``energy_change`` to round-off)."""
    def to_dict(self) -> dict[str, Any]:
        """The record as the CLI's JSON entry (``impax resolve --json``; an entry of
        ``results`` of ``impax compare --json`` for a body or a mechanism)."""

class Body:
    """A struck free body B (met at its highest point) with its state: the ``other=`` of a
    body constructor (``W = W_A + W_B``, ``v = v_A − v_B``, impulse ``p`` on A, ``−p`` on B)."""

    @property
    def w(self) -> np.ndarray:
        """``W_B`` at its contact point."""
    @property
    def description(self) -> str: ...

def body(
    shape: str,
    mass: float = 1.0,
    *,
    radius: float | None = None,
    length: float | None = None,
    angle: float | None = None,
    semi_axes: tuple[float, float] | None = None,
    inertia: float | None = None,
    contact: tuple[float, float] | None = None,
    velocity: tuple[float, float] = (0.0, 0.0),
    omega: float = 0.0,
    **params: float | tuple[float, float] | None,
) -> Body:
    """A struck body B for ``other=`` (the ``[other]`` table of a scenario file): ``shape`` one of
    :data:`SHAPES`, its parameters by keyword as scenario files name them; angles in radians."""

class BodyImpact:
    """A planar body with its state striking a fixed surface, with μ and e."""

    @property
    def w(self) -> np.ndarray:
        """``W = [[1/m + r_n²/I, −r_t r_n/I], [·, 1/m + r_t²/I]]`` (2×2)."""
    @property
    def v(self) -> tuple[float, float]:
        """Contact velocity before, ``(v_x − ω r_n, v_y + ω r_t)``."""
    @property
    def friction(self) -> float: ...
    @property
    def restitution(self) -> float: ...
    @property
    def energy_before(self) -> float:
        """``½ m |v|² + ½ I ω²``."""
    @property
    def t0(self) -> float:
        """The normalisation of ``energy_change_ratio``: the translational kinetic energy before."""
    @property
    def description(self) -> str: ...
    def resolve(self, law: str = "energetic") -> Outcome:
        """Resolve with one law (any law, including ``smith-centre``)."""

class MechanismImpact:
    """A built-in mechanism at a state, striking with its contact, with μ and e."""

    @property
    def name(self) -> str: ...
    @property
    def coordinates(self) -> tuple[str, ...]: ...
    @property
    def q(self) -> tuple[float, ...]:
        """Generalized coordinates (radians for angles)."""
    @property
    def u(self) -> tuple[float, ...]:
        """Generalized velocities before."""
    @property
    def w(self) -> np.ndarray:
        """``W = J M⁻¹ Jᵀ`` (by automatic differentiation of the kinematics)."""
    @property
    def v(self) -> tuple[float, float]:
        """``v⁻ = J u⁻``."""
    @property
    def friction(self) -> float: ...
    @property
    def restitution(self) -> float: ...
    @property
    def energy_before(self) -> float:
        """``½ u⁻ᵀ M u⁻``."""
    @property
    def gap(self) -> float: ...
    @property
    def description(self) -> str: ...
    def resolve(self, law: str = "energetic") -> Outcome:
        """Resolve with one law; ``velocities_after`` from ``M (u⁺ − u⁻) = Jᵀ p``."""

class Mechanism:
    """A mechanism file or a URDF robot read once (:func:`mechanism`), evaluated at any state
    ``(q, u)``. Every number is the core's (the command line's ``impax compare FILE``)."""

    @property
    def name(self) -> str: ...
    @property
    def space(self) -> Literal["2d", "3d"]: ...
    @property
    def coordinates(self) -> list[str]:
        """The names of the entries of ``q`` (a floating base's ``x, y, z, qw, qx, qy, qz`` first)."""
    @property
    def speeds(self) -> tuple[str, ...]:
        """The names of the entries of ``u`` (a floating base's ``vx, vy, vz, wx, wy, wz``, world frame)."""
    @property
    def contacts(self) -> tuple[str, ...]:
        """A file's contacts; a URDF robot's links (``"LINK"`` or ``"LINK:x,y,z"``)."""
    @property
    def mimic_joints(self) -> tuple[str, ...]: ...
    @property
    def description(self) -> str: ...
    def neutral(self) -> np.ndarray:
        """Every joint at zero; a floating base at the origin, quaternion ``(1, 0, 0, 0)``."""
    def default_state(self) -> tuple[np.ndarray, np.ndarray]:
        """A file's ``q`` and ``u`` (else neutral and at rest)."""
    def mass_matrix(self, q: ArrayLike) -> np.ndarray:
        """``M(q)``, ``nv × nv``: ``T = ½ uᵀ M u``."""
    def contact_jacobian(self, q: ArrayLike, contact: str | None = None) -> np.ndarray:
        """The contact's Jacobian in its contact frame (rows ``t, n`` in 2D; ``t1, t2, n`` =
        the world's ``x, y, z`` in 3D): ``v = J u``."""
    def contact_problem(
        self, q: ArrayLike, u: ArrayLike, contact: str | None = None, friction: float | None = None, restitution: float | None = None
    ) -> tuple[np.ndarray, np.ndarray]:
        """``(W, v⁻)``: ``W = J M⁻¹ Jᵀ`` and ``v⁻ = J u``."""
    def gap(self, q: ArrayLike, contact: str | None = None) -> float:
        """The contact's height above the floor (0 when the floor passes through it)."""
    def impact(
        self,
        q: ArrayLike,
        u: ArrayLike,
        contact: str | None = None,
        friction: float | None = None,
        restitution: float | None = None,
        laws: str | Sequence[str] | None = None,
    ) -> dict[str, Any]:
        """Every law (or ``laws``) on the impact at ``(q, u)``: the document of
        ``impax compare FILE --q Q --u U --json`` (``mechanism``, ``coordinates``, ``q``,
        ``u_before``, ``contact``, ``gap``, ``problem``, ``energy_before``, ``results`` with
        ``velocities_after``, ``energy_change``, …), key for key."""
    def impact_batch(
        self,
        q: ArrayLike,
        u: ArrayLike,
        contact: str | None = None,
        friction: float | None = None,
        restitution: float | None = None,
        law: str = "energetic",
        *,
        on_invalid: Literal["raise", "mark"] = "raise",
        threads: int | None = None,
    ) -> dict[str, Any]:
        """One law over many states, ``q`` ``(N, nq)`` and ``u`` ``(N, nv)``, in parallel:
        ``velocities_after`` ``(N, nv)``, ``impulse`` and ``velocity_after`` ``(N, d)``,
        ``energy_before``, ``energy_change`` and ``status`` ``(N,)``; row ``i`` equals
        ``impact(q[i], u[i], laws=law)``."""

@overload
def resolve(w: ArrayLike, v: ArrayLike, friction: float, restitution: float, law: str = "energetic") -> Outcome: ...
@overload
def resolve(
    w: ArrayLike,
    v: ArrayLike,
    friction: float | Sequence[float],
    restitution: float | Sequence[float],
    law: str = "energetic",
    *,
    contacts: int,
    stiffness: float | Sequence[float] | None = None,
    exponent: float | None = None,
) -> MultiOutcome: ...
def resolve(w, v, friction, restitution, law="energetic", *, contacts=None, stiffness=None, exponent=None):
    """Resolve one impact in contact space with one law.

    ``w``: ``W = J M⁻¹ Jᵀ``, 2×2 (planar) or 3×3 (spatial), or its upper triangle (3 or 6
    numbers, as ``impax resolve --w``); ``v``: the contact velocity before (tangent(s) first,
    normal last, ``v_n < 0``); ``friction`` μ ≥ 0; ``restitution`` e ∈ [0, 1]. During the
    impact ``v(p) = v⁻ + W p`` (theory §1). Raises ``ValueError`` with the CLI's message.

    With ``contacts=K`` (``impax resolve --contacts K``): a problem with ``K`` contacts at
    once — ``w`` the ``2K × 2K`` W (planar) or ``3K × 3K`` (spatial), positive
    semidefinite, or its upper triangle; ``v`` ``dK`` numbers or ``K`` rows of ``d``;
    ``friction`` and ``restitution`` one number or ``K``; laws ``lcp``, ``sequential`` and
    ``lzb`` (``MULTI_CONTACT_LAWS``, planar and spatial); for ``lzb``
    ``stiffness`` (one number or ``K``) and ``exponent``; returns a :class:`MultiOutcome`.
    """

class MultiOutcome:
    """The outcome of a law on a problem with several contacts."""

    @property
    def law(self) -> str: ...
    @property
    def verdict(self) -> str:
        """``consistent``, ``energy-gained``, ``inconsistent-assumption`` or ``breakdown``."""
    @property
    def energy_change(self) -> float | None:
        """``ΔT = ½ (v⁻ + v⁺)·p`` of the whole impact."""
    @property
    def impulses(self) -> list[tuple[float, float]] | None:
        """``(p_t, p_n)`` per contact."""
    @property
    def velocities_after(self) -> list[tuple[float, float]] | None:
        """``(v_t⁺, v_n⁺)`` per contact."""
    @property
    def contacts(self) -> list[dict[str, Any]] | None:
        """Per contact ``impulse``, ``velocity_after``, ``phases`` (``(kind, ends_at)``), ``work``."""
    @property
    def inconsistency(self) -> dict[str, str] | None: ...
    @property
    def breakdown(self) -> dict[str, str] | None: ...
    @property
    def detail(self) -> dict[str, Any] | None:
        """``lcp``: ``solutions``; ``sequential``: ``impacts`` (as the CLI's JSON)."""

class BatchResult(TypedDict):
    law: str
    impulse: np.ndarray
    velocity_after: np.ndarray
    energy_change: np.ndarray
    work_compression: np.ndarray
    work_restitution: np.ndarray
    work_friction: np.ndarray
    compression_impulse: np.ndarray
    status: np.ndarray
    sequence: np.ndarray
    energy_gained: np.ndarray

def resolve_batch(
    w: ArrayLike,
    v: ArrayLike,
    friction: ArrayLike,
    restitution: ArrayLike,
    law: str = "energetic",
    *,
    on_invalid: Literal["raise", "mark"] = "raise",
    threads: int | None = None,
    contacts: int | None = None,
) -> BatchResult:
    """Resolve many impacts with one law, in parallel (the GIL released), on numpy arrays.

    Planar: ``w`` (N, 3) = ``W_tt, W_tn, W_nn``, ``v`` (N, 2) = ``v_t, v_n``. Spatial: ``w``
    (N, 6) = ``W11, W12, W13, W22, W23, W33``, ``v`` (N, 3). ``friction``, ``restitution``:
    numbers or (N,). Row ``i`` is ``resolve(w[i], v[i], friction[i], restitution[i], law)``.

    With ``contacts=K`` (a multi-contact law): ``w`` (N, dK, dK) or its upper triangles
    (N, dK(dK+1)/2), d = 2 (planar) or 3 (spatial); ``v`` (N, dK) or (N, K, d);
    ``friction``, ``restitution`` numbers, (N,) or (N, K). Returns ``impulse`` and
    ``velocity_after`` (N, K, d), ``energy_change`` and ``status`` (N,); row ``i`` is
    ``resolve(w[i], v[i], friction[i], restitution[i], law, contacts=K)``.

    Returns arrays: ``impulse``, ``velocity_after`` (N, 2|3); ``energy_change``,
    ``work_compression``, ``work_restitution``, ``work_friction``, ``compression_impulse``
    (N,), NaN only where the law broke down or the row is invalid; ``status`` (uint8 codes
    into ``STATUSES``), ``sequence`` (codes into ``SEQUENCES`` / ``SEQUENCES_3D``),
    ``energy_gained`` (bool). The first invalid row raises ``ValueError("row I: <the CLI's
    message>")``, or with ``on_invalid="mark"`` gets status ``invalid``. Complex arrays raise
    ``TypeError``, integers too large for a float ``ValueError``. ``threads``: the number of
    worker threads, an integer from 1 to ``MAX_THREADS`` (256), default one per core; any
    other value raises ``ValueError``.
    """

def _check_threads(threads: int | None = None) -> int | None:
    """``threads`` checked as :func:`resolve_batch` checks it: None or an integer from 1 to
    ``MAX_THREADS``; anything else raises ``ValueError`` (``TypeError`` for a non-integer)."""

def sphere(
    mass: float = 1.0,
    radius: float = 1.0,
    *,
    speed: float | None = None,
    alpha: float | None = None,
    spin_ratio: float | None = None,
    velocity: tuple[float, float] | None = None,
    omega: float | None = None,
    friction: float = 0.4,
    restitution: float = 0.7,
    other: Body | None = None,
) -> BodyImpact:
    """A solid sphere (``I = 2/5 m r²``) striking a plane: paper A's state (speed ``v0``,
    ``alpha`` in radians from the normal, ``spin_ratio`` γ = ω0 r / v0; slip ``v0 (sin α + γ)``,
    eq. 6) or ``velocity``/``omega``. No arguments: the seed's case (α = 30°, μ = 0.4, e = 0.7)."""

def disc(
    mass: float = 1.0,
    radius: float = 1.0,
    *,
    speed: float | None = None,
    alpha: float | None = None,
    spin_ratio: float | None = None,
    velocity: tuple[float, float] | None = None,
    omega: float | None = None,
    friction: float = 0.4,
    restitution: float = 0.7,
    other: Body | None = None,
) -> BodyImpact:
    """A uniform disc (``I = ½ m r²``); the state as for :func:`sphere`."""

def rod(
    mass: float = 1.0,
    length: float = 1.0,
    angle: float = ...,
    *,
    velocity: tuple[float, float] = (0.5, -1.0),
    omega: float = 0.0,
    friction: float = 0.4,
    restitution: float = 0.7,
    other: Body | None = None,
) -> BodyImpact:
    """A uniform rod at ``angle`` (radians, 0 < θ < π; default 50°) from the surface, striking
    with its lower end: ``I = m L²/12``, contact at ``r = −(L/2)(cos θ, sin θ)``."""

def ellipse(
    mass: float = 1.0,
    a: float = 2.0,
    b: float = 1.0,
    angle: float = 0.0,
    *,
    velocity: tuple[float, float] = (0.5, -1.0),
    omega: float = 0.0,
    friction: float = 0.4,
    restitution: float = 0.7,
    other: Body | None = None,
) -> BodyImpact:
    """A uniform elliptical disc (``I = m (a² + b²)/4``), its ``a`` axis at ``angle`` from the surface."""

def body_impact(
    shape: str,
    mass: float = 1.0,
    *,
    speed: float | None = None,
    alpha: float | None = None,
    spin_ratio: float | None = None,
    velocity: tuple[float, float] | None = None,
    omega: float | None = None,
    friction: float = 0.4,
    restitution: float = 0.7,
    other: Body | None = None,
    **params: float | tuple[float, float] | None,
) -> BodyImpact:
    """A striking body A of any shape of :data:`SHAPES`, its parameters by keyword as scenario
    files name them (angles in radians: ``angle``). The motion: ``velocity``/``omega``, or paper
    A's ``speed``, ``alpha``, ``spin_ratio`` for a sphere or disc; without either, the seed's
    state for a round body and ``velocity=(0.5, -1)`` for any other."""

def rigid_body(
    mass: float,
    inertia: float,
    contact: tuple[float, float],
    *,
    velocity: tuple[float, float] = (0.5, -1.0),
    omega: float = 0.0,
    friction: float = 0.4,
    restitution: float = 0.7,
    other: Body | None = None,
) -> BodyImpact:
    """Any planar rigid body: mass, central inertia, contact point ``(r_t, r_n)`` from the centre."""

@overload
def mechanism(
    source: str,
    *,
    masses: Sequence[float] | None = None,
    lengths: Sequence[float] | None = None,
    radius: float | None = None,
    gravity: float | None = None,
    angles: Sequence[float] | None = None,
    rates: Sequence[float] | None = None,
    position: Sequence[float] | None = None,
    friction: float | None = None,
    restitution: float | None = None,
) -> MechanismImpact: ...
@overload
def mechanism(
    source: str | os.PathLike[str],
    *,
    floating_base: bool = False,
    contact: str | None = None,
    floor: float | None = None,
    gravity: float | None = None,
    friction: float | None = None,
    restitution: float | None = None,
) -> Mechanism: ...
def mechanism(source, **options):
    """A built-in mechanism by name (``double-pendulum``, ``sphere``, ``rod``) at a state, with
    the CLI's defaults and angles in radians (a :class:`MechanismImpact`); or a mechanism of
    one's own — a path to (or the text of) a mechanism file (``.toml``, planar or
    ``space = "3d"``) or a URDF robot (``.urdf``) — read once (a :class:`Mechanism`).

    ``floating_base`` (URDF): a free joint first, ``q = (x, y, z, qw, qx, qy, qz, …)``,
    ``u = (vx, vy, vz, wx, wy, wz, …)`` — the base origin's velocity and the angular velocity,
    both in the world frame. ``contact``: the default contact of the calls (a file's contact;
    a URDF link ``"LINK"`` or a point in its frame ``"LINK:x,y,z"``). ``floor``: the floor's
    height (default: a file's ``height``, else through the striking contact at each state).
    ``friction``, ``restitution``: defaults of the impacts (else the file's, else 0.5)."""

def double_pendulum(
    masses: tuple[float, float] = (1.0, 1.0),
    lengths: tuple[float, float] = (1.0, 1.0),
    angles: tuple[float, float] = ...,
    rates: tuple[float, float] = (-1.0, 2.0),
    gravity: float = 9.81,
    *,
    friction: float = 0.5,
    restitution: float = 0.5,
) -> MechanismImpact:
    """Kane & Levinson's double pendulum (θ = (30°, 0°) by default); Whittaker's T⁺/T⁻ = 1.26087."""

def compare(impact: BodyImpact | MechanismImpact | None = None, laws: Sequence[str] | None = None) -> list[dict[str, Any]]:
    """Every law side by side on one impact (default: the seed's sphere), as the ``results``
    of ``impax compare --json``."""

def rod_rows(
    angle: ArrayLike, speed: ArrayLike, direction: ArrayLike, omega: ArrayLike, mass: ArrayLike, length: ArrayLike
) -> tuple[np.ndarray, np.ndarray]:
    """``(W, v)`` of many uniform rods (the library's ``bodies::rod``), in parallel; used by
    :func:`impax.study.rod_problems`. A bad value raises ``ValueError("row I: ...")``."""

def sphere_rows(
    alpha: ArrayLike, spin_ratio: ArrayLike, speed: ArrayLike, mass: ArrayLike, radius: ArrayLike
) -> tuple[np.ndarray, np.ndarray]:
    """``(W, v)`` of paper A's sphere at many states (``bodies::sphere``, ``spin_state``), in
    parallel; used by :func:`impax.study.sphere_problems`."""
