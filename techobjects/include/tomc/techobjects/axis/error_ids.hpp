#pragma once
// The ErrorIDs tomc's instructions report. Chapter 9 of the manual names only a few (spec 03 §5); the others
// wait for the separate Siemens "Alarms and error IDs" manual, so tomc defines its own values in a block of
// its own (16#81xx) and docs/errors.md lists every one with its meaning and source.

#include <cstdint>
#include <string_view>

namespace tomc::techobjects::error_id {

inline constexpr std::uint16_t kNone = 0x0000;
// From the manual (spec 03 §5):
inline constexpr std::uint16_t kAbortedByAlarmReaction =
    0x8001;  // a technology alarm's stop reaction ended the job
inline constexpr std::uint16_t kJogWrongDirection = 0x8007;   // JogForward and JogBackward both TRUE
inline constexpr std::uint16_t kControlPanelActive = 0x8012;  // the axis control panel has control priority
inline constexpr std::uint16_t kLifebeatExpired = 0x8013;     // the panel's lifebeat monitoring time elapsed
// Synchronous operation, numbered as in the manual's error list (spec 07 §1.10, ALM8):
inline constexpr std::uint16_t kInvalidRatioNumerator = 0x8017;    // RatioNumerator = 0
inline constexpr std::uint16_t kInvalidRatioDenominator = 0x8018;  // RatioDenominator < 1
inline constexpr std::uint16_t kRecursiveLeadingValue = 0x8019;    // the follower leads its own leader
// Cams and camming (spec 07 §1.10, §3.2–§3.6; ALM8):
inline constexpr std::uint16_t kInvalidMasterOffset = 0x8021;   // MasterOffset not finite
inline constexpr std::uint16_t kInvalidSlaveOffset = 0x8022;    // SlaveOffset not finite
inline constexpr std::uint16_t kInvalidMasterScaling = 0x8023;  // MasterScaling = 0.0 (or not finite)
inline constexpr std::uint16_t kInvalidSlaveScaling = 0x8024;   // SlaveScaling unusable (inversion: 0.0)
inline constexpr std::uint16_t kInvalidApproachValue = 0x8062;  // MC_GetCamLeadingValue
inline constexpr std::uint16_t kNoLeadingValue = 0x8063;        // no leading value for this following value
inline constexpr std::uint16_t kNoFollowingValue = 0x8064;      // the leading value is outside the cam
inline constexpr std::uint16_t kInvalidApproachDirection = 0x8065;  // ApproachDirection not 1...3
inline constexpr std::uint16_t kCamEndReached =
    0x8066;                                           // no solution in ApproachDirection before the cam ends
inline constexpr std::uint16_t kCamEmpty = 0x80AA;    // MC_InterpolateCam: no valid point or segment
inline constexpr std::uint16_t kCamInUse = 0x80AB;    // MC_InterpolateCam: the cam is used by camming
inline constexpr std::uint16_t kCamInvalid = 0x80AC;  // MC_InterpolateCam: the elements make no cam
inline constexpr std::uint16_t kInvalidMasterStartDistance =
    0x8026;                                                       // MasterStartDistance / MasterStopDistance
inline constexpr std::uint16_t kInvalidApplicationMode = 0x8027;  // MC_CamIn.ApplicationMode not 0...2
inline constexpr std::uint16_t kInvalidMasterSyncPosition = 0x8034;
inline constexpr std::uint16_t kInvalidSyncProfileReference = 0x8036;
inline constexpr std::uint16_t kInvalidSlavePosition = 0x8037;    // MC_GearOut stop position not reachable
inline constexpr std::uint16_t kInvalidPhaseShift = 0x8070;       // PhaseShift not finite
inline constexpr std::uint16_t kNoSynchronousOperation = 0x8075;  // phasing/offset: no gearing or camming
// A new synchronous job while the synchronous operation is simulated (MC_SynchronizedMotionSimulation)
inline constexpr std::uint16_t kSynchronousOperationSimulated = 0x8076;
inline constexpr std::uint16_t kNoGearing = 0x8077;               // MC_GearOut without MC_GearIn/GearInPos
inline constexpr std::uint16_t kNoCamming = 0x8078;               // MC_CamOut without MC_CamIn
inline constexpr std::uint16_t kNoActiveCamming = 0x808B;         // MC_CamIn profile 5 without active camming
inline constexpr std::uint16_t kVelocityGearingActive = 0x8079;   // phasing/offset during MC_GearInVelocity
inline constexpr std::uint16_t kInvalidOffset = 0x8080;           // Offset not finite
inline constexpr std::uint16_t kInvalidOffsetDistance = 0x8081;   // OffsetDistance <= 0 (profiles 1, 2)
inline constexpr std::uint16_t kInvalidPhasingDistance = 0x8082;  // PhasingDistance <= 0 (profiles 1, 2)
inline constexpr std::uint16_t kInvalidProfileReference = 0x8083;    // phasing/offset ProfileReference
inline constexpr std::uint16_t kInvalidStartPosition = 0x8084;       // StartPosition not finite
inline constexpr std::uint16_t kPhasingAndOffsetExclusive = 0x808A;  // a leading and a following value offset
inline constexpr std::uint16_t kLeadingValueReversed = 0x808C;  // reversal during a leading/following offset
inline constexpr std::uint16_t kPhasingProfileNeedsGearing = 0x80A8;  // phasing profile 0 during camming
inline constexpr std::uint16_t kNotSynchronous = 0x80A9;  // phasing/offset outside status "Synchronous"
inline constexpr std::uint16_t kOutsideCam = 0x80AD;      // MC_CamIn sync position / leader outside the cam
inline constexpr std::uint16_t kHomingDuringGearInPos = 0x80A1;  // MC_Home while MC_GearInPos is active
// tomc's own (spec 03 §5 [IMPL]):
inline constexpr std::uint16_t kRejectedByRunningJob = 0x8101;  // §9.19 matrix cell "N"
inline constexpr std::uint16_t kLockedByStop = 0x8102;    // an MC_Stop with Execute = TRUE blocks motion jobs
inline constexpr std::uint16_t kAxisNotEnabled = 0x8103;  // the TO is not enabled (MC_Power.Status = FALSE)
inline constexpr std::uint16_t kAxisBlockedByAlarm = 0x8104;      // an alarm reaction blocks the TO
inline constexpr std::uint16_t kAxisNotHomed = 0x8105;            // MC_MoveAbsolute needs a homed axis
inline constexpr std::uint16_t kEncoderNotValid = 0x8106;         // the encoder's actual value is not valid
inline constexpr std::uint16_t kHomingModeNotAvailable = 0x8107;  // MC_Home mode not available on this TO
inline constexpr std::uint16_t kNotPositionControlled =
    0x8108;                                     // the job needs position-controlled operation
inline constexpr std::uint16_t kBusy = 0x8109;  // MC_SaveAbsoluteEncoderData: a backup is still being written
inline constexpr std::uint16_t kBackupFailed =
    0x810A;  // MC_SaveAbsoluteEncoderData: the file could not be written
inline constexpr std::uint16_t kInvalidVelocity = 0x8110;      // Velocity = 0.0 or not finite
inline constexpr std::uint16_t kInvalidAcceleration = 0x8111;  // Acceleration = 0.0 or not finite
inline constexpr std::uint16_t kInvalidDeceleration = 0x8112;  // Deceleration = 0.0 or not finite
inline constexpr std::uint16_t kInvalidJerk = 0x8113;          // Jerk not finite
inline constexpr std::uint16_t kInvalidMode = 0x8114;          // Mode out of range (e.g. MC_Stop.Mode = 1)
inline constexpr std::uint16_t kInvalidDirection = 0x8115;     // Direction out of range
inline constexpr std::uint16_t kInvalidStartMode = 0x8116;     // MC_Power.StartMode not 0/1
inline constexpr std::uint16_t kInvalidStopMode = 0x8117;      // MC_Power.StopMode not 0..3
inline constexpr std::uint16_t kInvalidPosition =
    0x8118;  // Position/Distance not finite, or outside the modulo range
inline constexpr std::uint16_t kInvalidBufferMode = 0x8119;  // BufferMode not 0/1
inline constexpr std::uint16_t kInvalidSensor = 0x811A;      // MC_Home.Sensor names no usable encoder
// MC_SetSensor (decision B4): Sensor/ReferenceSensor not 1...4 or no configured encoder of the axis
inline constexpr std::uint16_t kSensorNotConfigured = 0x811B;
inline constexpr std::uint16_t kSensorSwitchBlocked = 0x811C;  // MC_SetSensor while MC_Home or a restart runs
// MC_SetSensor Mode 0/1 away from encoder 1 on a simulated axis (seed 004 §6.1.7, decision B7)
inline constexpr std::uint16_t kSensorSwitchSimulated = 0x811D;
inline constexpr std::uint16_t kRestartNeedsDisabledAxis = 0x8120;  // MC_Reset.Restart while enabled or busy
inline constexpr std::uint16_t kInvalidParameterNumber =
    0x8130;  // MC_WriteParameter: index not writable on this TO
inline constexpr std::uint16_t kInvalidParameterValue = 0x8131;  // MC_WriteParameter: value not permitted
inline constexpr std::uint16_t kInvalidBitMask = 0x8132;      // MC_SetAxisSTW: mask outside the writable bits
inline constexpr std::uint16_t kNoDriveTelegram = 0x8133;     // MC_SetAxisSTW on a virtual/simulated axis
inline constexpr std::uint16_t kInvalidTorqueLimit = 0x8140;  // MC_TorqueLimiting.Limit not finite or > 1E12
// MC_TorqueLimiting Mode 0: the drive telegram carries no torque reduction (MOMRED, telegrams 10x)
inline constexpr std::uint16_t kNoTorqueReduction = 0x8141;
// MC_TorqueLimiting Mode 1: Clamping.PositionTolerance >= Clamping.FollowingErrorDeviation, or the
// following-error monitoring's MaxValue <= Clamping.FollowingErrorDeviation (spec 01 §8.11)
inline constexpr std::uint16_t kInvalidClampingConfiguration = 0x8142;
// MC_TorqueRange while MC_TorqueLimiting limits, and MC_TorqueLimiting while MC_TorqueRange limits (spec 03
// §4.18.2/§4.18.3: "rejected with an error", no number given)
inline constexpr std::uint16_t kTorqueLimitingExclusion = 0x8143;
// MC_TorqueAdditive / MC_TorqueRange on a drive without supplementary telegram 750 (spec 01 §12 scenario 36)
inline constexpr std::uint16_t kNoTorqueData = 0x8144;
// MC_TorqueRange: UpperLimit or LowerLimit not finite or outside ±1.0E12, or UpperLimit <= LowerLimit
inline constexpr std::uint16_t kInvalidTorqueRange = 0x8145;
// MC_TorqueAdditive: Value not finite or outside ±1.0E12
inline constexpr std::uint16_t kInvalidTorqueValue = 0x8146;
// Cams, tomc's own: MC_GetCamFollowingValue/LeadingValue on a cam that is not interpolated (the manual names
// alarm 612 for camming with such a cam, spec 07 §3.2, but no ErrorID for the read instructions)
inline constexpr std::uint16_t kCamNotInterpolated = 0x8150;
// MC_CopyCamData: an element range outside the cam's Point/Segment arrays or outside the given source arrays
inline constexpr std::uint16_t kInvalidCamElementRange = 0x8151;
// MC_SynchronizedMotionSimulation, tomc's own: the leading value or the follower moves when the simulation
// starts (the manual's procedure: the leader at standstill; a moving follower would be left without a job)
inline constexpr std::uint16_t kSimulationNeedsStandstill = 0x8152;
// MC_PositionProfile (spec 03 §4.7; tomc's profile structure, decision L1): no profile, fewer than 2 or more
// than kMaxTimePositionPoints points
inline constexpr std::uint16_t kInvalidTimePositionProfile = 0x8180;
inline constexpr std::uint16_t kTimePositionOutOfOrder = 0x8181;  // the times are not strictly increasing
inline constexpr std::uint16_t kTimePositionNotFinite = 0x8182;   // a time or position is NaN or infinite
inline constexpr std::uint16_t kInvalidStartTime = 0x8183;  // StartTime not within [first time, last time)
inline constexpr std::uint16_t kInvalidPositionProfileReference =
    0x8184;  // MC_PositionProfile.ProfileReference not 0/1
// ProfileReference 1: the profile moves at StartTime and the axis is not already on it (the transition
// profile reaches an absolute start point only at rest, decision L3)
inline constexpr std::uint16_t kProfileStartNotReachable = 0x8185;
// MotionIn (spec 03 §4.17): a setpoint input is NaN or infinite
inline constexpr std::uint16_t kInvalidMotionInSetpoint = 0x8186;
// MC_PositionProfile on a TO_Cam that does not end at rest: the axis stops at the profile's end (seed 004
// §9.7.1), which would be a velocity step (decision L8).
inline constexpr std::uint16_t kProfileNotAtRestAtEnd = 0x8187;
// MC_MotionInSuperimposedAxes: SuperimposingAxis is not configured as a possible superimposing axis of Axis
// (ErrorWord.X16 SuperimposingError, seed 004 §6.14.3.2).
inline constexpr std::uint16_t kSuperimposingAxisNotConfigured = 0x8190;
// MC_MotionInSuperimposedAxes: SuperimposingAxis is not enabled, not position-controlled, or homing (spec 03
// §4.17.4 prerequisites).
inline constexpr std::uint16_t kSuperimposingAxisNotReady = 0x8191;
// MC_MotionInSuperimposedAxes: SuperimposingAxis is not at standstill at the superimposition the axis shows
// (StatusPositioning.SuperimposedDistance, within PositioningMonitoring.Window): its setpoint would be a step
// (seed 004 §6.14.3.2 warning).
inline constexpr std::uint16_t kSuperimposingAxisNotAtSuperimposition = 0x8192;

std::string_view describe(std::uint16_t error_id) noexcept;

}  // namespace tomc::techobjects::error_id
