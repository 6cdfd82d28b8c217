"""`impax.mechanism(name, ...)` is the core's description of a built-in mechanism with its
angles in radians: its defaults are the command line's bit for bit, its errors name the
keywords (`angles`, not the files' `angles_deg`)."""

from __future__ import annotations

import math

import pytest

import impax


@pytest.mark.parametrize("name", ["double-pendulum", "sphere", "rod"])
def test_defaults_are_the_command_line_defaults_bit_for_bit(cli, tmp_path, name):
    toml = tmp_path / "mechanism.toml"
    toml.write_text(f'mechanism = "{name}"\n')
    ref = cli.json("compare", str(toml))
    m = impax.mechanism(name)
    assert m.w.tolist() == ref["problem"]["w"]
    assert list(m.v) == [ref["problem"]["v"]["t"], ref["problem"]["v"]["n"]]
    assert m.energy_before == ref["energy_before"]
    assert m.name == name


def test_descriptions_show_radians():
    d = impax.mechanism("double-pendulum", angles=[0.5, 0.0]).description
    assert "θ1 = 0.5 rad, θ2 = 0 rad" in d, d
    d = impax.mechanism("rod", angles=[0.7]).description
    assert "θ = 0.7 rad from the floor" in d, d


def test_errors_name_the_keywords():
    with pytest.raises(ValueError, match=r"^angles\[0\]: must be between -2π and 2π radians, got 7$"):
        impax.mechanism("double-pendulum", angles=[7.0, 0.0])
    with pytest.raises(ValueError, match=r"^angles: needs 1 value\(s\), got 2$"):
        impax.mechanism("rod", angles=[0.5, 0.5])
    with pytest.raises(ValueError, match=r"^cart-pendulum: has no contact point to strike \(try `impax conserved cart-pendulum`\)$"):
        impax.mechanism("cart-pendulum", angles=[math.radians(20)])
