#!/usr/bin/env bash
# Build the explorer page's WebAssembly module from crates/impax-wasm and copy it to
# web/impax_wasm.wasm (the file `impax explore` embeds). Needs only rustup and cargo:
#
#   bash scripts/build-explorer.sh
#
# Paths are remapped so that the module does not depend on where the checkout or the cargo
# home is: the same toolchain and sources give the same bytes.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
target=wasm32-unknown-unknown

if ! rustup target list --installed 2>/dev/null | grep -qx "$target"; then
    rustup target add "$target"
fi

cargo_home=${CARGO_HOME:-$HOME/.cargo}
export CARGO_TARGET_WASM32_UNKNOWN_UNKNOWN_RUSTFLAGS="--remap-path-prefix=$root=impax --remap-path-prefix=$cargo_home=cargo"
cargo build -p impax-wasm --release --target "$target" --locked

out_dir=${CARGO_TARGET_DIR:-target}
cp "$out_dir/$target/release/impax_wasm.wasm" web/impax_wasm.wasm
echo "web/impax_wasm.wasm: $(wc -c < web/impax_wasm.wasm) bytes"
