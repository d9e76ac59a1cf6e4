#!/usr/bin/env python3
"""The one table of the MC_* instructions of the C ABI and the IEC 61131-3 declarations.

From the table below this writes, next to it:
  include/tomc/tomc_instructions.h   one C struct per instruction (IEC FB instance data) + its functions
  src/instructions.inc               the C++ side: fields copied to/from tomc::instructions::MC_*<Axis>, and
                                     static_asserts that the table's defaults are the C++ classes' defaults
  iec/tomc_motion.st                 Structured Text FUNCTION_BLOCK declarations (external FBs)
The outputs are committed; `generate.py --check` (ctest capi.generated_files) fails when they differ from what
the table gives. Run `python3 capi/generate.py` after editing the table.
"""
import pathlib
import sys

# IEC type -> (C type, C++ conversion from the C field, C++ -> C)
TYPES = {
    "BOOL": "bool",
    "INT": "int16_t",
    "DINT": "int32_t",
    "WORD": "uint16_t",
    "LREAL": "double",
    # MC_PositionProfile.TimePosition: tomc's time-position point structure (decision L1), by pointer.
    "PROFILE": "const tomc_time_position_profile*",
    # MC_CamIn.Cam: a TO_Cam of the machine (tomc_object* handle).
    "CAM": "const tomc_object*",
    # MC_CopyCamData.ArrayOfPoints / ArrayOfSegments (IN_OUT ARRAY[*] in the manual): a pointer and, in the input
    # after it, the number of elements it holds.
    "POINTS": "const tomc_cam_point*",
    "SEGMENTS": "const tomc_cam_segment*",
}

# TO kinds: S TO_SpeedAxis, P TO_PositioningAxis, Y TO_SynchronousAxis, E TO_ExternalEncoder
# C TO_Cam (its instructions take the cam as their technology object)
KIND_NAMES = {"S": "TO_SpeedAxis", "P": "TO_PositioningAxis", "Y": "TO_SynchronousAxis", "E": "TO_ExternalEncoder",
              "C": "TO_Cam"}
KIND_CONSTANTS = {"S": "kSpeed", "P": "kPositioning", "Y": "kSynchronous", "E": "kEncoder", "C": "kCam"}
KIND_CLASSES = {"S": "SpeedAxis", "P": "PositioningAxis", "Y": "SynchronousAxis", "E": "ExternalEncoder",
                "C": "Cam"}


def fb(name, spec, kinds, inputs, outputs, master=False):
    """master: False, True (the input Master, the leading TO) or the name of another TO input."""
    source = "Master" if master is True else (master or None)
    return dict(name=name, spec=spec, kinds=kinds, inputs=inputs, outputs=outputs, master=source)


HANDSHAKE = [("Done", "BOOL"), ("Busy", "BOOL"), ("CommandAborted", "BOOL"), ("Error", "BOOL"), ("ErrorID", "WORD")]
DYN = [("Acceleration", "LREAL", "-1.0"), ("Deceleration", "LREAL", "-1.0"), ("Jerk", "LREAL", "-1.0")]

# Leading and following value offsets (spec 07 §4.1, §4.2).
PHASING_INPUTS = ([("Execute", "BOOL", "FALSE"), ("PhaseShift", "LREAL", "0.0"), ("Velocity", "LREAL", "-1.0")] + DYN +
                  [("ProfileReference", "DINT", "0"), ("PhasingDistance", "LREAL", "0.0"),
                   ("StartPosition", "LREAL", "0.0"), ("Direction", "DINT", "3")])
OFFSET_INPUTS = [("Execute", "BOOL", "FALSE"), ("Offset", "LREAL", "0.0"), ("ProfileReference", "DINT", "1"),
                 ("OffsetDistance", "LREAL", "0.0"), ("StartPosition", "LREAL", "0.0"), ("Direction", "DINT", "3")]

# Scaling and shifting of the cam read instructions (spec 07 §3.3, §3.6).
CAM_SCALING = [("MasterOffset", "LREAL", "0.0"), ("SlaveOffset", "LREAL", "0.0"), ("MasterScaling", "LREAL", "1.0"),
               ("SlaveScaling", "LREAL", "1.0")]
# Inputs of tomc's own beside the manual's (not in the C++ class): the length of an array given by pointer.
ARRAY_LENGTHS = {"ArrayOfPointsLength", "ArrayOfSegmentsLength"}
# A TO_Cam given as the C++ class's input named here (decision U15): MC_PositionProfile.TimePosition is a TO_Cam
# or tomc's point structure in the manual's DB_ANY, two pointers of different types in C; one of them, not both.
CAM_AS = {"TimePositionCam": "TimePosition"}

