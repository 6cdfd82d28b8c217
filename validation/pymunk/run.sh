#!/usr/bin/env bash
# Validate impax's `lcp` law against a real engine (pymunk 7.3.1, Chipmunk 2): creates the
# virtual environment .venv-pymunk/ (gitignored) from the pinned requirements.txt, builds the
# `impax` binary with cargo (honouring CARGO_TARGET_DIR; the path comes from cargo itself),
# and runs check.py, which prints the largest deviation and exits non-zero above 1e-6.
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
cd "$root"
venv="$root/.venv-pymunk"
if [[ ! -x "$venv/bin/python" ]]; then
    python3 -m venv "$venv"
fi
"$venv/bin/python" -m pip install --quiet --disable-pip-version-check \
    -r validation/pymunk/requirements.txt
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
    echo "validation/pymunk/run.sh: cargo did not report the impax binary" >&2
    exit 1
fi
"$venv/bin/python" validation/pymunk/check.py "$bin"
