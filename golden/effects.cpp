// Which parts of the pipeline a scene needs: units and logic outside this set
// are not simulated at all, and must not change the image.
#include <string>
#include <utility>
#include <vector>

#include "golden/scene.hpp"

namespace cube4::golden {
namespace {

const char* blend_name(Blend b) {
  switch (b) {
    case Blend::Composite: return "composite";
    case Blend::Mip: return "mip";
    case Blend::MinIp: return "minip";
  }
  return "composite";
}

}  // namespace

EffectSet effects_of(const Scene& s) {
  EffectSet e;
  e.blend = s.blend;
  // No light means no reflectance maps to build; such a scene renders as
  // unshaded (parse_scene never produces one: it fills in the default light).
  e.shading = s.shading && !s.lights.empty();
  e.specular = false;
  for (int t = 0; t < s.tag_count(); ++t) e.specular = e.specular || (e.shading && s.material_of(t).ks > 0);
  // Diffuse/specular modulation scale the shading terms, so they need |g|
  // only when those terms exist; opacity modulation needs it always.
  e.magnitude = s.gm.opacity || (e.shading && (s.gm.diffuse || s.gm.specular));
  e.gradient = e.shading || e.magnitude;
  e.cropping = s.cropping.enabled;
  e.cut_plane = s.cut.enabled;
  e.supersampling = s.supersampling > 1;
  e.polygons = !s.polygons.empty();
  e.tags = s.precision.tag_bits > 0;
  return e;
}

std::vector<std::string> EffectSet::names() const {
  std::vector<std::string> out{blend_name(blend)};
  const std::pair<bool, const char*> flags[] = {
      {gradient, "gradient"},   {magnitude, "magnitude"}, {shading, "shading"},
      {specular, "specular"},   {cropping, "cropping"},   {cut_plane, "cut_plane"},
      {supersampling, "supersampling"}, {polygons, "polygons"},
      {tags, "tags"},
  };
  for (const auto& [on, name] : flags)
    if (on) out.push_back(name);
  return out;
}

}  // namespace cube4::golden
