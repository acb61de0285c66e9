#!/usr/bin/env python3
"""Instructions per replay step on the emulated Cortex-M4, by source function.

`hil-sim qemu` counts whole steps (TIM2) and times building blocks one call at a time; this
script says where the instructions of a step go. It runs the firmware that `hil-sim qemu`
built on two excerpts of a trace, N and 2N records long, with QEMU's execution log
(`-d exec,nochain,in_asm`: every translated block with its instructions, every execution of
a block), so that the difference of the two runs is N steps and nothing else (start-up, the
settle and the building-block profile cancel). Each executed instruction is then attributed
with `arm-none-eabi-addr2line -i` to the chain of functions inlined at its address:

- *innermost*: the function whose code the instruction is (after inlining: a `max`, a root);
- *inclusive*: every function of the inline chain (`Bearing::run` holds most of the step;
  functions the compiler kept out of line, such as the film table's `sum_at` on the M4, are
  counted under their own name, not under their caller's);
- *lines*: the source lines, innermost.

The step is branch-free, so every excerpt gives the same counts; the default excerpt starts at
the hub-motor trace's resonance passage. Needs qemu-system-arm and binutils-arm-none-eabi
(both installed by .ci/run) and the firmware built (`hil-sim qemu` builds it).

`--core m7` and `--core m33` build the firmware for QEMU's MPS2 boards (features `mps2-an500`,
a Cortex-M7 on thumbv7em-none-eabihf, and `mps2-an505`, a Cortex-M33 on
thumbv8m.main-none-eabihf; the next `hil-sim qemu` builds its own image again) and count
there; the cycle estimate is the Cortex-M4's on every core.

    python3 hil-sim/tools/profile_functions.py [--core m4|m7|m33] [--film int] [--steps 40]
"""

import argparse
import collections
import os
import re
import struct
import subprocess
import sys
import tempfile
import zlib

HEADER_LEN = 64
ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
DEFAULT_ELF = os.path.join(
    ROOT,
    "hil-sim/firmware/target/thumbv7em-none-eabihf/release/bearing-hil-firmware",
)
DEFAULT_TRACE = os.path.join(ROOT, "hil-sim/traces/hub_motor_runup.bin")


# QEMU machine, CPU, Rust target and firmware feature of each core (None: the default build).
CORES = {
    "m4": ("netduinoplus2", "cortex-m4", "thumbv7em-none-eabihf", None),
    "m7": ("mps2-an500", "cortex-m7", "thumbv7em-none-eabihf", "mps2-an500"),
    "m33": ("mps2-an505", "cortex-m33", "thumbv8m.main-none-eabihf", "mps2-an505"),
}


def build(target: str, feature: str) -> str:
    """Builds the firmware for `target` with `feature`; its ELF."""
    firmware = os.path.join(ROOT, "hil-sim/firmware")
    target_dir = os.path.join(firmware, "target")
    env = {k: v for k, v in os.environ.items()
           if k not in ("CARGO_TARGET_DIR", "RUSTFLAGS", "CARGO_ENCODED_RUSTFLAGS",
                        "CARGO_BUILD_TARGET")}
    subprocess.run(["cargo", "build", "--release", "--target", target, "--features", feature],
                   cwd=firmware, env=env, check=True)
    return os.path.join(target_dir, target, "release", "bearing-hil-firmware")


def excerpt(trace: bytes, start: int, count: int) -> bytes:
    """Records start … start+count of a binary trace (hil-sim/kernel/src/wire.rs), with the
    header's count and both CRC-32s renewed."""
    flags, total = struct.unpack_from("<HI", trace, 10)
    record = 36 if flags & 1 else 28
    if start + count > total:
        sys.exit(f"--start {start} + {count} records is past the trace's {total} records")
    body = trace[HEADER_LEN + start * record : HEADER_LEN + (start + count) * record]
    header = bytearray(trace[:HEADER_LEN])
    struct.pack_into("<I", header, 12, count)
    struct.pack_into("<I", header, 56, zlib.crc32(body))
    struct.pack_into("<I", header, 60, zlib.crc32(bytes(header[:60])))
    return bytes(header) + body


