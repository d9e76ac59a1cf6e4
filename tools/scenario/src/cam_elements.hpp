#pragma once
// Internal: the elements of a TO_Cam in a machine file (docs/scenarios.md "Cams"): "Points" inline or from a
// CSV file, "Segments", "MotionLaws" (VDI 2143, compiled into segments as the cam editor does), and
// "Interpolate" (run MC_InterpolateCam when the machine is built). Problems are named by their JSON paths.

#include <filesystem>
#include <vector>

#include "json_reader.hpp"
#include "tomc/techobjects/cam/cam.hpp"

namespace tomc::scenario::detail {

struct CamElements {
  std::vector<techobjects::TO_Cam_Struct_PointData> points;
  std::vector<techobjects::TO_Cam_Struct_SegmentData> segments;
  bool interpolate = false;
};

// Reads the cam keys of `r` (an entry of technology_objects); a CSV file name is relative to `directory`.
CamElements load_cam_elements(ObjectReader& r, techobjects::CamVariant variant,
                              const std::filesystem::path& directory, Problems& problems);

// Writes the elements into `cam` (Point[1..], Segment[1..]) and interpolates it if asked; a failed
// interpolation is a problem at `path`.
void apply_cam_elements(const CamElements& elements, techobjects::Cam& cam, const std::string& path,
                        Problems& problems);

}  // namespace tomc::scenario::detail
