#!/usr/bin/env bash
# Stage: robots against Pinocchio (a rigid-body dynamics library): solo12, ur5, go2, anymal
# (B and C), panda and talos_reduced from example-robot-data, fixed and floating base, at
# random states — M(q), the contact point's Jacobian, W = J M⁻¹ Jᵀ, v⁻ = J u and
# M (u⁺ − u⁻) = Jᵀ p agree ≤ 1e-10 (relative), every other robot of the package impax reads
# too, with the largest deviations and the files it cannot read (and why) printed; then the
# speed of a solo12 foot impact beside Pinocchio's crba + Jacobian + Cholesky, printed only
# (validation/pinocchio/check.py and speed.py; the pinned pin and example-robot-data go into
# .venv-pinocchio/).
set -euo pipefail
cd "$(dirname "$0")/../.."
bash validation/pinocchio/run.sh
