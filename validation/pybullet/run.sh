#!/usr/bin/env bash
# Compare impax's spatial `lcp` at several contacts with a real engine (PyBullet 3.2.6,
# Bullet 3): creates the virtual environment .venv-pybullet/ (gitignored) from the pinned
# requirements.txt, builds the `impax` binary with cargo (honouring CARGO_TARGET_DIR), and
# runs check.py, which prints the deviations and exits non-zero above 1e-6 where the engine's
# friction is the exact cone's (module docs of check.py).
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
cd "$root"
venv="$root/.venv-pybullet"
if [[ ! -x "$venv/bin/python" ]]; then
    python3 -m venv "$venv"
fi
"$venv/bin/python" -m pip install --quiet --disable-pip-version-check \
    -r validation/pybullet/requirements.txt
bin="$(cargo build --quiet --bin impax --message-format=json-render-diagnostics |
    python3 -c '
import json, sys
for line in sys.stdin:
    m = json.loads(line)
    if m.get("reason") == "compiler-artifact" and "bin" in m["target"]["kind"] \
            and m["target"]["name"] == "impax" and m.get("executable"):
        print(m["executable"])
')"
if [[ -z "$bin" || ! -x "$bin" ]]; then
    echo "validation/pybullet/run.sh: cargo did not report the impax binary" >&2
    exit 1
fi
"$venv/bin/python" validation/pybullet/check.py "$bin"
