#pragma once
// MC_CopyCamData (spec 07 §3.6): copies points and segments from arrays of the user program into the cam's
// Point/Segment arrays and marks them valid; Mode 0 invalidates every element of the cam first. Allowed while
// the cam is in use: the copy takes effect with the next MC_InterpolateCam. Completes within the call.
#include <cstdint>
#include <span>

#include "tomc/instructions/execute_handshake.hpp"
#include "tomc/techobjects/cam/cam.hpp"

namespace tomc::instructions {

struct MC_CopyCamData {
  bool Execute = false;
  std::int32_t Mode = 0;
  std::int32_t StartPointCam = 1;
  std::int32_t StartSegmentCam = 1;
  std::int32_t StartPointArray = 0;  // index into ArrayOfPoints from 0 (techobjects::CopyCamDataInputs)
  std::int32_t StartSegmentArray = 0;
  std::int32_t NumberOfPoints = 0;
  std::int32_t NumberOfSegments = 0;
  std::span<const techobjects::TO_Cam_Struct_PointData> ArrayOfPoints;  // IN_OUT in the manual
  std::span<const techobjects::TO_Cam_Struct_SegmentData> ArrayOfSegments;
  bool Done = false;
  bool Busy = false;
  bool CommandAborted = false;  // never set
  bool Error = false;
  std::uint16_t ErrorID = 0;

  void operator()(techobjects::Cam& cam) noexcept {
    handshake_.call(
        Execute,
        [&] {
          return cam.copy_cam_data(techobjects::CopyCamDataInputs{
              Mode, StartPointCam, StartSegmentCam, StartPointArray, StartSegmentArray, NumberOfPoints,
              NumberOfSegments, ArrayOfPoints, ArrayOfSegments});
        },
        [&](techobjects::JobId id) { return cam.job_status(id); });
    show_outputs(*this, handshake_.outputs());
  }

 private:
  ExecuteHandshake handshake_;
};

}  // namespace tomc::instructions
