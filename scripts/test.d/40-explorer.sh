#!/usr/bin/env bash
# The explorer page in a real browser: Debian's chromium (installed with apt if missing; no
# test downloads a browser), playwright-core from web/test/package-lock.json (npm ci, into
# web/test/node_modules), the page served by `impax explore`.
#
# The WebAssembly module is rebuilt from the sources first and `impax` rebuilt to embed it, so
# the test always runs today's core; a committed web/impax_wasm.wasm that differs only earns a
# notice (rebuild it with scripts/build-explorer.sh and commit it). Under CI=true (a throwaway
# clone) the committed module is judged by its sources' fingerprint
# (crates/impax-wasm/module-sources.sha256): built from today's sources, it is the one tested
# (the module the checkout ships); else a module is built the quicker way (`--fast`: no LTO,
# 16 codegen units) and tested.
set -euo pipefail
cd "$(dirname "$0")/../.."

as_root() {
    if [[ $(id -u) -eq 0 ]]; then "$@"; else sudo "$@"; fi
}
apt_install() {
    as_root apt-get update -qq
    as_root env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "$@"
}

if [[ ! -x /usr/bin/chromium ]]; then
    echo "-- installing Debian's chromium"
    apt_install chromium
fi
if ! command -v node >/dev/null || ! command -v npm >/dev/null; then
    echo "-- installing node and npm"
    apt_install nodejs npm
fi

echo "-- the WebAssembly module (scripts/build-explorer.sh) (stage at $SECONDS s)"
if [[ "${CI:-}" == "true" ]]; then
    if ! bash scripts/build-explorer.sh --check; then
        bash scripts/build-explorer.sh --fast
    fi
else
    committed=$(mktemp)
    trap 'rm -f "$committed"' EXIT
    cp web/impax_wasm.wasm "$committed"
    bash scripts/build-explorer.sh
    if ! cmp -s "$committed" web/impax_wasm.wasm; then
        echo "notice: the committed web/impax_wasm.wasm differs from the module built from today's sources;"
        echo "        the test uses the fresh one (run bash scripts/build-explorer.sh and commit it)"
    fi
fi

echo "-- impax, embedding the module (stage at $SECONDS s)"
cargo build -p impax-cli --locked
bin="${CARGO_TARGET_DIR:-target}/debug/impax"

echo "-- playwright-core (npm ci in web/test) (stage at $SECONDS s)"
(cd web/test && npm ci --no-audit --no-fund --loglevel=error)

echo "-- the page in chromium (stage at $SECONDS s)"
IMPAX_BIN="$bin" CHROMIUM=/usr/bin/chromium node --test web/test/e2e.test.mjs
echo "-- the explorer passed (stage at $SECONDS s)"
