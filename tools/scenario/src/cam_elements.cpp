// The elements of a TO_Cam in a machine file (cam_elements.hpp; docs/scenarios.md "Cams").
#include "cam_elements.hpp"

#include <array>
#include <fstream>
#include <sstream>
#include <string>

#include "tomc/techobjects/axis/error_ids.hpp"
#include "tomc/techobjects/cam/vdi2143.hpp"

namespace tomc::scenario::detail {

namespace to = tomc::techobjects;

namespace {

// "x,y" per line; blank lines, lines starting with '#' and one line before the first point that is not
// numeric (a header) are skipped.
void read_points_csv(const std::filesystem::path& file, const std::string& path,
                     std::vector<to::TO_Cam_Struct_PointData>& out, Problems& problems) {
  std::ifstream in(file);
  if (!in) {
    problems.add(path, "cannot read '" + file.string() + "'");
    return;
  }
  std::string line;
  std::size_t number = 0;
  bool header_seen = false;  // one header line before the first point
  while (std::getline(in, line)) {
    ++number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty() || line[0] == '#') continue;
    std::istringstream fields(line);
    double x = 0.0;
    double y = 0.0;
    char comma = 0;
    if (fields >> x >> comma >> y && comma == ',') {
      out.push_back({x, y});
      continue;
    }
    if (header_seen || !out.empty()) {
      problems.add(path, file.filename().string() + " line " + std::to_string(number) +
                             ": expected 'x,y' (two numbers separated by a comma)");
    }
    header_seen = true;
  }
}

void read_points(const Json& v, const std::string& path, const std::filesystem::path& directory,
                 std::vector<to::TO_Cam_Struct_PointData>& out, Problems& problems) {
  if (v.is_object()) {
    ObjectReader f(v, path, problems);
    if (const Json* name = f.get("file", true)) {
      if (auto s = read_string(*name, f.path_of("file"), problems)) {
        const std::filesystem::path file(*s);
        read_points_csv(file.is_absolute() ? file : directory / file, f.path_of("file"), out, problems);
      }
    }
    f.finish();
    return;
  }
  if (!v.is_array()) {
    problems.add(path, "expected an array of [x, y] pairs or {\"file\": \"<points>.csv\"}");
    return;
  }
  for (std::size_t i = 0; i < v.size(); ++i) {
    const std::string at = path + "[" + std::to_string(i) + "]";
    const Json& p = v[i];
    if (!p.is_array() || p.size() != 2) {
      problems.add(at, "expected [x, y]");
      continue;
    }
    const auto x = read_number(p[0], at + "[0]", problems);
    const auto y = read_number(p[1], at + "[1]", problems);
    if (x && y) out.push_back({*x, *y});
  }
}

void read_segments(const Json& v, const std::string& path, std::vector<to::TO_Cam_Struct_SegmentData>& out,
                   Problems& problems) {
  if (!v.is_array()) {
    problems.add(path, "expected an array of segments {\"xmin\": ..., \"xmax\": ..., \"a0\": ...}");
    return;
  }
  for (std::size_t i = 0; i < v.size(); ++i) {
    ObjectReader s(v[i], path + "[" + std::to_string(i) + "]", problems);
    if (!s.valid()) continue;
    to::TO_Cam_Struct_SegmentData d;
    const std::array<std::pair<const char*, double*>, 12> fields{{{"xmin", &d.xmin},
                                                                  {"xmax", &d.xmax},
                                                                  {"a0", &d.a0},
                                                                  {"a1", &d.a1},
                                                                  {"a2", &d.a2},
                                                                  {"a3", &d.a3},
                                                                  {"a4", &d.a4},
                                                                  {"a5", &d.a5},
                                                                  {"a6", &d.a6},
                                                                  {"sineAmplitude", &d.sineAmplitude},
                                                                  {"sinePeriod", &d.sinePeriod},
                                                                  {"sinePhase", &d.sinePhase}}};
    for (const auto& [key, target] : fields) {
      const bool required = std::string_view(key) == "xmin" || std::string_view(key) == "xmax";
      if (const Json* n = s.get(key, required)) {
        if (auto value = read_number(*n, s.path_of(key), problems)) *target = *value;
      }
    }
    s.finish();
    out.push_back(d);
  }
}

void read_motion_laws(const Json& v, const std::string& path, std::vector<to::TO_Cam_Struct_SegmentData>& out,
                      Problems& problems) {
  if (!v.is_array()) {
    problems.add(path,
                 "expected an array of {\"law\": ..., \"x0\": ..., \"y0\": ..., \"x1\": ..., \"y1\": ...}");
    return;
  }
  const std::vector<std::string_view> names{"Line",         "QuadraticParabola", "SimpleSine",
                                            "InclinedSine", "Polynomial5",       "ModifiedSine"};
  for (std::size_t i = 0; i < v.size(); ++i) {
    ObjectReader m(v[i], path + "[" + std::to_string(i) + "]", problems);
    if (!m.valid()) continue;
    std::optional<std::size_t> law;
    if (const Json* l = m.get("law", true)) law = read_choice(*l, m.path_of("law"), names, problems);
    std::array<std::optional<double>, 4> p{};
    const std::array<const char*, 4> keys{"x0", "y0", "x1", "y1"};
    for (std::size_t k = 0; k < 4; ++k) {
      if (const Json* n = m.get(keys[k], true)) p[k] = read_number(*n, m.path_of(keys[k]), problems);
    }
    m.finish();
    if (!law || !p[0] || !p[1] || !p[2] || !p[3]) continue;
    std::array<to::TO_Cam_Struct_SegmentData, to::kMaxLawSegments> segments{};
    const std::size_t n =
        to::motion_law_segments(static_cast<to::MotionLaw>(*law), *p[0], *p[1], *p[2], *p[3], segments);
    if (n == 0) {
      problems.add(m.path_of("x1"), "must be greater than x0");
      continue;
    }
    out.insert(out.end(), segments.begin(), segments.begin() + static_cast<std::ptrdiff_t>(n));
  }
}

}  // namespace

