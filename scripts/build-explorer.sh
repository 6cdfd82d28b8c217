#!/usr/bin/env bash
# Build the explorer page's WebAssembly module from crates/impax-wasm and copy it to
# web/impax_wasm.wasm (the file `impax explore` embeds). Needs only rustup and cargo:
#
#   bash scripts/build-explorer.sh           # the release module, and its sources' fingerprint
#                                            # in crates/impax-wasm/module-sources.sha256 (commit both)
#   bash scripts/build-explorer.sh --check   # exit 0 if the committed module was built from
#                                            # today's sources (their fingerprint), else a
#                                            # notice and exit 1
#   bash scripts/build-explorer.sh --fast    # a quicker build (no LTO, 16 codegen units) for a
#                                            # test run; the fingerprint is left alone
#
# Paths are remapped so that the module does not depend on where the checkout or the cargo
# home is: the same toolchain and sources give the same bytes.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
target=wasm32-unknown-unknown
mode=${1:-}

# The fingerprint of what the module is built from: the core's and the module crate's sources
# and manifests, the workspace manifest and the lock file (not the tests, benches or docs).
fingerprint() {
    git ls-files -z -- crates/impax/src crates/impax/Cargo.toml crates/impax-wasm/src \
        crates/impax-wasm/Cargo.toml Cargo.toml Cargo.lock |
        sort -z | xargs -0 sha256sum | sha256sum | cut -d' ' -f1
}

if [[ "$mode" == "--check" ]]; then
    if ! git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
        echo "(not a git checkout: the module's fingerprint is not checked)"
        exit 1
    elif [[ "$(fingerprint)" != "$(cat crates/impax-wasm/module-sources.sha256 2>/dev/null)" ]]; then
        echo "notice: the committed web/impax_wasm.wasm predates today's sources (the fingerprint in"
        echo "        crates/impax-wasm/module-sources.sha256 differs): rebuild it with"
        echo "        bash scripts/build-explorer.sh and commit both files"
        exit 1
    else
        echo "web/impax_wasm.wasm: built from today's sources"
    fi
    exit 0
fi
if [[ -n "$mode" && "$mode" != "--fast" ]]; then
    echo "scripts/build-explorer.sh: unknown option $mode (--check or --fast)" >&2
    exit 2
fi

if ! rustup target list --installed 2>/dev/null | grep -qx "$target"; then
    rustup target add "$target"
fi

cargo_home=${CARGO_HOME:-$HOME/.cargo}
export CARGO_TARGET_WASM32_UNKNOWN_UNKNOWN_RUSTFLAGS="--remap-path-prefix=$root=impax --remap-path-prefix=$cargo_home=cargo"
if [[ "$mode" == "--fast" ]]; then
    CARGO_PROFILE_RELEASE_LTO=off CARGO_PROFILE_RELEASE_CODEGEN_UNITS=16 \
        cargo build -p impax-wasm --release --target "$target" --locked
else
    cargo build -p impax-wasm --release --target "$target" --locked
fi

out_dir=${CARGO_TARGET_DIR:-target}
cp "$out_dir/$target/release/impax_wasm.wasm" web/impax_wasm.wasm
echo "web/impax_wasm.wasm: $(wc -c < web/impax_wasm.wasm) bytes"
if [[ "$mode" != "--fast" ]] && git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
    fingerprint > crates/impax-wasm/module-sources.sha256
fi
