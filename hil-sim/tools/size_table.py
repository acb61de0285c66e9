#!/usr/bin/env python3
"""Instructions per bearing step on the emulated Cortex-M4 by roller and slice count, and the
step rate at 168 MHz each allows: the table of docs/performance.md.

Builds the HIL firmware with its `size-table` feature (in the firmware's own workspace; the
next `hil-sim qemu` builds its image without it again), runs it under QEMU as `hil-sim qemu`
does on a one-record excerpt of the hub-motor trace, and reads `sizes.csv`: the step's
instructions (TIM2, exact) for 8, 12, 17, 21 and 25 rollers of 5, 10 and 20 slices, integer
network and dry. The counts between the measured roller counts are a straight line through the
measured ones of the same slice count and film model (a step is a fixed part plus the same work
for every roller; the script prints the largest deviation of a measured count from the line).
The cycles are the instructions times the CPI range `profile_functions.py` derives for the
replayed step from the Cortex-M4's instruction timings (--cpi, default 1.20 … 2.01).

    python3 hil-sim/tools/size_table.py [--cpi 1.20 2.01]
"""

import argparse
import csv
import os
import struct
import subprocess
import sys
import tempfile
import zlib

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
FIRMWARE = os.path.join(ROOT, "hil-sim/firmware")
TRACE = os.path.join(ROOT, "hil-sim/traces/hub_motor_runup.bin")
CLOCK_HZ = 168.0e6


def one_record(trace: bytes) -> bytes:
    """The first record of a binary trace, with the header's count and checksums renewed."""
    flags = struct.unpack_from("<H", trace, 10)[0]
    record = 36 if flags & 1 else 28
    body = trace[64 : 64 + record]
    header = bytearray(trace[:64])
    struct.pack_into("<I", header, 12, 1)
    struct.pack_into("<I", header, 56, zlib.crc32(body))
    struct.pack_into("<I", header, 60, zlib.crc32(bytes(header[:60])))
    return bytes(header) + body


def measure() -> list:
    env = {k: v for k, v in os.environ.items()
           if k not in ("CARGO_TARGET_DIR", "RUSTFLAGS", "CARGO_ENCODED_RUSTFLAGS",
                        "CARGO_BUILD_TARGET")}
    subprocess.run(
        ["cargo", "build", "--release", "--target", "thumbv7em-none-eabihf",
         "--features", "size-table"],
        cwd=FIRMWARE, env=env, check=True,
    )
    elf = os.path.join(FIRMWARE, "target/thumbv7em-none-eabihf/release/bearing-hil-firmware")
    with tempfile.TemporaryDirectory() as scratch:
        with open(os.path.join(scratch, "trace.bin"), "wb") as f:
            f.write(one_record(open(TRACE, "rb").read()))
        with open(os.path.join(scratch, "film.txt"), "w") as f:
            f.write("int")
        run = subprocess.run(
            ["qemu-system-arm", "-machine", "netduinoplus2", "-cpu", "cortex-m4",
             "-nographic", "-monitor", "none", "-serial", "none",
             "-semihosting-config", "enable=on,target=native", "-icount", "shift=0",
             "-kernel", elf],
            cwd=scratch, stdout=subprocess.DEVNULL, timeout=900,
        )
        if run.returncode != 0:
            sys.exit(f"the firmware exited with code {run.returncode}")
        with open(os.path.join(scratch, "sizes.csv")) as f:
            return [(int(r["rollers"]), int(r["slices"]), r["film"], int(r["instructions"]))
                    for r in csv.DictReader(f)]


def line_through(points):
    """Least-squares a + b·z through (z, count) points."""
    n = len(points)
    mz = sum(z for z, _ in points) / n
    mc = sum(c for _, c in points) / n
    b = sum((z - mz) * (c - mc) for z, c in points) / sum((z - mz) ** 2 for z, _ in points)
    return mc - b * mz, b


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--cpi", nargs=2, type=float, default=(1.20, 2.01),
                        metavar=("FEWEST", "MOST"))
    args = parser.parse_args()
    rows = measure()
    measured = {(z, s, film): n for z, s, film, n in rows}
    slices = sorted({s for _, s, _ in measured})
    films = ("int", "dry")
    lines = {}
    for s in slices:
        for film in films:
            points = sorted((z, n) for (z, s2, f), n in measured.items() if s2 == s and f == film)
            a, b = line_through(points)
            worst = max(abs(n - (a + b * z)) for z, n in points)
            lines[(s, film)] = (a, b)
            print(f"{film:>3}, {s:2} slices: {a:7.0f} + {b:6.1f} per roller "
                  f"(measured at {', '.join(str(z) for z, _ in points)}; "
                  f"largest deviation from the line {worst:.0f} instructions)")
    fewest, most = args.cpi
    header = ["rollers"] + [f"{film} S={s}" for film in films for s in slices]
    print("\n| " + " | ".join(header) + " |")
    print("|" + "---|" * len(header))
    for z in range(8, 26):
        cells = [str(z)]
        for film in films:
            for s in slices:
                if (z, s, film) in measured:
                    count, mark = measured[(z, s, film)], "**"
                else:
                    a, b = lines[(s, film)]
                    count, mark = round(a + b * z), ""
                rate_low = CLOCK_HZ / (count * most) / 1e3
                rate_high = CLOCK_HZ / (count * fewest) / 1e3
                cells.append(f"{mark}{count:,}{mark} ({rate_low:.1f}–{rate_high:.1f})"
                             .replace(",", " "))
        print("| " + " | ".join(cells) + " |")
    print("\nbold: measured; others on the line through the measured counts of their column; "
          f"(kHz at {CLOCK_HZ / 1e6:.0f} MHz for CPI {most} … {fewest})")


if __name__ == "__main__":
    main()
