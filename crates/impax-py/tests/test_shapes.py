"""The planar shapes are the core's: `body_impact(shape, ...)` builds any of `SHAPES` by name
and equals the named constructors bit for bit; errors name the keyword the caller wrote
(`angle`, in radians, not the files' `angle_deg`); the known shapes are the command line's."""

from __future__ import annotations

import math

import pytest

import impax
from conftest import assert_close


def same(a, b):
    """Two impacts with the same W, v, energy and description, and the same compare rows."""
    assert a.w.tolist() == b.w.tolist()
    assert a.v == b.v
    assert a.energy_before == b.energy_before
    assert a.description == b.description
    assert impax.compare(a) == impax.compare(b)


def test_shapes_are_the_core_list():
    assert impax.SHAPES[:5] == ["sphere", "disc", "rod", "ellipse", "rigid"]
    assert len(set(impax.SHAPES)) == len(impax.SHAPES)


def test_body_impact_equals_the_named_constructors():
    same(impax.body_impact("sphere", radius=1.0), impax.sphere())
    same(
        impax.body_impact("disc", 2.0, radius=0.5, speed=1.5, alpha=-0.3, spin_ratio=0.2, friction=0.2),
        impax.disc(2.0, 0.5, speed=1.5, alpha=-0.3, spin_ratio=0.2, friction=0.2),
    )
    a = math.radians(35.0)
    same(
        impax.body_impact("rod", 2.0, length=1.5, angle=a, velocity=(0.8, -1.2), omega=1.5),
        impax.rod(2.0, 1.5, a, velocity=(0.8, -1.2), omega=1.5),
    )
    # Without a motion, a body that is not round has the constructors' default velocity.
    same(impax.body_impact("rod", length=1.0, angle=a), impax.rod(1.0, 1.0, a))
    same(
        impax.body_impact("ellipse", semi_axes=(2.0, 1.0), angle=0.4, restitution=0.3),
        impax.ellipse(1.0, 2.0, 1.0, 0.4, restitution=0.3),
    )
    same(
        impax.body_impact("rigid", 1.5, inertia=0.4, contact=(0.3, -1.0), velocity=(0.2, -1.0), omega=1.0),
        impax.rigid_body(1.5, 0.4, (0.3, -1.0), velocity=(0.2, -1.0), omega=1.0),
    )
    other = impax.body("rod", 2.0, length=1.0, angle=math.radians(60), velocity=(0.1, 0.0), omega=0.5)
    same(impax.body_impact("sphere", radius=1.0, other=other), impax.sphere(other=other))


def test_descriptions_show_radians():
    assert impax.sphere().description == "sphere m = 1, r = 1, v0 = 1, α = 0.5235987755982989 rad, γ = 0"
    assert impax.rod(1.0, 2.0, 0.5).description == "rod m = 1, L = 2, at 0.5 rad to the surface, v = (0.5, -1), ω = 0"
    assert impax.body("ellipse", semi_axes=(2.0, 1.0)).description == "ellipse m = 1, a = 2, b = 1, at 0 rad, v = (0, 0), ω = 0"


def test_body_impact_errors_name_the_keyword():
    cases = [
        (dict(shape="rod", length=1.0), "^angle: required for shape `rod`$"),
        (dict(shape="rod", length=1.0, angle=1.0, radius=1.0), "^radius: not a parameter of shape `rod`$"),
        (dict(shape="rod", length=1.0, angle_deg=50.0), "^angle_deg: not a parameter of any shape \\(known: radius, length, semi_axes, inertia, contact, angle\\b.*\\)$"),
        (dict(shape="ellipse", semi_axes=(1.0, 2.0, 3.0)), "^semi_axes: expected 2 numbers, got 3$"),
        (dict(shape="rod", length=1.0, angle=1.0, speed=1.0), "^speed: speed/alpha/spin_ratio describe round bodies"),
        (dict(shape="sphere", radius=1.0, alpha=2.0), "^alpha: must be in \\(-π/2, π/2\\) for the body to approach the surface, got 2$"),
        (dict(shape="rod", length=1.0, angle=math.pi), "^angle: .* a rod touches with one end only for 0 < angle < 180°$"),
        (dict(shape="disc", radius=-1.0), "^radius: -1(\\.0)? is out of range: must be > 0$"),
    ]
    for kwargs, message in cases:
        with pytest.raises(ValueError, match=message):
            impax.body_impact(**kwargs)
    with pytest.raises(ValueError) as err:
        impax.body_impact("cube")
    assert str(err.value) == "shape: unknown shape `cube` (known: " + ", ".join(impax.SHAPES) + ")"


def test_unknown_shape_lists_what_the_cli_lists(cli, tmp_path):
    toml = tmp_path / "cube.toml"
    toml.write_text("friction = 0.4\nrestitution = 0.7\n[body]\nshape = \"cube\"\nmass = 1.0\n")
    message = cli.error("compare", str(toml))
    assert message.endswith("body.shape: unknown shape `cube` (known: " + ", ".join(impax.SHAPES) + ")"), message


def test_box_from_the_core_alone(cli, tmp_path):
    """The planar box was added to the core's table only: here it is built by name, equals the
    rigid body with its inertia and lowest corner, and agrees with the command line."""
    assert "box" in impax.SHAPES
    m, a, b, theta = 2.0, 1.0, 0.5, math.radians(20.0)
    box = impax.body_impact("box", m, half_extents=(a, b), angle=theta, velocity=(0.3, -1.0), omega=0.2, friction=0.5, restitution=0.6)
    s, c = math.sin(theta), math.cos(theta)
    rigid = impax.rigid_body(m, m * (a * a + b * b) / 3.0, (-a * c + b * s, -a * s - b * c), velocity=(0.3, -1.0), omega=0.2, friction=0.5, restitution=0.6)
    for x, y in zip(box.w.ravel(), rigid.w.ravel()):
        assert abs(x - y) <= 1e-15
    assert all(abs(x - y) <= 1e-15 for x, y in zip(box.v, rigid.v))
    assert box.description == f"box m = 2, a = 1, b = 0.5, at {theta} rad, v = (0.3, -1), ω = 0.2"
    toml = tmp_path / "box.toml"
    toml.write_text(
        "friction = 0.5\nrestitution = 0.6\n[body]\nshape = \"box\"\nmass = 2.0\nhalf_extents = [1.0, 0.5]\n"
        "angle_deg = 20\nvelocity = [0.3, -1.0]\nomega = 0.2\n"
    )
    ref = cli.json("compare", str(toml))
    for py, r in zip(impax.compare(box), ref["results"]):
        assert_close(py, r, r["law"])
    # Flat on an edge the corner is needed, as the keyword `corner` (signs in the box's frame).
    with pytest.raises(ValueError, match="^corner: an edge touches, not one corner"):
        impax.body_impact("box", half_extents=(a, b))
    flat = impax.body_impact("box", half_extents=(a, b), corner=(1, -1), velocity=(0.0, -1.0))
    assert flat.w[0, 1] > 0  # W_tn = −r_t r_n / I with r = (a, −b)
    # As the struck body B of a sphere, met at its highest corner.
    pair = impax.sphere(other=impax.body("box", 3.0, half_extents=(0.5, 0.5), angle=0.3))
    assert pair.description.endswith("striking box m = 3, a = 0.5, b = 0.5, at 0.3 rad, v = (0, 0), ω = 0")
    with pytest.raises(ValueError, match="^half_extents: expected 2 numbers, got 1$"):
        impax.body("box", half_extents=(1.0,))
