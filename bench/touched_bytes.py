#!/usr/bin/env python3
"""Data touched per axis-cycle (issue 23, docs/performance.md "Per-cycle cost").

Runs a callgrind workload with the argument `touched` under valgrind's lackey (--trace-mem=yes). The workload
brackets each counted phase (MC_Servo, MC_Interpolator of its axes) with two stores to a marker whose address it
prints first; this script collects every data load/store/modify between the markers of the last cycle (the last
two phases) and prints the distinct bytes and 64-byte cache lines, all and without the stack.

A workload that also prints `object=<address> size=<bytes>` (its first axis) gets a third line: the bytes and
lines inside that object; with --offsets, the touched byte ranges as offsets into it (to set against
`ptype /o` of the class: which members the cycle touches, decision O4).

With --lines, every touched line outside the first axis object and the stack, named by the program's symbol or
section it falls in (`nm`, `readelf`; the program's load address from the marker's symbol), or "heap": where
the lines beside the TO's own members come from (decision P28).

Usage: bench/touched_bytes.py build-bench/bin/positioning_to_cycle_callgrind [units] [--offsets] [--lines]
  units: divide by this many axes (the workload's units=, e.g. 16 followers of gearing_cycle)
"""
import subprocess
import sys
import threading

LINE = 64


def main() -> int:
    args = [a for a in sys.argv[1:] if a not in ("--offsets", "--lines")]
    offsets = "--offsets" in sys.argv[1:]
    list_lines = "--lines" in sys.argv[1:]
    program = args[0]
    units = int(args[1]) if len(args) > 1 else 1
    proc = subprocess.Popen(
        ["valgrind", "--tool=lackey", "--trace-mem=yes", "--log-fd=2", program, "touched"],
        stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, bufsize=1 << 20)
    marker = []
    cycles = []
    objects = []

    def read_stdout() -> None:
        for line in proc.stdout:
            if line.startswith("marker=") and not marker:
                marker.append(int(line.split("=", 1)[1], 16))
            elif line.startswith("object="):
                address, size = line.split()
                objects.append((int(address.split("=")[1], 16), int(size.split("=")[1])))
            elif line.startswith("cycles="):
                cycles.append(int(line.split()[0].split("=")[1]))

    reader = threading.Thread(target=read_stdout)
    reader.start()
    # Phases in order: each a set of (address, size); the marker's own accesses are not counted.
    phases = []
    current = None
    tag = None
    for line in proc.stderr:
        if tag is None:
            # The marker is printed before the machine is built, long before its first store; the trace
            # up to then (the loader, the set-up) is drained unread so that valgrind never blocks on it.
            if not marker:
                continue
            tag = f" {marker[0]:08x},"  # lackey prints " S %08lx,size"
        if current is None:
            # Outside the counted phases only the opening store matters (a substring test, for speed).
            if tag in line and line[1] in "SM":
                current = []
            continue
        if len(line) < 3 or line[0] != " " or line[1] not in "LSM":
            continue
        addr_s, size_s = line[3:].strip().split(",")
        if int(addr_s, 16) == marker[0]:
            if line[1] in "SM":
                phases.append(current)
                current = None
            continue
        current.append((int(addr_s, 16), int(size_s)))
    proc.wait()
    reader.join()
    expected = 2 * cycles[0] if cycles else -1  # MC_Servo and MC_Interpolator of every cycle
    if proc.returncode != 0 or len(phases) != expected:
        print(f"touched_bytes: {program} failed or traced {len(phases)} phases, not {expected}", file=sys.stderr)
        return 1
    cycle = phases[-2] + phases[-1]  # MC_Servo + MC_Interpolator of the last cycle
    # The stack: the highest addresses of the trace (valgrind places it far above heap and image).
    stack_floor = max(a for a, _ in cycle) - (1 << 20)
    counts = {}
    picks = [("all", lambda a: True), ("without stack", lambda a: a < stack_floor)]
    if objects:
        object_base, object_size = objects[0]
        picks.append(("inside the first axis object", lambda a: object_base <= a < object_base + object_size))
    for name, pick in picks:
        data_bytes = set()
        lines = set()
        for addr, size in cycle:
            for b in range(addr, addr + size):
                if pick(b):
                    data_bytes.add(b)
                    lines.add(b // LINE)
        counts[name] = (len(data_bytes), len(lines))
    accesses = len(cycle)
    print(f"{program}: one cycle, {accesses} data accesses; per axis (units={units}):")
    for name, (nb, nl) in counts.items():
        print(f"  {name}: {nb // units} distinct bytes, {nl / units:.0f} cache lines = {nl * LINE // units} bytes")
    if objects and offsets:
        base, size = objects[0]
        touched = sorted({b - base for a, n in cycle for b in range(a, a + n) if base <= b < base + size})
        ranges = []
        for off in touched:
            if ranges and off == ranges[-1][1] + 1:
                ranges[-1][1] = off
            else:
                ranges.append([off, off])
        print("  offsets:", " ".join(f"{a}" if a == b else f"{a}-{b}" for a, b in ranges))
    if list_lines:
        object_base, object_size = objects[0] if objects else (0, 0)
        outside = {}
        for addr, size in cycle:
            for b in range(addr, addr + size):
                if b < stack_floor and not object_base <= b < object_base + object_size:
                    outside.setdefault(b // LINE, set()).add(b)
        name_of = program_symbols(program, marker[0])
        print(f"  lines outside the axis object and the stack: {len(outside)}")
        for line in sorted(outside):
            print(f"    {line * LINE:#x} {len(outside[line]):3d} bytes  {name_of(min(outside[line]), max(outside[line]))}")
    return 0


def program_symbols(program: str, marker_address: int):
    """A function naming an address range by the program's data symbols and sections, or "heap"."""
    import bisect
    nm = subprocess.run(["nm", "-C", "-n", "-S", "--defined-only", program], capture_output=True, text=True).stdout
    symbols = []  # (address, size, name)
    marker_symbol = None
    for row in nm.splitlines():
        parts = row.split(maxsplit=3)
        if len(parts) == 4 and parts[2].lower() in "bdrvug":
            address, size, name = int(parts[0], 16), int(parts[1], 16), parts[3]
            symbols.append((address, size, name))
            if name == "tomc::bench::touched_marker":
                marker_symbol = address
    sections = []  # (address, size, name)
    readelf = subprocess.run(["readelf", "-SW", program], capture_output=True, text=True).stdout
    for row in readelf.splitlines():
        parts = row.replace("[ ", "[").split()
        if len(parts) > 5 and parts[0].startswith("[") and parts[1].startswith("."):
            sections.append((int(parts[3], 16), int(parts[5], 16), parts[1]))
    base = marker_address - marker_symbol if marker_symbol is not None else 0
    starts = [s[0] for s in symbols]

    def name_of(first: int, last: int) -> str:
        names = []
        for address in (first, last):
            a = address - base
            i = bisect.bisect_right(starts, a) - 1
            if i >= 0 and symbols[i][0] <= a < symbols[i][0] + max(symbols[i][1], 1):
                names.append(symbols[i][2][:90])
                continue
            section = next((n for s, z, n in sections if s <= a < s + z), None)
            names.append(section if section is not None else "heap")
        return names[0] if names[0] == names[1] else f"{names[0]} .. {names[1]}"

    return name_of


if __name__ == "__main__":
    sys.exit(main())