CamElements load_cam_elements(ObjectReader& r, to::CamVariant variant, const std::filesystem::path& directory,
                              Problems& problems) {
  CamElements e;
  const to::CamCapacity capacity = to::capacity_of(variant);
  if (const Json* v = r.get("Points")) {
    read_points(*v, r.path_of("Points"), directory, e.points, problems);
    if (e.points.size() > capacity.points) {
      problems.add(r.path_of("Points"), std::to_string(e.points.size()) + " points, a " +
                                            std::string(to::type_name(variant)) + " holds " +
                                            std::to_string(capacity.points));
    }
  }
  if (const Json* v = r.get("Segments")) read_segments(*v, r.path_of("Segments"), e.segments, problems);
  if (const Json* v = r.get("MotionLaws"))
    read_motion_laws(*v, r.path_of("MotionLaws"), e.segments, problems);
  if (e.segments.size() > capacity.segments) {
    problems.add(r.path_of(r.has("MotionLaws") ? "MotionLaws" : "Segments"),
                 std::to_string(e.segments.size()) + " segments (motion laws included), a " +
                     std::string(to::type_name(variant)) + " holds " + std::to_string(capacity.segments));
  }
  if (const Json* v = r.get("Interpolate")) {
    if (auto b = read_bool(*v, r.path_of("Interpolate"), problems)) e.interpolate = *b;
  }
  return e;
}

void apply_cam_elements(const CamElements& elements, to::Cam& cam, const std::string& path,
                        Problems& problems) {
  for (std::size_t i = 0; i < elements.points.size(); ++i)
    (void)cam.write_point(i + 1, elements.points[i], true);
  for (std::size_t i = 0; i < elements.segments.size(); ++i)
    (void)cam.write_segment(i + 1, elements.segments[i], true);
  if (!elements.interpolate) return;
  const to::Submission s = cam.interpolate_cam();
  if (!s.accepted()) {
    const auto& r = cam.last_interpolation();
    char id[8];
    std::snprintf(id, sizeof id, "%04X", s.error_id);
    problems.add(path + ".Interpolate",
                 "MC_InterpolateCam fails with 16#" + std::string(id) + ": " +
                     std::string(to::error_id::describe(s.error_id)) +
                     (r.element != 0 ? " (element " + std::to_string(r.element) + ")" : ""));
  }
}

}  // namespace tomc::scenario::detail