# The implemented instructions in the manual's order (spec 01 §1.3). Inputs: (name, IEC type, default);
# outputs: (name, IEC type). A "master" instruction also has the input Master (the leading TO), or the TO input
# named by `master`.
TABLE = [
    fb("MC_Power", "spec 03 §4.1", "SPYE",
       [("Enable", "BOOL", "FALSE"), ("StartMode", "DINT", "1"), ("StopMode", "INT", "0")],
       [("Status", "BOOL"), ("Busy", "BOOL"), ("Error", "BOOL"), ("ErrorID", "WORD")]),
    fb("MC_Reset", "spec 03 §4.2", "SPYE",
       [("Execute", "BOOL", "FALSE"), ("Restart", "BOOL", "FALSE")], HANDSHAKE),
    fb("MC_Home", "spec 03 §4.3", "PYE",
       [("Execute", "BOOL", "FALSE"), ("Position", "LREAL", "0.0"), ("Mode", "INT", "0"),
        ("Sensor", "DINT", "0")],
       [("ReferenceMarkPosition", "LREAL")] + HANDSHAKE),
    fb("MC_Halt", "spec 03 §4.4", "SPY",
       [("Execute", "BOOL", "FALSE"), ("Deceleration", "LREAL", "-1.0"), ("Jerk", "LREAL", "-1.0"),
        ("AbortAcceleration", "BOOL", "FALSE"), ("Mode", "DINT", "0")], HANDSHAKE),
    fb("MC_MoveAbsolute", "spec 03 §4.5", "PY",
       [("Execute", "BOOL", "FALSE"), ("Position", "LREAL", "0.0"), ("Velocity", "LREAL", "-1.0")] + DYN +
       [("BufferMode", "DINT", "0"), ("Direction", "INT", "1")],
       [("Done", "BOOL"), ("Busy", "BOOL"), ("Active", "BOOL"), ("CommandAborted", "BOOL"), ("Error", "BOOL"),
        ("ErrorID", "WORD")]),
    fb("MC_MoveRelative", "spec 03 §4.6", "PY",
       [("Execute", "BOOL", "FALSE"), ("Distance", "LREAL", "0.0"), ("Velocity", "LREAL", "-1.0")] + DYN +
       [("BufferMode", "DINT", "0")],
       [("Done", "BOOL"), ("Busy", "BOOL"), ("Active", "BOOL"), ("CommandAborted", "BOOL"), ("Error", "BOOL"),
        ("ErrorID", "WORD")]),
    fb("MC_MoveVelocity", "spec 03 §4.8", "SPY",
       [("Execute", "BOOL", "FALSE"), ("Velocity", "LREAL", "100.0")] + DYN +
       [("Direction", "INT", "0"), ("Current", "BOOL", "FALSE"), ("PositionControlled", "BOOL", "TRUE")],
       [("InVelocity", "BOOL"), ("Busy", "BOOL"), ("CommandAborted", "BOOL"), ("Error", "BOOL"),
        ("ErrorID", "WORD")]),
    fb("MC_MoveJog", "spec 03 §4.9", "SPY",
       [("JogForward", "BOOL", "FALSE"), ("JogBackward", "BOOL", "FALSE"), ("Velocity", "LREAL", "100.0")] + DYN +
       [("PositionControlled", "BOOL", "TRUE")],
       [("InVelocity", "BOOL"), ("Busy", "BOOL"), ("CommandAborted", "BOOL"), ("Error", "BOOL"),
        ("ErrorID", "WORD")]),
    fb("MC_MoveSuperimposed", "spec 03 §4.10", "PY",
       [("Execute", "BOOL", "FALSE"), ("Distance", "LREAL", "0.0"), ("VelocityDiff", "LREAL", "-1.0")] + DYN,
       HANDSHAKE),
    fb("MC_HaltSuperimposed", "spec 03 §4.11", "PY",
       [("Execute", "BOOL", "FALSE"), ("Deceleration", "LREAL", "-1.0"), ("Jerk", "LREAL", "-1.0"),
        ("AbortAcceleration", "BOOL", "FALSE")], HANDSHAKE),
    fb("MC_SetSensor", "spec 03 §4.12", "PY",
       [("Execute", "BOOL", "FALSE"), ("Sensor", "INT", "1"), ("Mode", "DINT", "0"),
        ("ReferenceSensor", "INT", "1")], HANDSHAKE),
    fb("MC_Stop", "spec 03 §4.13", "SPY",
       [("Execute", "BOOL", "FALSE"), ("Mode", "DINT", "0"), ("Deceleration", "LREAL", "-1.0"),
        ("Jerk", "LREAL", "-1.0"), ("AbortAcceleration", "BOOL", "FALSE")], HANDSHAKE),
    fb("MC_SetAxisSTW", "spec 03 §4.14", "SPY",
       [("Execute", "BOOL", "FALSE"), ("STW1", "WORD", "0"), ("STW1BitMask", "WORD", "0"), ("STW2", "WORD", "0"),
        ("STW2BitMask", "WORD", "0")], HANDSHAKE),
    fb("MC_WriteParameter", "spec 03 §4.15", "SPYE",
       [("Execute", "BOOL", "FALSE"), ("ParameterNumber", "DINT", "0"), ("Value", "LREAL", "0.0")], HANDSHAKE),
    fb("MC_TorqueLimiting", "spec 03 §4.18.3", "SPY",
       [("Enable", "BOOL", "FALSE"), ("Limit", "LREAL", "-1.0"), ("Mode", "DINT", "0")],
       [("InClamping", "BOOL"), ("InLimitation", "BOOL"), ("Busy", "BOOL"), ("Error", "BOOL"),
        ("ErrorID", "WORD")]),
    fb("MC_TorqueAdditive", "spec 03 §4.18.1", "SPY",
       [("Enable", "BOOL", "FALSE"), ("Value", "LREAL", "0.0")],
       [("Busy", "BOOL"), ("Error", "BOOL"), ("ErrorID", "WORD")]),
    fb("MC_TorqueRange", "spec 03 §4.18.2", "SPY",
       [("Enable", "BOOL", "FALSE"), ("UpperLimit", "LREAL", "1.0E12"), ("LowerLimit", "LREAL", "-1.0E12")],
       [("Busy", "BOOL"), ("Error", "BOOL"), ("ErrorID", "WORD")]),
    # MotionIn (spec 03 §4.17): the host controller's door — called every cycle with its setpoints while
    # Enable = TRUE, they act in the next MC_Interpolator without profile or dynamic limits.
    fb("MC_MotionInVelocity", "spec 03 §4.17.1", "SPY",
       [("Enable", "BOOL", "FALSE"), ("Velocity", "LREAL", "0.0"), ("Acceleration", "LREAL", "0.0"),
        ("PositionControlled", "BOOL", "TRUE")],
       [("Busy", "BOOL"), ("CommandAborted", "BOOL"), ("Error", "BOOL"), ("ErrorID", "WORD")]),
    fb("MC_MotionInPosition", "spec 03 §4.17.2", "PY",
       [("Enable", "BOOL", "FALSE"), ("Position", "LREAL", "0.0"), ("Velocity", "LREAL", "0.0"),
        ("Acceleration", "LREAL", "0.0")],
       [("Busy", "BOOL"), ("CommandAborted", "BOOL"), ("Error", "BOOL"), ("ErrorID", "WORD")]),
    fb("MC_MotionInSuperimposed", "spec 03 §4.17.3", "PY",
       [("Enable", "BOOL", "FALSE"), ("Distance", "LREAL", "0.0"), ("VelocityDiff", "LREAL", "0.0"),
        ("AccelerationDiff", "LREAL", "0.0")],
       [("Busy", "BOOL"), ("CommandAborted", "BOOL"), ("Error", "BOOL"), ("ErrorID", "WORD")]),
    fb("MC_MotionInSuperimposedAxes", "spec 03 §4.17.4", "PY",
       [("Enable", "BOOL", "FALSE")],
       [("Busy", "BOOL"), ("CommandAborted", "BOOL"), ("Error", "BOOL"), ("ErrorID", "WORD")],
       master="SuperimposingAxis"),
    fb("MC_PositionProfile", "spec 03 §4.7", "PY",
       [("TimePosition", "PROFILE", "NULL"), ("TimePositionCam", "CAM", "NULL"), ("Execute", "BOOL", "FALSE"), ("BufferMode", "DINT", "0"),
        ("StartTime", "LREAL", "0.0"), ("ProfileReference", "DINT", "0"), ("Velocity", "LREAL", "-1.0")] + DYN,
       [("Done", "BOOL"), ("Busy", "BOOL"), ("Active", "BOOL"), ("CommandAborted", "BOOL"), ("Error", "BOOL"),
        ("ErrorID", "WORD")]),
    fb("MC_GearIn", "spec 07 §2.1", "Y",
       [("Execute", "BOOL", "FALSE"), ("RatioNumerator", "DINT", "1"), ("RatioDenominator", "DINT", "1")] + DYN,
       [("InGear", "BOOL"), ("Busy", "BOOL"), ("CommandAborted", "BOOL"), ("Error", "BOOL"), ("ErrorID", "WORD")],
       master=True),
    fb("MC_GearInPos", "spec 07 §2.2", "Y",
       [("Execute", "BOOL", "FALSE"), ("RatioNumerator", "DINT", "1"), ("RatioDenominator", "DINT", "1"),
        ("MasterSyncPosition", "LREAL", "0.0"), ("SlaveSyncPosition", "LREAL", "0.0"),
        ("SyncProfileReference", "DINT", "1"), ("MasterStartDistance", "LREAL", "1.0"),
        ("Velocity", "LREAL", "-1.0")] + DYN + [("SyncDirection", "DINT", "3")],
       [("StartSync", "BOOL"), ("InSync", "BOOL"), ("Busy", "BOOL"), ("CommandAborted", "BOOL"), ("Error", "BOOL"),
        ("ErrorID", "WORD")],
       master=True),
    fb("MC_GearInVelocity", "spec 07 §2.3", "Y",
       [("Execute", "BOOL", "FALSE"), ("ContinuousUpdate", "BOOL", "FALSE"), ("RatioNumerator", "DINT", "1"),
        ("RatioDenominator", "DINT", "1")] + DYN + [("PositionControlled", "BOOL", "FALSE")],
       [("StartSync", "BOOL"), ("InSync", "BOOL"), ("ContinuousUpdateActive", "BOOL"), ("Busy", "BOOL"),
        ("CommandAborted", "BOOL"), ("Error", "BOOL"), ("ErrorID", "WORD")],
       master=True),
    fb("MC_GearOut", "spec 07 §2.4", "Y",
       [("Execute", "BOOL", "FALSE"), ("SlavePosition", "LREAL", "0.0"), ("SyncProfileReference", "DINT", "1"),
        ("MasterStopDistance", "LREAL", "0.0"), ("Deceleration", "LREAL", "-1.0"), ("Jerk", "LREAL", "-1.0"),
        ("SyncOutDirection", "DINT", "3")],
       [("StartSyncOut", "BOOL")] + HANDSHAKE),
    fb("MC_CamIn", "spec 07 §3.4", "Y",
       [("Cam", "CAM", "NULL"), ("Execute", "BOOL", "FALSE"), ("MasterOffset", "LREAL", "0.0"),
        ("SlaveOffset", "LREAL", "0.0"), ("MasterScaling", "LREAL", "1.0"), ("SlaveScaling", "LREAL", "1.0"),
        ("MasterSyncPosition", "LREAL", "0.0"), ("SyncProfileReference", "DINT", "1"),
        ("MasterStartDistance", "LREAL", "0.0"), ("Velocity", "LREAL", "-1.0")] + DYN +
       [("ApplicationMode", "DINT", "0"), ("SyncDirection", "DINT", "3")],
       [("StartSync", "BOOL"), ("InSync", "BOOL"), ("Busy", "BOOL"), ("CommandAborted", "BOOL"), ("Error", "BOOL"),
        ("ErrorID", "WORD"), ("EndOfProfile", "BOOL")],
       master=True),
    fb("MC_CamOut", "spec 07 §3.5", "Y",
       [("Execute", "BOOL", "FALSE"), ("SlavePosition", "LREAL", "0.0"), ("SyncProfileReference", "DINT", "1"),
        ("MasterStopDistance", "LREAL", "0.0"), ("Deceleration", "LREAL", "-1.0"), ("Jerk", "LREAL", "-1.0"),
        ("SyncOutDirection", "DINT", "3")],
       [("StartSyncOut", "BOOL")] + HANDSHAKE),
    fb("MC_PhasingAbsolute", "spec 07 §4.1", "Y", PHASING_INPUTS,
       [("StartPhasing", "BOOL")] + HANDSHAKE + [("AbsolutePhaseShift", "LREAL")], master=True),
    fb("MC_PhasingRelative", "spec 07 §4.1", "Y", PHASING_INPUTS,
       [("StartPhasing", "BOOL")] + HANDSHAKE + [("CoveredPhaseShift", "LREAL")], master=True),
    fb("MC_OffsetAbsolute", "spec 07 §4.2", "Y", OFFSET_INPUTS,
       [("StartOffset", "BOOL")] + HANDSHAKE + [("AbsoluteOffset", "LREAL")]),
    fb("MC_OffsetRelative", "spec 07 §4.2", "Y", OFFSET_INPUTS,
       [("StartOffset", "BOOL")] + HANDSHAKE + [("CoveredOffset", "LREAL")]),
    fb("MC_LeadingValueAdditive", "spec 07 §4.3", "Y",
       [("Enable", "BOOL", "FALSE"), ("Position", "LREAL", "0.0"), ("Velocity", "LREAL", "0.0"),
        ("Acceleration", "LREAL", "0.0")],
       [("Busy", "BOOL"), ("Error", "BOOL"), ("ErrorID", "WORD")]),
    fb("MC_SynchronizedMotionSimulation", "spec 07 §4.4", "Y", [("Enable", "BOOL", "FALSE")],
       [("InSimulation", "BOOL"), ("Busy", "BOOL"), ("Error", "BOOL"), ("ErrorID", "WORD")]),
    # The cam's own instructions (spec 07 §3.2, §3.6): the TO_Cam is their technology object; each completes in
    # the call of its rising edge (decision C2).
    fb("MC_InterpolateCam", "spec 07 §3.2", "C", [("Execute", "BOOL", "FALSE")], HANDSHAKE),
    fb("MC_GetCamFollowingValue", "spec 07 §3.6", "C",
       [("Execute", "BOOL", "FALSE"), ("LeadingValue", "LREAL", "0.0")] + CAM_SCALING,
       [("Value", "LREAL"), ("FirstDerivative", "LREAL"), ("SecondDerivative", "LREAL")] + HANDSHAKE),
    fb("MC_GetCamFollowingValueCyclic", "spec 07 §3.6", "C",
       [("Enable", "BOOL", "FALSE"), ("LeadingValue", "LREAL", "0.0")] + CAM_SCALING,
       [("Valid", "BOOL"), ("Busy", "BOOL"), ("Error", "BOOL"), ("ErrorID", "WORD"), ("Value", "LREAL"),
        ("FirstDerivative", "LREAL"), ("SecondDerivative", "LREAL")]),
    fb("MC_GetCamLeadingValue", "spec 07 §3.6", "C",
       [("Execute", "BOOL", "FALSE"), ("FollowingValue", "LREAL", "0.0"), ("ApproachLeadingValue", "LREAL", "0.0"),
        ("ApproachDirection", "DINT", "3")] + CAM_SCALING,
       [("Value", "LREAL")] + HANDSHAKE),
    fb("MC_CopyCamData", "spec 07 §3.6", "C",
       [("Execute", "BOOL", "FALSE"), ("Mode", "DINT", "0"), ("StartPointCam", "DINT", "1"),
        ("StartSegmentCam", "DINT", "1"), ("StartPointArray", "DINT", "0"), ("StartSegmentArray", "DINT", "0"),
        ("NumberOfPoints", "DINT", "0"), ("NumberOfSegments", "DINT", "0"), ("ArrayOfPoints", "POINTS", "NULL"),
        ("ArrayOfPointsLength", "DINT", "0"), ("ArrayOfSegments", "SEGMENTS", "NULL"),
        ("ArrayOfSegmentsLength", "DINT", "0")],
       HANDSHAKE),
]

