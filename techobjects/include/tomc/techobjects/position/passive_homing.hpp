#pragma once
// Passive (on-the-fly) homing (spec 02 §5.6, seed 004 §6.11.4): no motion of its own — the reference mark is
// detected while the user's motion moves the axis or encoder, and only while it moves in the configured
// homing direction. Shared by TO_PositioningAxis and TO_ExternalEncoder. noexcept, no allocation.

#include <cstdint>
#include <optional>

#include "tomc/techobjects/drive/encoder_channel.hpp"

namespace tomc::techobjects {

// Edges of the homing digital input (or reference cam), seen at the servo rate and kept for the interpolator.
struct InputEdges {
  bool was_active = false;
  bool entered = false;
  bool left = false;
  double position = 0.0;  // actual position at the last edge

  void observe(bool active, double actual_position) noexcept {
    if (active != was_active) {
      (active ? entered : left) = true;
      position = actual_position;
    }
    was_active = active;
  }
  void clear() noexcept { entered = left = false; }
};

class PassiveHomingSearch {
 public:
  struct Config {
    std::int32_t method = 0;  // Sensor.PassiveHoming.Mode: 0 zero mark, 1 cam + zero mark, 2 digital input
    std::int32_t direction =
        2;                   // Sensor.PassiveHoming.Direction: 0 positive, 1 negative, 2 current direction
    bool side_input = true;  // Sensor.PassiveHoming.SideInput: TRUE positive side
    double moving_threshold = 0.0;  // |v| above which the axis counts as moving (StandstillSignal threshold)
  };

  void start(const Config& config) noexcept {
    config_ = config;
    active_ = true;
    cam_seen_ = cam_left_ = false;
  }
  void stop(EncoderChannel& encoder) noexcept {
    active_ = false;
    encoder.cancel_reference_mark();
  }
  bool active() const noexcept { return active_; }

  // One interpolator step with what MC_Servo observed. Returns the continuous actual position at the mark
  // once it was found; the search then ends.
  std::optional<double> step(double actual_velocity, const InputEdges& edges, std::optional<double> mark,
                             EncoderChannel& encoder) noexcept;

 private:
  Config config_{};
  bool active_ = false;
  bool cam_seen_ = false;  // cam + zero mark: the cam was detected in the homing direction
  bool cam_left_ = false;  // ... and left: the zero-mark search is armed
};

}  // namespace tomc::techobjects