def executed(elf: str, directory: str, machine: str, cpu: str,
             listing_of: dict) -> collections.Counter:
    """Executions of each instruction address in one QEMU run of `elf` in `directory`; the
    disassembly of each address (mnemonic, operands) into `listing_of`."""
    log = os.path.join(directory, "qemu.log")
    command = [
        "qemu-system-arm", "-machine", machine, "-cpu", cpu, "-nographic",
        "-monitor", "none", "-serial", "none",
        "-semihosting-config", "enable=on,target=native", "-icount", "shift=0",
        "-d", "exec,nochain,in_asm", "-D", log, "-kernel", elf,
    ]
    run = subprocess.run(command, cwd=directory, stdout=subprocess.DEVNULL, timeout=600)
    if run.returncode != 0:
        sys.exit(f"the firmware exited with code {run.returncode} in {directory}")
    blocks = {}
    listing = None
    runs = collections.Counter()
    with open(log) as text:
        for line in text:
            if line.startswith("IN:"):
                listing = []
            elif listing is not None and line.startswith("0x"):
                address = int(line[2:10], 16)
                listing.append(address)
                words = re.match(r"0x[0-9a-f]{8}:\s+[0-9a-f]{4}(?: [0-9a-f]{4})?\s+(\S+)\s*(.*)", line)
                if words:
                    listing_of[address] = (words.group(1), words.group(2))
            elif line.startswith("Trace"):
                # Trace 0: host [cs_base/pc/flags/cflags] symbol
                fields = re.search(r"\[[0-9a-f]+/([0-9a-f]+)/", line)
                runs[int(fields.group(1), 16)] += 1
            elif listing and not line.strip():
                blocks[listing[0]] = listing
                listing = None
    counts = collections.Counter()
    for pc, n in runs.items():
        for address in blocks.get(pc, [pc]):
            counts[address] += n
    return counts


def inline_chains(elf: str, addresses):
    """For each address, [(function, file:line), …] from the innermost inlined function out."""
    out = subprocess.run(
        ["arm-none-eabi-addr2line", "-e", elf, "-i", "-f", "-C", "-a"]
        + [hex(a) for a in addresses],
        capture_output=True, text=True, check=True,
    ).stdout.splitlines()
    chains, current, i = {}, None, 0
    while i < len(out):
        if out[i].startswith("0x"):
            current = int(out[i], 16)
            chains[current] = []
            i += 1
        elif current is not None and i + 1 < len(out):
            chains[current].append((out[i], out[i + 1]))
            i += 2
        else:
            i += 1
    return chains


# Cycles of an instruction on a Cortex-M4 with zero-wait-state memory, (fewest, most), from the
# instruction timings of the Cortex-M4 Technical Reference Manual (ARM DDI 0439, §3.3.1, and the
# FPU's, §7.2.3): loads and stores 2 cycles, 1 when neighbouring ones pipeline; a taken branch
# 1 + P with a pipeline refill P of 1 to 3 (a conditional one not taken: 1); multiply-accumulate
# on the FPU (VMLA, VFMA, …) 3; VDIV and VSQRT 14, counted as 1 at the fewest in case the core
# overlaps them with independent instructions; IT 0 when folded; 1 + N for an N-register
# transfer; 1 for the rest.
def cycles(mnemonic: str, operands: str):
    m = mnemonic.split(".")[0]
    base = re.sub(r"(eq|ne|cs|hs|cc|lo|mi|pl|vs|vc|hi|ls|ge|lt|gt|le|al)$", "", m)
    registers = 0
    if "{" in operands:
        for part in operands[operands.index("{") + 1 : operands.index("}")].split(","):
            part = part.strip()
            span = re.match(r"([rsd])(\d+)-[rsd](\d+)", part)
            count = int(span.group(3)) - int(span.group(2)) + 1 if span else 1
            registers += count * (2 if part.startswith("d") else 1)
    if base in ("vdiv", "vsqrt"):
        return (1, 14)
    if base in ("vmla", "vmls", "vnmla", "vnmls", "vfma", "vfms", "vfnma", "vfnms"):
        return (3, 3)
    if base in ("vpush", "vpop", "vldm", "vstm", "vldmia", "vstmia", "vstmdb", "push", "pop",
                "ldm", "stm", "ldmia", "stmia", "stmdb"):
        refill = (1, 3) if "pc" in operands else (0, 0)
        return (1 + registers + refill[0], 1 + registers + refill[1])
    if base in ("ldrd", "strd"):
        return (2, 3)
    if base.startswith(("ldr", "str", "vldr", "vstr")):
        return (1, 2)
    if m in ("b", "bl", "bx", "blx"):
        return (2, 4)
    if m in ("cbz", "cbnz") or (base == "b" and m != base):
        return (1, 4)
    if base in ("sdiv", "udiv"):
        return (2, 12)
    if base == "it" or base.startswith("it"):
        return (0, 1)
    return (1, 1)


