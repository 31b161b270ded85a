#include "tb/report.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "golden/errors.hpp"
#include "golden/perspective_dataflow.hpp"

namespace cube4::tb {

uint64_t fnv1a64(const void* data, size_t bytes) {
  const auto* p = static_cast<const unsigned char*>(data);
  uint64_t h = 1469598103934665603ull;
  for (size_t i = 0; i < bytes; ++i) {
    h ^= p[i];
    h *= 1099511628211ull;
  }
  return h;
}

std::string hex64(uint64_t v) {
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(v));
  return buf;
}

nlohmann::json describe_volume(const golden::Volume& v) {
  return {{"source", v.source}, {"dim", v.dim}, {"spacing", v.spacing}, {"voxel_bits", v.bits}};
}

nlohmann::json describe_view(const golden::Scene& s, const golden::HostProgram& h) {
  const golden::ViewFactorisation& f = h.view;
  static const char* axis = "xyz";
  std::string order;
  for (int i = 0; i < 3; ++i) order += std::string(f.flip[i] ? "-" : "+") + axis[f.perm[i]];
  nlohmann::json j = {
      {"base_plane_axis", std::string(f.flip[2] ? "-" : "+") + axis[f.perm[2]]},
      {"permuted_axes", order},
      {"shear", {f.shear_x, f.shear_y}},
      {"base_plane", {h.regs.base_width(), h.regs.base_height()}},
      {"sample_slices", h.regs.sample_slices()},
      {"image", {s.width, s.height}},
      {"zoom", s.view.zoom},
      {"look_at", f.look_at},
      {"xy_supersampling", s.xy_supersampling},
  };
  if (s.view.direction) {
    j["direction"] = *s.view.direction;
    j["up"] = s.view.up;
  } else if (s.view.eye) {
    j["up"] = s.view.up;
  } else {
    j["rotate_deg"] = s.view.rotate;
  }
  j["projection"] = f.perspective ? "perspective" : "parallel";
  if (f.perspective) {
    j["fov_deg"] = s.view.fov;
    j["eye"] = f.eye_object;
    j["eye_distance"] = f.eye_distance;
    // The rays' spacing on the last sample slice: the box filter's width there.
    j["last_slice_ray_spacing"] =
        std::ldexp(static_cast<double>(h.regs.ray_spacing(h.regs.sample_slices() - 1)), -h.regs.p.dda_frac_bits);
    j["dataflow"] = describe_perspective_dataflow(golden::perspective_reach(h.regs));
  }
  return j;
}

// What the rings would need for this frame (docs/perspective.md, "The
// dataflow"): how far each operand lies from a sample's home, in cells.
nlohmann::json describe_perspective_dataflow(const golden::PerspectiveReach& r) {
  auto range = [](const golden::CellRange& c) {
    return c.empty() ? nlohmann::json("none") : nlohmann::json::array({c.lo, c.hi});
  };
  auto axis = [&](const golden::AxisReach& a) {
    return nlohmann::json{{"box", range(a.box)},
                          {"next_ray", range(a.next)},
                          {"behind", range(a.behind)},
                          {"ahead", range(a.ahead)},
                          {"home_move", range(a.drift)}};
  };
  return {{"samples", r.samples},
          {"x", axis(r.x)},
          {"y", axis(r.y)},
          {"compositor_reach_needed", golden::largest_home_move(r)}};
}

nlohmann::json describe_registers(const golden::Registers& r) {
  return {
      {"dim", r.dim},
      {"perm", r.perm},
      {"flip", r.flip},
      {"supersampling", r.supersampling},
      {"dda", {{"frac_bits", r.p.dda_frac_bits}, {"x_start", r.x_start}, {"x_step", r.x_step},
               {"y_start", r.y_start}, {"y_step", r.y_step}}},
      {"perspective", r.perspective ? nlohmann::json{{"scale_start", r.scale_start}, {"scale_step", r.scale_step}}
                                    : nlohmann::json(false)},
      {"classification_entries", r.classification.size()},
      {"gm_lut_entries", r.gm_lut.size()},
      {"diffuse_map_entries", r.diffuse_map.size()},
      {"specular_map_entries", r.specular_map.size()},
      {"coefs", {{"ke", r.coefs.ke}, {"kd", r.coefs.kd}, {"ks", r.coefs.ks}, {"specular", r.coefs.specular}}},
      {"eye", r.eye},
      {"modes", {{"gradient", r.gradient}, {"magnitude", r.magnitude}, {"shading", r.shading},
                 {"specular", r.specular}, {"gm_opacity", r.gm_opacity}, {"gm_diffuse", r.gm_diffuse},
                 {"gm_specular", r.gm_specular}, {"blend", static_cast<int>(r.blend)},
                 {"crop", r.crop_enabled}, {"cut", r.cut_enabled}}},
      {"crop", {{"slab", r.crop.slab}, {"mask", r.crop.mask}}},
      {"cut", {{"a", r.cut.a}, {"b", r.cut.b}, {"c", r.cut.c}, {"dmin", r.cut.dmin}, {"dmax", r.cut.dmax},
               {"falloff", r.cut.falloff}, {"inv_falloff", r.cut.inv_falloff}, {"keep_inside", r.cut.keep_inside}}},
  };
}

void write_text(const std::string& path, const std::string& text, const std::string& shown_as) {
  const std::string& shown = shown_as.empty() ? path : shown_as;
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
  if (fd < 0) throw golden::InputError("cannot write '" + shown + "' (" + std::strerror(errno) + ")");
  size_t done = 0;
  int error = 0;
  while (done < text.size()) {
    const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      error = n < 0 ? errno : ENOSPC;
      break;
    }
    done += static_cast<size_t>(n);
  }
  if (::close(fd) != 0 && error == 0) error = errno;
  if (error != 0) throw golden::InputError("cannot write '" + shown + "' (" + std::strerror(error) + ")");
}

void write_json(const std::string& path, const nlohmann::json& j, const std::string& shown_as) {
  write_text(path, j.dump(2) + "\n", shown_as);
}

}  // namespace cube4::tb
