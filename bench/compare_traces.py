#!/usr/bin/env python3
"""Scenario traces of two tomc binaries, byte for byte (issue 23: a cheaper cycle must show the same values).

For every tests/scenarios/*.json and examples/*.json it runs `tomc sim` with both binaries twice: on the file as
it is, and on a copy whose trace also lists the status variables the cycle writes (per TO type, below), so that a
variable no scenario traces is compared too. Prints one line per difference and a summary; exit 1 on any.

Usage: bench/compare_traces.py BASE_TOMC NEW_TOMC   (e.g. a build of main and one of the branch)
"""
import glob
import json
import os
import re
import subprocess
import sys
import tempfile

AXIS = ["Position", "ActualPosition", "Velocity", "ActualVelocity", "Acceleration", "ActualAcceleration",
        "ModuloCycle", "ActualModuloCycle", "VelocitySetpoint", "ActualSpeed", "StatusWord", "StatusWord2",
        "ErrorWord", "WarningWord", "ErrorDetail.Number", "ErrorDetail.Reaction",
        "StatusPositioning.TargetPosition", "StatusPositioning.TargetPositionModuloCycle",
        "StatusPositioning.Distance", "StatusPositioning.SuperimposedDistance",
        "StatusPositioning.SetpointExecutionTime", "StatusPositioning.FollowingError",
        "StatusServo.BalancedPosition", "StatusServo.ControlDifference", "StatusServo.PositionAfterDynamicFilter",
        "StatusDrive.InOperation", "StatusDrive.CommunicationOK", "StatusDrive.Error",
        "StatusTorqueData.TotalTorqueAdditive", "StatusTorqueData.TotalForceAdditive",
        "StatusTorqueData.ActualTorque", "StatusTorqueData.CommandAdditiveTorqueActive",
        "StatusMotionIn.StatusWord", "StatusMotionIn.FunctionState",
        "StatusExtrapolation.ExtrapolatedPosition", "StatusExtrapolation.ExtrapolatedVelocity"] + [
        f"StatusSensor[{n}].{m}" for n in (1, 2) for m in
        ("Position", "Velocity", "ModuloCycle", "State", "Error", "CommunicationOK", "Adjusted", "AbsEncoderOffset")]
SPEED = ["Velocity", "ActualVelocity", "VelocitySetpoint", "ActualSpeed", "StatusWord", "StatusWord2", "ErrorWord",
         "WarningWord", "ErrorDetail.Number", "StatusTorqueData.TotalTorqueAdditive"]
EXTRA = {"TO_PositioningAxis": AXIS, "TO_SynchronousAxis": AXIS, "TO_SpeedAxis": SPEED}


def run(tomc: str, scenario: str, out: str) -> tuple[int, bytes]:
    if os.path.exists(out):
        os.remove(out)
    r = subprocess.run([tomc, "sim", scenario, "--out", out], capture_output=True)
    if not os.path.exists(out):
        return r.returncode, r.stderr
    with open(out, "rb") as f:
        return r.returncode, f.read()


def extended(path: str, tomc: str) -> str | None:
    """A copy of the scenario (beside it: relative file names stay valid) tracing every EXTRA variable its TOs
    have; names the TO does not have are dropped after a first run that reports them (trace[i])."""
    with open(path) as f:
        d = json.load(f)
    names = list(d.get("trace", []))
    for to in d["technology_objects"]:
        names += [f"{to['name']}.{v}" for v in EXTRA.get(to["type"], [])]
    d.pop("expect", None)
    copy = os.path.join(os.path.dirname(path), ".compare_" + os.path.basename(path))
    for _ in range(2):
        d["trace"] = names
        with open(copy, "w") as f:
            json.dump(d, f)
        r = subprocess.run([tomc, "sim", copy, "--out", os.devnull], capture_output=True, text=True)
        if r.returncode in (0, 1):
            return copy
        bad = {int(m) for m in re.findall(r": trace\[(\d+)\]", r.stderr)}
        if not bad:
            break
        names = [n for i, n in enumerate(names) if i not in bad]
    os.remove(copy)
    return None


def main() -> int:
    base, new = sys.argv[1], sys.argv[2]
    files = sorted(glob.glob("tests/scenarios/**/*.json", recursive=True) + glob.glob("examples/*.json"))
    differ = compared = skipped = 0
    columns = 0
    with tempfile.TemporaryDirectory() as tmp:
        for path in files:
            with open(path) as f:
                if "cycles" not in json.load(f):  # e.g. examples/demo_machine.json, a `tomc demo` configuration
                    print(f"note: {path}: not a tomc sim scenario (no cycles); skipped")
                    continue
            variants = [path]
            ext = extended(path, base)
            if ext is None:
                print(f"note: {path}: no extended trace (the probe did not accept it); compared as it is")
            else:
                variants.append(ext)
            for v in variants:
                rb, tb = run(base, v, os.path.join(tmp, "base.csv"))
                rn, tn = run(new, v, os.path.join(tmp, "new.csv"))
                compared += 1
                columns += tb.split(b"\n", 1)[0].count(b",") - 1
                if rb != rn or tb != tn:
                    differ += 1
                    print(f"DIFFERENT: {v} (exit {rb} vs {rn}, {len(tb)} vs {len(tn)} bytes)")
            if ext is not None:
                os.remove(ext)
    print(f"{compared} traces of {len(files)} scenario files compared ({columns} columns in all): {differ} different")
    return 1 if differ else 0


if __name__ == "__main__":
    sys.exit(main())
