"""impax — rigid-body impact with friction, on numpy arrays.

Every classical frictional impact law side by side — ``whittaker`` (Newton restitution with
Coulomb friction on the total impulses, paper A eq. 7), ``two-phase`` (paper A §3), ``smith``
(Smith 1991), ``brach`` (Brach 1989) and the exact Darboux–Keller integration in normal
impulse terminated by ``newton``, ``poisson`` or ``energetic`` (Stronge) restitution — with
the energy audit of each and a verdict (energy gained: Kane's paradox).

Contact space (theory §1): ``W = J M⁻¹ Jᵀ`` (2×2 planar, 3×3 spatial), tangent(s) first and
normal last; approach means ``v_n < 0``; the impulse ``p`` acts on the moving body and
``v(p) = v⁻ + W p``; ``ΔT = v⁻·p + ½ pᵀ W p``.

* :func:`resolve` — one problem, an :class:`Outcome` (with ``contacts=K``: a planar problem
  with ``K`` contacts at once, a :class:`MultiOutcome`);
* :func:`resolve_batch` — many problems on numpy arrays, in parallel with the GIL released;
* :func:`sphere`, :func:`disc`, :func:`rod`, :func:`ellipse`, :func:`rigid_body`,
  :func:`body_impact` (any shape of :data:`SHAPES` by name), :func:`double_pendulum`,
  :func:`mechanism` — bodies and mechanisms producing problems (:func:`body` — a struck free
  body, the ``other=`` of a body: body against body);
* :func:`mechanism` with a path (or text) of a mechanism file or a URDF robot — a
  :class:`Mechanism` read once: ``M(q)``, contact Jacobians, impacts as the command line's
  records and batches of states over numpy arrays;
* :func:`compare` — every law side by side, as ``impax compare --json``;
* :mod:`impax.study` — parameter spaces (grids, random samples) of built-in scenarios, run
  in chunks, reduced;
* :mod:`impax.dask` — the same sweeps on a Dask cluster (needs ``dask[distributed]``).

Errors are ``ValueError`` with the command line's message (a batch names the row); an
argument of the wrong type (a complex number where a real one is expected) is a ``TypeError``
naming it.
"""

from ._impax import (
    CONTACT_SPACE_LAWS,
    LAWS,
    MAX_THREADS,
    MECHANISMS,
    MULTI_CONTACT_LAWS,
    SEQUENCES,
    SEQUENCES_3D,
    SHAPES,
    SPATIAL_LAWS,
    STATUSES,
    Body,
    BodyImpact,
    Mechanism,
    MechanismImpact,
    MultiOutcome,
    Outcome,
    __version__,
    body,
    body_impact,
    compare,
    disc,
    double_pendulum,
    ellipse,
    mechanism,
    resolve,
    resolve_batch,
    rigid_body,
    rod,
    sphere,
)
from . import study

__all__ = [
    "CONTACT_SPACE_LAWS",
    "LAWS",
    "MAX_THREADS",
    "MECHANISMS",
    "MULTI_CONTACT_LAWS",
    "SEQUENCES",
    "SEQUENCES_3D",
    "SHAPES",
    "SPATIAL_LAWS",
    "STATUSES",
    "Body",
    "BodyImpact",
    "Mechanism",
    "MechanismImpact",
    "MultiOutcome",
    "Outcome",
    "__version__",
    "body",
    "body_impact",
    "compare",
    "disc",
    "double_pendulum",
    "ellipse",
    "mechanism",
    "resolve",
    "resolve_batch",
    "rigid_body",
    "rod",
    "sphere",
    "study",
]
