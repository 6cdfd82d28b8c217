#!/usr/bin/env bash
# Coverage-guided fuzzing (libFuzzer through cargo-fuzz) of the inputs users write: contact
# problems with every law, the numeric lists of the command line, scenario / simulation /
# mechanism TOML files through `impax compare`, `simulate`, `audit` and `conserved`. Each
# target checks the command line's contract (exit 0 or 2; one error line; no non-finite or
# null number where a number is documented; energetic never gains energy).
#
#   bash scripts/fuzz.sh            # 15 s per target
#   bash scripts/fuzz.sh 600        # 10 min per target
#   bash scripts/fuzz.sh 60 numbers # one target
#   bash scripts/fuzz.sh --dev 10   # a debug build (built in about half the time, runs about
#                                   # six times fewer inputs a second; an input that takes
#                                   # seconds optimised can pass the 20 s timeout)
#
# cargo-fuzz (pinned) is installed into .tools/ on first use (a debug build: it only drives
# cargo); libFuzzer builds need nightly flags, which stable Rust accepts with
# RUSTC_BOOTSTRAP=1. The seed corpus (fuzz/corpus/, from
# the documented examples) is read only; what the fuzzer finds goes to fuzz/work/, and a
# failing input to fuzz/artifacts/<target>/ (reproduce: cargo fuzz run -s none TARGET FILE).
set -euo pipefail
cd "$(dirname "$0")/.."
# (16 codegen units: the optimised build in half the time on two cores, for a few per cent
# fewer executions a second.)
build=(--codegen-units 16)
if [[ "${1:-}" == "--dev" ]]; then
    build=(--dev)
    shift
fi
seconds="${1:-15}"
targets=("${@:2}")
if [[ ${#targets[@]} -eq 0 ]]; then
    targets=(contact_problem numbers scenario_toml mechanism_toml)
fi
version=0.13.2
tools="$PWD/.tools"
if ! "$tools/bin/cargo-fuzz" --version 2>/dev/null | grep -q " $version"; then
    echo "== installing cargo-fuzz $version into .tools/"
    cargo install cargo-fuzz --version "$version" --locked --root "$tools" --quiet --debug
fi
export PATH="$tools/bin:$PATH" RUSTC_BOOTSTRAP=1
echo "== building the fuzz targets"
cargo fuzz build -s none "${build[@]}"
for target in "${targets[@]}"; do
    mkdir -p "fuzz/work/$target"
    rm -rf "fuzz/artifacts/$target"
    echo "== fuzzing $target for $seconds s"
    cargo fuzz run -s none "${build[@]}" "$target" "fuzz/work/$target" "fuzz/corpus/$target" -- \
        -max_total_time="$seconds" -timeout=20 -rss_limit_mb=4096 -print_final_stats=1 \
        2>&1 | grep -E '^(Done|stat::number_of_executed_units|stat::peak_rss_mb)|panicked|ERROR|SUMMARY|Test unit written|(left|right):|assertion' || true
    if compgen -G "fuzz/artifacts/$target/*" >/dev/null; then
        echo "scripts/fuzz.sh: $target found a failing input (fuzz/artifacts/$target/)" >&2
        exit 1
    fi
done
echo "== fuzzing passed"