def short(function: str) -> str:
    """A demangled name without generic arguments or hashes."""
    previous = None
    while previous != function:
        previous, function = function, re.sub(r"<[^<>]*>", "", function)
    return function[:100]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--core", default="m4", choices=sorted(CORES))
    parser.add_argument("--elf", help="firmware to run (default: the core's build)")
    parser.add_argument("--trace", default=DEFAULT_TRACE)
    parser.add_argument("--film", default="int", choices=["int", "f32", "regression", "dry"])
    parser.add_argument("--start", type=int, default=10000, help="first record of the excerpt")
    parser.add_argument("--steps", type=int, default=40, help="N: steps the difference counts")
    parser.add_argument("--top", type=int, default=30)
    args = parser.parse_args()
    machine, cpu, target, feature = CORES[args.core]
    if args.elf is None:
        args.elf = DEFAULT_ELF if feature is None else build(target, feature)
    trace = open(args.trace, "rb").read()
    counts = []
    listing_of = {}
    with tempfile.TemporaryDirectory() as scratch:
        for count in (args.steps, 2 * args.steps):
            directory = os.path.join(scratch, str(count))
            os.makedirs(directory)
            with open(os.path.join(directory, "trace.bin"), "wb") as f:
                f.write(excerpt(trace, args.start, count))
            with open(os.path.join(directory, "film.txt"), "w") as f:
                f.write(args.film)
            counts.append(executed(args.elf, directory, machine, cpu, listing_of))
    short_run, long_run = counts
    steps = {a: n - short_run.get(a, 0) for a, n in long_run.items() if n > short_run.get(a, 0)}
    chains = inline_chains(args.elf, sorted(steps))
    innermost, inclusive, lines = (collections.Counter() for _ in range(3))
    for address, n in steps.items():
        chain = chains.get(address) or [("?", "?")]
        innermost[short(chain[0][0])] += n
        lines[chain[0][1].split("/src/")[-1].split(" ")[0]] += n
        for function in {short(f) for f, _ in chain}:
            inclusive[function] += n
    per_step = args.steps
    total = sum(steps.values()) / per_step
    fewest = most = 0
    mnemonics = collections.Counter()
    for address, n in steps.items():
        mnemonic, operands = listing_of.get(address, ("?", ""))
        low, high = cycles(mnemonic, operands)
        fewest += low * n
        most += high * n
        mnemonics[mnemonic] += n
    print(f"{total:.0f} instructions per step on {machine} ({cpu}) "
          f"(film {args.film}, records {args.start}…, difference of {args.steps} steps; "
          "the replay kernel's decoding and output encoding included)")
    print(f"Cortex-M4 cycles per step, zero-wait-state memory: {fewest / per_step:.0f} … "
          f"{most / per_step:.0f} (CPI {fewest / per_step / total:.2f} … "
          f"{most / per_step / total:.2f})")
    for title, table in (("inclusive (inline chain)", inclusive), ("mnemonic", mnemonics),
                         ("innermost function", innermost), ("source line", lines)):
        print(f"\n{title}: instructions per step")
        for name, n in table.most_common(args.top):
            print(f"{n / per_step:9.0f}  {name}")


if __name__ == "__main__":
    main()