HEADER_NOTE = "Generated by capi/generate.py from its table: do not edit; edit the table and run it again."


def c_default(iec_type, value):
    if iec_type == "BOOL":
        return "true" if value == "TRUE" else "false"
    return value


def cpp_literal(iec_type, value):
    if iec_type == "BOOL":
        return "true" if value == "TRUE" else "false"
    if iec_type in ("PROFILE", "CAM", "POINTS", "SEGMENTS"):
        return "nullptr"
    return value


def c_header():
    out = [f"/* {HEADER_NOTE} */",
           "/* The MC_* instructions of <tomc/tomc.h>: one struct per instruction with the manual's inputs and",
           " * outputs as fields (the IEC function block's instance data), tomc_<FB>_init() that sets the struct",
           " * version and the inputs' defaults, and tomc_<FB>_call() that calls the instance with its technology",
           " * object. Keep one instance per call site, as in a PLC program; do not share one between axes. */",
           "#ifndef TOMC_TOMC_INSTRUCTIONS_H",
           "#define TOMC_TOMC_INSTRUCTIONS_H",
           "/* Included by <tomc/tomc.h>. */",
           "#ifdef __cplusplus",
           'extern "C" {',
           "#endif",
           "",
           "/* MC_PositionProfile.TimePosition (spec 03 §4.7): x = time in s, y = position in the axis' position unit,",
           " * Time strictly increasing; the structure must stay unchanged while a job follows it (decision L1). */",
           "#define TOMC_MAX_TIME_POSITION_POINTS 128",
           "typedef struct tomc_time_position_point {",
           "  double Time;",
           "  double Position;",
           "} tomc_time_position_point;",
           "typedef struct tomc_time_position_profile {",
           "  int32_t NumberOfPoints; /* 2 ... TOMC_MAX_TIME_POSITION_POINTS */",
           "  tomc_time_position_point Point[TOMC_MAX_TIME_POSITION_POINTS];",
           "} tomc_time_position_profile;",
           "",
           "/* MC_CopyCamData's elements (spec 07 §3.1 TO_Cam_Struct_PointData / TO_Cam_Struct_SegmentData): a segment is",
           " * y = a6·x⁶ + … + a1·x + a0 + sineAmplitude·sin(sinePeriod·x + sinePhase) on [xmin, xmax], x absolute. */",
           "typedef struct tomc_cam_point {",
           "  double x;",
           "  double y;",
           "} tomc_cam_point;",
           "typedef struct tomc_cam_segment {",
           "  double xmin, xmax;",
           "  double a0, a1, a2, a3, a4, a5, a6;",
           "  double sineAmplitude, sinePeriod, sinePhase;",
           "} tomc_cam_segment;",
           ""]
    for f in TABLE:
        kinds = ", ".join(KIND_NAMES[k] for k in f["kinds"])
        out.append(f"/* {f['name']} ({f['spec']}) on {kinds}. */")
        out.append(f"typedef struct tomc_{f['name']} {{")
        out.append("  tomc_struct_header header; /* set by the init function */")
        out.append("  /* inputs */")
        if f["master"] == "Master":
            out.append("  const tomc_object* Master; /* the leading axis or external encoder */")
        elif f["master"]:
            out.append(f"  const tomc_object* {f['master']}; /* a positioning or synchronous axis */")
        for name, t, _ in f["inputs"]:
            note = {"CAM": f" /* a TO_Cam{' (tomc: instead of ' + CAM_AS[name] + ')' if name in CAM_AS else ''} */", "POINTS": " /* ArrayOfPointsLength elements */",
                    "SEGMENTS": " /* ArrayOfSegmentsLength elements */"}.get(t, "")
            if name in ARRAY_LENGTHS:
                note = " /* tomc: the number of elements the array above holds */"
            out.append(f"  {TYPES[t]} {name};{note}")
        out.append("  /* outputs */")
        for name, t in f["outputs"]:
            out.append(f"  {TYPES[t]} {name};")
        out.append("  tomc_instance_data instance; /* the handshake's state: owned by the library */")
        out.append(f"}} tomc_{f['name']};")
        out.append(f"TOMC_API void tomc_{f['name']}_init(tomc_{f['name']}* fb);")
        out.append(f"TOMC_API tomc_status tomc_{f['name']}_call(tomc_object* axis, tomc_{f['name']}* fb);")
        out.append("")
    out += ["#ifdef __cplusplus", "}", "#endif", "#endif /* TOMC_TOMC_INSTRUCTIONS_H */", ""]
    return "\n".join(out)


