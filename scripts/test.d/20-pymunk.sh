#!/usr/bin/env bash
# Stage: the `lcp` law against pymunk (a real engine), ≥ 50 rod drops, a double pendulum
# on pivot joints, and rods, boxes and rocking blocks on two contacts at once (`--contacts 2`),
# agreement ≤ 1e-6 with the largest deviation printed
# (validation/pymunk/check.py; the pinned pymunk goes into .venv-pymunk/).
set -euo pipefail
cd "$(dirname "$0")/../.."
bash validation/pymunk/run.sh
