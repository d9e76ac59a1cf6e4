#include "tomc/techobjects/axis/error_ids.hpp"

namespace tomc::techobjects::error_id {

std::string_view describe(std::uint16_t id) noexcept {
  switch (id) {
    case kNone:
      return "no error";
    case kAbortedByAlarmReaction:
      return "job aborted by the stop reaction of a technology alarm";
    case kJogWrongDirection:
      return "wrong direction specification: JogForward and JogBackward both TRUE";
    case kControlPanelActive:
      return "the axis control panel has control priority (jobs of the user program are rejected)";
    case kLifebeatExpired:
      return "lifebeat monitoring of the axis control panel expired: axis stopped, control priority returned";
    case kInvalidRatioNumerator:
      return "RatioNumerator 0 is not allowed";
    case kInvalidRatioDenominator:
      return "RatioDenominator must be 1 or more";
    case kRecursiveLeadingValue:
      return "the following axis would be the origin of its own leading value";
    case kInvalidMasterStartDistance:
      return "invalid MasterStartDistance / MasterStopDistance";
    case kInvalidMasterSyncPosition:
      return "invalid MasterSyncPosition (the leader is already past the start of synchronization)";
    case kInvalidSyncProfileReference:
      return "invalid SyncProfileReference";
    case kInvalidSlavePosition:
      return "invalid SlavePosition (a linear follower is already inside the stop travel before it, or past "
             "it)";
    case kInvalidMasterScaling:
      return "invalid MasterScaling (0.0)";
    case kInvalidSlaveScaling:
      return "invalid SlaveScaling (0.0 cannot be inverted)";
    case kInvalidApproachValue:
      return "invalid approach value";
    case kNoLeadingValue:
      return "the cam reaches this following value at no leading value";
    case kNoFollowingValue:
      return "the leading value is outside the cam";
    case kInvalidApproachDirection:
      return "invalid ApproachDirection (1, 2 or 3)";
    case kCamEndReached:
      return "no solution in the approach direction before the end of the cam";
    case kCamEmpty:
      return "the cam has no valid point or segment";
    case kCamInUse:
      return "the cam is in use by camming";
    case kCamInvalid:
      return "the cam elements make no cam (a single point, points out of order, a segment with xmin >= "
             "xmax, "
             "a value that is not finite)";
    case kSynchronousOperationSimulated:
      return "the synchronous operation is simulated (MC_SynchronizedMotionSimulation): no new synchronous "
             "job";
    case kSimulationNeedsStandstill:
      return "MC_SynchronizedMotionSimulation: the leading value and the follower must be at standstill";
    case kCamNotInterpolated:
      return "the cam is not interpolated (MC_InterpolateCam)";
    case kInvalidCamElementRange:
      return "MC_CopyCamData: element range outside the cam or the source array";
    case kInvalidTimePositionProfile:
      return "MC_PositionProfile: no time-position profile, or fewer than 2 or more than 128 points";
    case kTimePositionOutOfOrder:
      return "MC_PositionProfile: the times of the profile points are not strictly increasing";
    case kTimePositionNotFinite:
      return "MC_PositionProfile: a time or position of the profile is not finite";
    case kInvalidStartTime:
      return "MC_PositionProfile: StartTime is not within the profile's time range";
    case kInvalidPositionProfileReference:
      return "MC_PositionProfile: ProfileReference must be 0 (relative) or 1 (absolute)";
    case kProfileStartNotReachable:
      return "MC_PositionProfile: an absolute profile moving at StartTime can only be joined by an axis "
             "already "
             "on it";
    case kInvalidMotionInSetpoint:
      return "MotionIn: a setpoint input is not finite";
    case kProfileNotAtRestAtEnd:
      return "MC_PositionProfile: the TO_Cam does not end at rest (its velocity at the last time is not 0)";
    case kSuperimposingAxisNotConfigured:
      return "MC_MotionInSuperimposedAxes: SuperimposingAxis is not a possible superimposing axis of Axis";
    case kSuperimposingAxisNotAtSuperimposition:
      return "MC_MotionInSuperimposedAxes: SuperimposingAxis does not stand at "
             "StatusPositioning.SuperimposedDistance";
    case kSuperimposingAxisNotReady:
      return "MC_MotionInSuperimposedAxes: SuperimposingAxis is not enabled, not position-controlled or "
             "homing";
    case kNoGearing:
      return "no MC_GearIn / MC_GearInPos pending or active";
    case kNoCamming:
      return "no MC_CamIn pending or active";
    case kNoActiveCamming:
      return "MC_CamIn SyncProfileReference 5 without active camming";
    case kInvalidPhaseShift:
      return "invalid PhaseShift";
    case kNoSynchronousOperation:
      return "no gearing or camming active (with this leading value)";
    case kVelocityGearingActive:
      return "not possible while MC_GearInVelocity is active";
    case kInvalidOffset:
      return "invalid Offset";
    case kInvalidOffsetDistance:
      return "invalid OffsetDistance (> 0 for ProfileReference 1, 2)";
    case kInvalidPhasingDistance:
      return "invalid PhasingDistance (> 0 for ProfileReference 1, 2)";
    case kInvalidProfileReference:
      return "invalid ProfileReference";
    case kInvalidStartPosition:
      return "invalid StartPosition";
    case kPhasingAndOffsetExclusive:
      return "a leading value offset and a following value offset cannot run together";
    case kLeadingValueReversed:
      return "the leading value reversed during a leading or following value offset";
    case kPhasingProfileNeedsGearing:
      return "phasing with dynamic parameters (ProfileReference 0) only during gearing";
    case kNotSynchronous:
      return "the synchronous operation is not in status Synchronous";
    case kOutsideCam:
      return "MasterSyncPosition outside the cam, or the leader outside the scaled and shifted cam";
    case kInvalidMasterOffset:
      return "invalid MasterOffset";
    case kInvalidSlaveOffset:
      return "invalid SlaveOffset";
    case kInvalidApplicationMode:
      return "invalid ApplicationMode";
    case kHomingDuringGearInPos:
      return "MC_Home is not possible while MC_GearInPos is active";
    case kRejectedByRunningJob:
      return "rejected by a running job (override matrix cell N)";
    case kLockedByStop:
      return "motion jobs are blocked while MC_Stop.Execute is TRUE";
    case kAxisNotEnabled:
      return "technology object not enabled";
    case kAxisBlockedByAlarm:
      return "technology object blocked by an alarm reaction";
    case kAxisNotHomed:
      return "technology object not homed";
    case kEncoderNotValid:
      return "encoder actual value not valid";
    case kHomingModeNotAvailable:
      return "homing mode not available on this technology object";
    case kNotPositionControlled:
      return "the job needs position-controlled operation";
    case kBusy:
      return "a backup of the absolute-encoder adjustment is still being written";
    case kBackupFailed:
      return "the absolute-encoder backup could not be written";
    case kInvalidPosition:
      return "invalid Position or Distance (not finite, or outside the modulo range)";
    case kInvalidBufferMode:
      return "invalid BufferMode";
    case kInvalidSensor:
      return "invalid Sensor";
    case kInvalidVelocity:
      return "invalid Velocity";
    case kInvalidAcceleration:
      return "invalid Acceleration";
    case kInvalidDeceleration:
      return "invalid Deceleration";
    case kInvalidJerk:
      return "invalid Jerk";
    case kInvalidMode:
      return "invalid Mode";
    case kInvalidDirection:
      return "invalid Direction";
    case kInvalidStartMode:
      return "invalid StartMode";
    case kInvalidStopMode:
      return "invalid StopMode";
    case kRestartNeedsDisabledAxis:
      return "restart needs a disabled technology object";
    case kInvalidParameterNumber:
      return "parameter number not writable on this technology object";
    case kInvalidParameterValue:
      return "parameter value not permitted";
    case kInvalidBitMask:
      return "bit mask selects bits the technology object owns";
    case kNoDriveTelegram:
      return "no drive telegram (virtual axis or simulation)";
    case kInvalidTorqueLimit:
      return "invalid torque/force limit (not finite or above 1E12)";
    case kNoTorqueReduction:
      return "the drive telegram carries no torque reduction (MOMRED, telegrams 102 to 106)";
    case kInvalidClampingConfiguration:
      return "fixed-stop detection: PositionTolerance must be below FollowingErrorDeviation, which must be "
             "below the maximum following error";
    case kTorqueLimitingExclusion:
      return "MC_TorqueRange and MC_TorqueLimiting exclude each other: the other one limits the torque";
    case kNoTorqueData:
      return "the drive has no supplementary telegram 750 (torque data)";
    case kInvalidTorqueRange:
      return "invalid torque/force range (not finite, outside 1E12, or UpperLimit not above LowerLimit)";
    case kInvalidTorqueValue:
      return "invalid additive torque/force (not finite or outside 1E12)";
    default:
      return "unknown ErrorID";
  }
}

}  // namespace tomc::techobjects::error_id