def cpp_glue():
    out = [f"// {HEADER_NOTE}", "// Included by capi/src/tomc_c.cpp inside its namespace; see generate.py.", "",
           "// tomc_time_position_profile is techobjects::TimePositionProfile, field by field.",
           "static_assert(sizeof(tomc_time_position_profile) == sizeof(techobjects::TimePositionProfile));",
           "static_assert(offsetof(tomc_time_position_profile, NumberOfPoints) == offsetof(techobjects::TimePositionProfile, NumberOfPoints));",
           "static_assert(std::is_same_v<decltype(tomc_time_position_profile::NumberOfPoints), decltype(techobjects::TimePositionProfile::NumberOfPoints)>);",
           "static_assert(offsetof(tomc_time_position_profile, Point) == offsetof(techobjects::TimePositionProfile, Point));",
           "static_assert(sizeof(tomc_time_position_point) == sizeof(techobjects::TimePositionPoint));",
           "static_assert(TOMC_MAX_TIME_POSITION_POINTS == techobjects::kMaxTimePositionPoints);",
           "// tomc_cam_point / tomc_cam_segment are TO_Cam_Struct_PointData / TO_Cam_Struct_SegmentData (all doubles).",
           "static_assert(sizeof(tomc_cam_point) == sizeof(techobjects::TO_Cam_Struct_PointData));",
           "static_assert(offsetof(tomc_cam_point, y) == offsetof(techobjects::TO_Cam_Struct_PointData, y));",
           "static_assert(sizeof(tomc_cam_segment) == sizeof(techobjects::TO_Cam_Struct_SegmentData));",
           "static_assert(offsetof(tomc_cam_segment, a0) == offsetof(techobjects::TO_Cam_Struct_SegmentData, a0));",
           "static_assert(offsetof(tomc_cam_segment, sinePhase) == offsetof(techobjects::TO_Cam_Struct_SegmentData, sinePhase));",
           ""]
    for f in TABLE:
        n = f["name"]
        kinds = " | ".join(KIND_CONSTANTS[k] for k in f["kinds"])
        cam_fb = f["kinds"] == "C"  # the cam's instructions are not templates over the TO type
        out.append(f"struct Fb_{n} {{")
        out.append(f"  using C = tomc_{n};")
        out.append(f"  template <typename Axis> using Cpp = instructions::{n}{'' if cam_fb else '<Axis>'};")
        out.append(f'  static constexpr const char* kName = "{n}";')
        out.append(f"  static constexpr unsigned kKinds = {kinds};")
        out.append(f"  static constexpr bool kMaster = {'true' if f['master'] else 'false'};")
        # MC_InterpolateCam allocates, MC_CopyCamData reads the caller's arrays: not from a user task (decision C22).
        user_program = n in ("MC_InterpolateCam", "MC_CopyCamData")
        out.append(f"  static constexpr bool kUserProgramOnly = {'true' if user_program else 'false'};")
        # The input and what is wrong with it: a handle that is not a TO_Cam, or a cam given beside the point
        # structure it stands in for.
        cams = [name for name, t, _ in f["inputs"] if t == "CAM"]
        if cams:
            out.append("  static const char* wrong_object(const C& c) noexcept {")
            for cam in cams:
                out.append(f'    if (c.{cam} != nullptr && cam_of(c.{cam}) == nullptr) return "{cam}: not a TO_Cam";')
                if cam in CAM_AS:
                    out.append(f"    if (c.{cam} != nullptr && c.{CAM_AS[cam]} != nullptr)")
                    out.append(f'      return "{cam}: {CAM_AS[cam]} is given too (a profile is a TO_Cam or the point structure)";')
            out.append("    return nullptr;")
            out.append("  }")
        else:
            out.append("  static const char* wrong_object(const C&) noexcept { return nullptr; }")
        if f["master"]:
            m = f["master"]
            out.append(f'  static constexpr const char* kMasterName = "{m}";')
            out.append(f"  static const tomc_object* master(const C& c) noexcept {{ return c.{m}; }}")
            out.append(f"  template <typename T> static void set_master(T& t, const techobjects::LeadingValueSource* s) noexcept {{ t.{m} = s; }}")
        out.append("  template <typename T> static void in(const C& c, T& t) noexcept {")
        for name, t, _ in f["inputs"]:
            if t == "PROFILE":  # the same layout (static_asserts below the table)
                out.append(f"    t.{name} = reinterpret_cast<const techobjects::TimePositionProfile*>(c.{name});")
                continue
            if t == "CAM" and name in CAM_AS:  # after the input it stands in for (the table's order)
                out.append(f"    if (c.{name} != nullptr) t.{CAM_AS[name]} = cam_of(c.{name});")
                continue
            if t == "CAM":
                out.append(f"    t.{name} = cam_of(c.{name});")
                continue
            if t in ("POINTS", "SEGMENTS"):  # the same layout; the length is the input after it
                element = "PointData" if t == "POINTS" else "SegmentData"
                out.append(f"    t.{name} = array_of(reinterpret_cast<const techobjects::TO_Cam_Struct_{element}*>(c.{name}), c.{name}Length);")
                continue
            if name in ARRAY_LENGTHS:
                continue
            cast = "static_cast<bool>" if t == "BOOL" else ""
            out.append(f"    t.{name} = {cast}(c.{name});")
        out.append("  }")
        out.append("  template <typename T> static void out(const T& t, C& c) noexcept {")
        for name, _ in f["outputs"]:
            out.append(f"    c.{name} = t.{name};")
        out.append("  }")
        out.append("  static void copy_outputs(const C& from, C& to) noexcept {")
        for name, _ in f["outputs"]:
            out.append(f"    to.{name} = from.{name};")
        out.append("  }")
        out.append("  static void defaults(C& c) noexcept {")
        for name, t, d in f["inputs"]:
            out.append(f"    c.{name} = {cpp_literal(t, d)};")
        out.append("  }")
        out.append("};")
        first = KIND_CLASSES[f["kinds"][0]]
        cls = f"instructions::{n}" if cam_fb else f"instructions::{n}<techobjects::{first}>"
        for name, t, d in f["inputs"]:
            if t in ("PROFILE", "CAM", "POINTS", "SEGMENTS") or name in ARRAY_LENGTHS:
                continue  # pointers and spans, none by default (not comparable in a constant)
            out.append(f"static_assert({cls}{{}}.{name} == {cpp_literal(t, d)},")
            out.append(f'              "{n}.{name}: the table\'s default differs from the C++ class");')
        out.append(f"extern \"C\" void tomc_{n}_init(tomc_{n}* fb) {{ init_fb<Fb_{n}>(fb); }}")
        out.append(f"extern \"C\" tomc_status tomc_{n}_call(tomc_object* axis, tomc_{n}* fb) {{")
        out.append(f"  return call_fb<Fb_{n}>(axis, fb);")
        out.append("}")
        out.append("")
    return "\n".join(out)


