#!/usr/bin/env bash
# Builds the fuzz targets and fuzzes each for SECONDS, one after the other (one process each).
#
#     fuzz/run.sh SECONDS [TARGET...]    # all five targets when none is named
#
# The build passes the flags `cargo +nightly fuzz build` passes (cargo-fuzz 0.13.2,
# src/project.rs: SanitizerCoverage with inline 8-bit counters, PC table, compare tracing and
# stack depth; AddressSanitizer; `--cfg fuzzing`; debug assertions, hence overflow checks; one
# codegen unit; line tables) into the directory cargo-fuzz uses, so `cargo +nightly fuzz run
# <target>` reuses this build, and neither needs the other: cargo-fuzz itself is not needed here
# (installing it takes ≈ 9 min). libFuzzer (libfuzzer-sys) is linked into each binary.
#
# Each target runs with a fixed seed (FUZZ_SEED, 1) into a scratch corpus (FUZZ_SCRATCH/<target>,
# a temporary directory removed afterwards when FUZZ_SCRATCH is unset) that starts from
# corpus/<target>; nothing is written to corpus/. The last status line and libFuzzer's final
# statistics are printed per target. A crash, a panic, a sanitizer report or an input running
# longer than 60 s stops the script with status 1; the input is in artifacts/<target>/.
set -euo pipefail
cd "$(dirname "$0")"

all=(trace_binary trace_csv bearing_toml shaft_toml core_step)
seconds=${1:-}
if ! [[ $seconds =~ ^[1-9][0-9]{0,5}$ ]]; then
  echo "fuzz/run.sh: SECONDS must be a whole number from 1 to 999999, got '$seconds'" >&2
  echo "usage: fuzz/run.sh SECONDS [TARGET...]   (targets: ${all[*]})" >&2
  exit 2
fi
shift
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=("${all[@]}")
for target in "${targets[@]}"; do
  if [[ " ${all[*]} " != *" $target "* ]]; then
    echo "fuzz/run.sh: unknown target '$target' (targets: ${all[*]})" >&2
    exit 2
  fi
done

triple=x86_64-unknown-linux-gnu
flags=(
  -Cpasses=sancov-module
  -Cllvm-args=-sanitizer-coverage-level=4
  -Cllvm-args=-sanitizer-coverage-inline-8bit-counters
  -Cllvm-args=-sanitizer-coverage-pc-table
  -Cllvm-args=-sanitizer-coverage-trace-compares
  --cfg fuzzing
  -Cllvm-args=-simplifycfg-branch-fold-threshold=0
  -Zsanitizer=address
  -Cllvm-args=-sanitizer-coverage-stack-depth
  -Cdebug-assertions
  -Ccodegen-units=1
)
# `--target` keeps these flags away from build scripts and proc macros, as cargo-fuzz does.
RUSTFLAGS="${flags[*]}" cargo +nightly build --release --target "$triple" \
  --config 'profile.release.debug="line-tables-only"' --bins

scratch=${FUZZ_SCRATCH:-}
if [ -z "$scratch" ]; then
  scratch=$(mktemp -d)
  trap 'rm -rf "$scratch"' EXIT
fi
export ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_odr_violation=0"
for target in "${targets[@]}"; do
  mkdir -p "$scratch/$target" "artifacts/$target"
  log="$scratch/$target.log"
  echo "== $target: ${seconds} s"
  status=0
  "target/$triple/release/$target" "$scratch/$target" "corpus/$target" \
    -max_total_time="$seconds" -seed="${FUZZ_SEED:-1}" -timeout=60 -print_final_stats=1 \
    -artifact_prefix="artifacts/$target/" >"$log" 2>&1 || status=$?
  if [ "$status" -ne 0 ]; then
    tail -n 60 "$log"
    echo "fuzz/run.sh: $target failed (status $status); the input is in fuzz/artifacts/$target/" >&2
    exit 1
  fi
  grep -E '^#[0-9]+' "$log" | tail -n 1
  grep -E '^(Done |stat::)' "$log"
done
