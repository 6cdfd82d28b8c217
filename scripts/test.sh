#!/usr/bin/env bash
# The whole test suite (the README's test command): the Rust workspace, the optional-feature
# tests, then every stage in scripts/test.d/ in name order (each stage installs what it needs
# from the project's own pinned lists, into folders inside the checkout).
#
#   bash scripts/test.sh            # everything
#   bash scripts/test.sh --rust     # the Rust workspace only (cargo test --workspace, with the
#                                   # core's serde feature: one build for both)
set -euo pipefail
cd "$(dirname "$0")/.."

# The core's optional `serde` feature only adds derives: testing the workspace with it on runs
# its round trips (tests/serde.rs, the lib.rs example) in the same build, not a second one.
echo "== cargo test --workspace --features impax/serde"
cargo test --workspace --features impax/serde

if [[ "${1:-}" == "--rust" ]]; then
    exit 0
fi

echo "== Parquet output (feature \`parquet\`) (at $SECONDS s)"
cargo test -p impax-cli --features parquet --test cli parquet::

for stage in scripts/test.d/*.sh; do
    [[ -e "$stage" ]] || continue
    echo "== stage $(basename "$stage") (at $SECONDS s)"
    bash "$stage"
done
