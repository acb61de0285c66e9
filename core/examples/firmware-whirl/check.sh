#!/usr/bin/env bash
# Builds the firmware-whirl example, runs it on QEMU (the runner of .cargo/config.toml) and
# checks that it exited 0 (every sample stepped, none dropped) and logged the expected number
# of defmt frames: a start line, one per step, a closing line. The frames are counted without
# decoding: each ends in a zero byte, which the rzCOBS encoding keeps out of the frame; the
# stream also begins with one.
# With `defmt-print` installed, the log is decoded and shown too.
set -euo pipefail
cd "$(dirname "$0")"
steps=$(sed -n 's/^const STEPS: u32 = \([0-9_]*\);$/\1/p' src/main.rs | tr -d _)
log=$(mktemp)
trap 'rm -f "$log"' EXIT
cargo build --release
status=0
cargo run --release --quiet >"$log" || status=$?
zeros=$(tr -cd '\000' <"$log" | wc -c)
leading=$(head -c 1 "$log" | tr -cd '\000' | wc -c)
frames=$((zeros - leading))
if command -v defmt-print >/dev/null 2>&1; then
  defmt-print -e target/thumbv7em-none-eabihf/release/firmware-whirl <"$log" | tail -3
fi
echo "firmware-whirl: exit code $status, $frames defmt frames (expected $((steps + 2)))"
[ "$status" -eq 0 ] && [ "$frames" -eq $((steps + 2)) ]
