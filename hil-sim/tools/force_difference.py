#!/usr/bin/env python3
"""Bearing-force difference between two builds of the HIL firmware over the bundled traces.

Runs each firmware ELF under QEMU (as `hil-sim qemu` does) on `hil-sim/traces/hub_motor_runup.bin`
and `nu205_sweep.bin`, reads every step's outputs back (`outputs.bin`,
`hil-sim/kernel/src/outputs.rs`) and reports, per trace and over both, the p99 and maximum of
|ΔF|/max(|F_a|, mean roller load of a): the force of build b against that of build a, divided
by the larger of a's force and a's mean roller load (the normalisation of `hil-sim replay`'s
force verdict, which keeps a preloaded ring whose resultant nearly cancels from dividing by
almost nothing). Also the instructions per step of each (min, max).

    python3 hil-sim/tools/force_difference.py BEFORE.elf AFTER.elf [--film int]
"""

import argparse
import math
import os
import shutil
import struct
import subprocess
import sys
import tempfile

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
TRACES = ["hub_motor_runup.bin", "nu205_sweep.bin"]


def run(elf: str, trace: str, film: str):
    """(instructions, F_x, F_y, mean roller load) of every step of `elf` on `trace`."""
    with tempfile.TemporaryDirectory() as scratch:
        shutil.copy(trace, os.path.join(scratch, "trace.bin"))
        with open(os.path.join(scratch, "film.txt"), "w") as f:
            f.write(film)
        done = subprocess.run(
            ["qemu-system-arm", "-machine", "netduinoplus2", "-cpu", "cortex-m4",
             "-nographic", "-monitor", "none", "-serial", "none",
             "-semihosting-config", "enable=on,target=native", "-icount", "shift=0",
             "-kernel", elf],
            cwd=scratch, stdout=subprocess.DEVNULL, timeout=1800)
        if done.returncode != 0:
            sys.exit(f"{elf} exited with code {done.returncode} on {trace}")
        data = open(os.path.join(scratch, "outputs.bin"), "rb").read()
    if data[:8] != b"BRGSTEPS":
        sys.exit("outputs.bin: bad magic")
    rollers, count = struct.unpack_from("<HI", data, 10)
    # A step record (`hil-sim/kernel/src/outputs.rs`): instructions, SysTick and friction
    # instructions (u32), F_x, F_y, cage angle and five friction fields (f32), then per roller
    # its load, two films and approach (f32) and two source bytes.
    fixed, per_roller = 44, 18
    size = fixed + rollers * per_roller
    steps = []
    for k in range(count):
        at = 16 + k * size
        instructions, _, _, fx, fy = struct.unpack_from("<IIIff", data, at)
        loads = [struct.unpack_from("<f", data, at + fixed + per_roller * j)[0]
                 for j in range(rollers)]
        steps.append((instructions, fx, fy, sum(loads) / rollers))
    return steps


def percentile(sorted_values, p):
    return sorted_values[min(len(sorted_values) - 1, max(0, math.ceil(p * len(sorted_values)) - 1))]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("before")
    parser.add_argument("after")
    parser.add_argument("--film", default="int", choices=["int", "f32", "regression", "dry"])
    args = parser.parse_args()
    everything = []
    for name in TRACES:
        trace = os.path.join(ROOT, "hil-sim/traces", name)
        a, b = run(args.before, trace, args.film), run(args.after, trace, args.film)
        errors = sorted(
            math.hypot(fb - fa, gb - ga) / max(math.hypot(fa, ga), mean)
            for (_, fa, ga, mean), (_, fb, gb, _) in zip(a, b))
        everything += errors
        counts = [(min(s[0] for s in r), max(s[0] for s in r)) for r in (a, b)]
        print(f"{name}: {len(errors)} steps, |ΔF|/max(|F|, mean Q) p99 "
              f"{percentile(errors, 0.99):.2e}, max {errors[-1]:.2e}; instructions per step "
              f"{counts[0][0]}…{counts[0][1]} → {counts[1][0]}…{counts[1][1]}")
    everything.sort()
    print(f"both traces: {len(everything)} steps, p99 {percentile(everything, 0.99):.2e}, "
          f"max {everything[-1]:.2e}")


if __name__ == "__main__":
    main()
