#!/usr/bin/env bash
# Stage: the Python bindings. Creates the virtual environment .venv-ci/ (gitignored) from the
# pinned crates/impax-py/requirements-test.txt, builds the wheel with maturin (profile `ci`:
# optimised, parallel code generation), installs it, builds the `impax` binary the tests
# compare against, and runs pytest on crates/impax-py/tests (agreement with the CLI's JSON,
# bad input, physics identities, Dask LocalCluster and Parquet). No test times anything: the
# batch speed-up is the benchmark crates/impax-py/bench/batch_speed.py, which prints figures.
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
cd "$root"
venv="$root/.venv-ci"
if [[ ! -x "$venv/bin/python" ]]; then
    python3 -m venv "$venv"
fi
"$venv/bin/python" -m pip install --quiet --disable-pip-version-check \
    -r crates/impax-py/requirements-test.txt
wheels="$(mktemp -d)"
trap 'rm -rf "$wheels"' EXIT
(cd crates/impax-py && "$venv/bin/maturin" build --quiet --profile ci \
    --interpreter "$venv/bin/python" --out "$wheels")
"$venv/bin/python" -m pip install --quiet --disable-pip-version-check --force-reinstall \
    --no-deps "$wheels"/impax-*.whl
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
    echo "scripts/test.d/30-python.sh: cargo did not report the impax binary" >&2
    exit 1
fi
# From the tests' folder, so that `import impax` is the installed wheel, not the sources.
cd crates/impax-py/tests
IMPAX_BIN="$bin" "$venv/bin/python" -m pytest -q -p no:cacheprovider -s .