def st_declarations():
    out = [f"(* {HEADER_NOTE} *)",
           "(* The MC_* function blocks of tomc as IEC 61131-3 Structured Text declarations, for a runtime that",
           "   compiles ST and binds them as external function blocks to the C functions of <tomc/tomc.h>",
           "   (tomc_<FB>_call(axis, &instance)). Axis and Master are technology-object handles (tomc_object*). *)",
           "",
           "TYPE",
           "  TO_Object : LWORD; (* a tomc_object* handle: TO_SpeedAxis, TO_PositioningAxis, TO_SynchronousAxis,",
           "                        TO_ExternalEncoder, TO_Cam *)",
           "END_TYPE",
           ""]
    for f in TABLE:
        kinds = ", ".join(KIND_NAMES[k] for k in f["kinds"])
        out.append(f"(* {f['name']} ({f['spec']}): Axis is a {kinds} *)")
        out.append(f"FUNCTION_BLOCK {f['name']}")
        out.append("VAR_INPUT")
        out.append("  Axis : TO_Object;")
        if f["master"]:
            out.append(f"  {f['master']} : TO_Object;")
        for name, t, d in f["inputs"]:
            if t == "PROFILE":
                out.append(f"  {name} : LWORD; (* a tomc_time_position_profile* *)")
                continue
            if t == "CAM":
                instead = f" (tomc: instead of {CAM_AS[name]})" if name in CAM_AS else ""
                out.append(f"  {name} : TO_Object; (* a TO_Cam{instead} *)")
                continue
            if t in ("POINTS", "SEGMENTS"):
                out.append(f"  {name} : LWORD; (* a {TYPES[t][6:-1]}* *)")
                continue
            out.append(f"  {name} : {t} := {d};")
        out.append("END_VAR")
        out.append("VAR_OUTPUT")
        for name, t in f["outputs"]:
            out.append(f"  {name} : {t};")
        out.append("END_VAR")
        out.append("END_FUNCTION_BLOCK")
        out.append("")
    return "\n".join(out)


def main():
    here = pathlib.Path(__file__).resolve().parent
    files = {
        here / "include/tomc/tomc_instructions.h": c_header(),
        here / "src/instructions.inc": cpp_glue(),
        here / "iec/tomc_motion.st": st_declarations(),
    }
    if len(sys.argv) > 1 and sys.argv[1] == "--check":
        stale = [str(p.relative_to(here)) for p, text in files.items() if not p.exists() or p.read_text() != text]
        if stale:
            print("out of date (run python3 capi/generate.py): " + ", ".join(stale))
            return 1
        print("generated files match the table")
        return 0
    for p, text in files.items():
        p.parent.mkdir(parents=True, exist_ok=True)
        p.write_text(text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
