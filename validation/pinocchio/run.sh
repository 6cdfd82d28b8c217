#!/usr/bin/env bash
# Compare impax's robots with Pinocchio (pin 4.1.0) on the robots of example-robot-data
# 6.0.0: creates the virtual environment .venv-pinocchio/ (gitignored) from the pinned
# requirements.txt, builds impax's wheel with maturin (profile `ci`, as the Python stage;
# honouring CARGO_TARGET_DIR) and installs it there, then runs check.py — M(q), the contact
# Jacobians, W, v⁻ and the momentum balance over random states, fixed and floating base;
# exit status non-zero above 1e-10 — and speed.py, which prints timings beside Pinocchio's
# (figures only, nothing asserted).
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
cd "$root"
venv="$root/.venv-pinocchio"
if [[ ! -x "$venv/bin/python" ]]; then
    python3 -m venv "$venv"
fi
"$venv/bin/python" -m pip install --quiet --disable-pip-version-check \
    -r validation/pinocchio/requirements.txt
wheels="$(mktemp -d)"
trap 'rm -rf "$wheels"' EXIT
(cd crates/impax-py && "$venv/bin/maturin" build --quiet --profile ci \
    --interpreter "$venv/bin/python" --out "$wheels")
"$venv/bin/python" -m pip install --quiet --disable-pip-version-check --force-reinstall \
    --no-deps "$wheels"/impax-*.whl
"$venv/bin/python" validation/pinocchio/check.py
echo
"$venv/bin/python" validation/pinocchio/speed.py
