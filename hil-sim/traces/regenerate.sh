#!/usr/bin/env bash
# Regenerates the bundled traces from scratch with the shaft simulator (`bearing shaft run`)
# and hil-sim's converter. Run from anywhere; needs only cargo. See README.md here for what
# each trace is and why these parameters.
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
cd "$root"
cargo build --release -p bearing-cli --bin bearing -p bearing-hil --bin hil-sim
bearing="$root/target/release/bearing"
hil="$root/target/release/hil-sim"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

# Hub-motor shaft (docs/physics.md §6.2), regression film: run-up 1000 -> 2000 rpm in 1 s after
# 0.1 s settling at 1000 rpm. The gear-mesh order (17x) crosses the first lateral mode
# (~2620 rad/s, `bearing shaft campbell`) near 1470 rpm. Integrated at dt = 10 us, every 5th
# step kept: 20 kHz, 20 000 samples. Newton stall bound 3 nm: at the resonance the default
# 1 nm stalls on the core's f32 force scatter (the run reports resolution-limited steps).
"$bearing" shaft run --config configs/shaft_hub_motor.toml \
  --speed-rpm 1000 --speed-end-rpm 2000 --settle 0.1 --duration 1.0 \
  --dt 1e-5 --record-every 5 --newton-resolution 3e-9 \
  --out "$work/hub" --json > "$work/hub.json"
"$hil" trace convert "$work/hub_b0_trace.csv" hil-sim/traces/hub_motor_runup.bin

# NU 205 rig (docs/physics.md §6.1), regression film: the last 0.3 s of the 0 -> 15 000 rpm / 4 s
# sweep at its rate (3750 rpm/s), 13 875 -> 15 000 rpm, after 0.1 s settling at 13 875 rpm,
# sampled at the rig's 100 kHz: 30 000 samples (the whole sweep would be 400 000, 11 MB).
"$bearing" shaft run --config configs/shaft_nu205_rig.toml \
  --speed-rpm 13875 --speed-end-rpm 15000 --settle 0.1 --duration 0.3 \
  --dt 1e-5 --record-every 1 \
  --out "$work/nu205" --json > "$work/nu205.json"
"$hil" trace convert "$work/nu205_b0_trace.csv" hil-sim/traces/nu205_sweep.bin

"$hil" trace info hil-sim/traces/hub_motor_runup.bin
"$hil" trace info hil-sim/traces/nu205_sweep.bin
