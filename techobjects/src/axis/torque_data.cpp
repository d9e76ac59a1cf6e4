#include "tomc/techobjects/axis/torque_data.hpp"

#include <cmath>
#include <numbers>

#include "tomc/techobjects/axis/enable_level_job.hpp"
#include "tomc/techobjects/axis/error_ids.hpp"
#include "tomc/telegrams/normalisation.hpp"

namespace tomc::techobjects {

namespace tg = tomc::telegrams;

namespace {

constexpr double kMaxTorqueValue = 1.0e12;  // the range of Value, UpperLimit, LowerLimit (spec 03 §4.18)

bool valid_value(double v) noexcept {
  return std::isfinite(v) && std::fabs(v) <= kMaxTorqueValue;
}

// The start conditions both jobs share (spec 01 §8.12/§8.13, §12 scenario 36): the panel's master control,
// no MC_Stop, and telegram 750 on a real drive (a virtual or simulated axis accepts and outputs nothing,
// decision Q2).
std::uint16_t start_rejection(const TorqueDataConditions& c) noexcept {
  if (c.panel != 0) return c.panel;
  if (c.stop_locks) return error_id::kLockedByStop;
  if (c.drive && !c.telegram_750) return error_id::kNoTorqueData;
  return 0;
}

}  // namespace

TorqueJobState TorqueDataJobs::additive(const TorqueAdditiveInputs& in,
                                        const TorqueDataConditions& c) noexcept {
  enable_level_call(
      in.Enable, additive_active_, additive_error_,
      [&]() -> std::uint16_t {
        if (!valid_value(in.Value)) return error_id::kInvalidTorqueValue;
        if (additive_active_) return 0;  // the start conditions only when it starts (decision Q1)
        if (const auto e = start_rejection(c)) return e;
        if (!c.enabled) return error_id::kAxisNotEnabled;  // spec 03 §4.18.1 prerequisites
        return 0;
      },
      [&] { value_ = static_cast<float>(in.Value); });
  return TorqueJobState{additive_active_, additive_error_ != 0, additive_error_};
}

TorqueJobState TorqueDataJobs::range(const TorqueRangeInputs& in, const TorqueDataConditions& c) noexcept {
  enable_level_call(
      in.Enable, range_active_, range_error_,
      [&]() -> std::uint16_t {
        if (!valid_value(in.UpperLimit) || !valid_value(in.LowerLimit) || in.UpperLimit <= in.LowerLimit)
          return error_id::kInvalidTorqueRange;
        if (range_active_) return 0;
        if (const auto e = start_rejection(c)) return e;
        // Mutual exclusion (spec 03 §4.18.2 priority, seed L10730): neither replaces the other.
        if (c.torque_limiting) return error_id::kTorqueLimitingExclusion;
        return 0;
      },
      [&] {
        // Inverted setpoints: upper' = −lower, lower' = −upper (spec 01 §8.13 [derived], seed L4278).
        limit_pos_ = tg::torque_to_n2(c.inverse ? -in.LowerLimit : in.UpperLimit, c.reference);
        limit_neg_ = tg::torque_to_n2(c.inverse ? -in.UpperLimit : in.LowerLimit, c.reference);
      });
  return TorqueJobState{range_active_, range_error_ != 0, range_error_};
}

void TorqueDataJobs::write(DriveConnection& drive, double total, double reference,
                           bool inverse) const noexcept {
  const std::int16_t m_add1 = tg::torque_to_n2(inverse ? -total : total, reference);
  // Without MC_TorqueRange: ±ReferenceTorque (ReferenceForce), spec 01 §8.13, TV14.
  if (range_active_) {
    drive.set_torque_data(m_add1, limit_pos_, limit_neg_);
  } else {
    drive.set_torque_data(m_add1, 0x4000, static_cast<std::int16_t>(-0x4000));
  }
}

double precontrol_torque(double acceleration, const TorquePrecontrolMechanics& m) noexcept {
  const double scale = m.scale_percent / 100.0;
  if (m.linear_motor) {  // a force: (motor mass + load mass) · a [m/s²]
    return scale * (m.motor_inertia + m.load_inertia) * acceleration * m.metres_or_radians_per_unit;
  }
  // Motor side: α = 2π·r·a; the load inertia reflected through load SI per motor radian s/(2π·r).
  const double radians_per_unit = 2.0 * std::numbers::pi * m.motor_revolutions_per_unit;
  if (radians_per_unit == 0.0) return 0.0;
  const double load_per_motor_radian = m.metres_or_radians_per_unit / radians_per_unit;
  const double inertia = m.motor_inertia + m.load_inertia * load_per_motor_radian * load_per_motor_radian;
  return scale * inertia * radians_per_unit * acceleration;
}

}  // namespace tomc::techobjects
