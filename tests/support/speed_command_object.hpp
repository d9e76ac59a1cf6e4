#pragma once
// A minimal technology object for tests and benchmarks of the runtime: it enables its drive through a
// DriveConnection and commands a speed profile (a sine), as an axis would from MC_Servo/MC_Interpolator.
#include <cmath>
#include <string_view>

#include "tomc/techobjects/drive/drive_connection.hpp"
#include "tomc/techobjects/runtime/runtime.hpp"

namespace tomc::testing {

class SpeedCommandObject final : public techobjects::TechnologyObject {
 public:
  SpeedCommandObject(techobjects::DeviceIo& device, const techobjects::DriveConnectionConfig& config,
                     double amplitude_rpm, double period_s)
      : connection_(device, config), amplitude_rpm_(amplitude_rpm), period_s_(period_s) {}

  std::string_view name() const noexcept override { return "speed-command"; }
  void servo(const techobjects::CycleClock&) noexcept override {
    connection_.read();
    connection_.write(techobjects::ServoCommand{.speed_rpm = setpoint_rpm_});
  }
  void interpolate(const techobjects::CycleClock& clock) noexcept override {
    connection_.request(telegrams::DriveRequest::kOperate);
    const double phase = 2.0 * 3.141592653589793 * clock.time_s() / period_s_;
    setpoint_rpm_ = connection_.in_operation() ? amplitude_rpm_ * std::sin(phase) : 0.0;
  }
  techobjects::DriveConnection& connection() noexcept { return connection_; }

 private:
  techobjects::DriveConnection connection_;
  double amplitude_rpm_;
  double period_s_;
  double setpoint_rpm_ = 0.0;
};

}  // namespace tomc::testing
