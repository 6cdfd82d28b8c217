#!/usr/bin/env bash
# Stage: the spatial `lcp` at several contacts against PyBullet (a real 3D engine): boxes
# landing level on four corners and sliding along an axis agree ≤ 1e-6 with
# `impax compare box-flat`; spinning and oblique boxes, where Bullet's friction is not the
# exact circular cone, are printed (validation/pybullet/check.py; the pinned pybullet goes
# into .venv-pybullet/).
set -euo pipefail
cd "$(dirname "$0")/../.."
bash validation/pybullet/run.sh
