#!/usr/bin/env bash
# The whole test suite (the README's test command): the Rust workspace, the optional-feature
# tests, then every stage in scripts/test.d/ in name order (each stage installs what it needs
# from the project's own pinned lists, into folders inside the checkout).
#
#   bash scripts/test.sh            # everything
#   bash scripts/test.sh --rust     # the Rust workspace only (what `cargo test --workspace` runs)
set -euo pipefail
cd "$(dirname "$0")/.."

echo "== cargo test --workspace"
cargo test --workspace

if [[ "${1:-}" == "--rust" ]]; then
    exit 0
fi

echo "== Parquet output (feature \`parquet\`) (at $SECONDS s)"
cargo test -p impax-cli --features parquet --test cli parquet::

echo "== serde round trips (feature \`serde\`) (at $SECONDS s)"
cargo test -p impax --features serde --test serde
cargo test -p impax --features serde --doc -- src/lib.rs

for stage in scripts/test.d/*.sh; do
    [[ -e "$stage" ]] || continue
    echo "== stage $(basename "$stage") (at $SECONDS s)"
    bash "$stage"
done
