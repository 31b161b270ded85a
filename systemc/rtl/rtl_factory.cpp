// One case per verilated p (the generated lists come from
// systemc/CMakeLists.txt: rtl_variant_headers.inc, rtl_variant_list.inc).
#include "systemc/rtl/rtl_factory.hpp"

#include <cstring>
#include <stdexcept>
#include <string>

#include "systemc/rtl/rtl_model.hpp"  // before the models: see its sc_time_stamp note

#include "Vsys_compose_node.h"
#include "Vsys_compose_node___024root.h"
#include "Vsys_compose_out.h"
#include "Vsys_compose_out___024root.h"
#include "Vsys_dda.h"
#include "Vsys_dda___024root.h"
#include "Vsys_dda_persp.h"
#include "Vsys_dda_persp___024root.h"
#include "Vsys_shade_lean.h"
#include "Vsys_shade_lean___024root.h"
#include "Vsys_shade_tags.h"
#include "Vsys_shade_tags___024root.h"
#include "Vsys_shade_unit.h"
#include "Vsys_shade_unit___024root.h"
#include "Vsys_shade_unit_cube4_pkg.h"
#include "rtl_variant_headers.inc"
#include "systemc/rtl/rtl_addr.hpp"
#include "systemc/rtl/rtl_compose.hpp"
#include "systemc/rtl/rtl_composite.hpp"
#include "systemc/rtl/rtl_composite_persp.hpp"
#include "systemc/rtl/rtl_dda.hpp"
#include "systemc/rtl/rtl_gradient.hpp"
#include "systemc/rtl/rtl_gradient_persp.hpp"
#include "systemc/rtl/rtl_interp.hpp"
#include "systemc/rtl/rtl_interp_persp.hpp"
#include "systemc/rtl/rtl_shade.hpp"

namespace cube4::sysc {

// The hardware constants the wrappers state in C++ are the RTL package's
// (rtl/cube4_pkg.sv; every verilated model exports it, the shading unit's
// copy is read here). The golden widths are checked by test_rtl_pkg.
using Pkg = Vsys_shade_unit_cube4_pkg;
static_assert(Pkg::DimBits == kRtlAddrDimBits, "the address generator's dimension width");
static_assert(Pkg::SupersamplingBits == rtl::kSupersamplingBits, "the gradient ring's supersampling field");
static_assert(Pkg::PosBits == golden::kPositionBits, "the compositor's position width");
static_assert(Pkg::CutCoefBits == golden::kCutCoefBits, "the cut-plane coefficient width");

#ifdef CUBE4_RTL_VOXEL_TAG_BITS
static_assert(kRtlVoxelTagBits == CUBE4_RTL_VOXEL_TAG_BITS, "the verilated VoxelTagBits differ (systemc/CMakeLists.txt)");
#endif
static_assert(Pkg::VoxelBits + kRtlVoxelTagBits <= 16, "a voxel word {tag, value} is at most 16 bits");

#ifdef CUBE4_SHADE_SIDE_BITS
static_assert(kShadeSideBits == CUBE4_SHADE_SIDE_BITS, "the verilated shading unit's SideBits differ (systemc/CMakeLists.txt)");
#endif

namespace {

// Refuses a p the build has no `what` for, naming the p it was built for,
// the CMake list that adds one, and what else the user can do.
void require_variant(int p, const std::vector<int>& built, const std::string& what, const std::string& cmake_list,
                     const std::string& otherwise) {
  std::string list;
  for (int q : built) {
    if (q == p) return;
    list += (list.empty() ? "" : ", ") + std::to_string(q);
  }
  throw std::invalid_argument("pipelines: " + std::to_string(p) + " has no " + what + " (built for p = " +
                              (list.empty() ? std::string("none") : list) + "; add it to CMake's " + cmake_list +
                              ", or " + otherwise + ")");
}

// VolumePro's z gradient at RTL: the `rings` verilated with it for p (no
// ring has it with voxel tags).
void require_zdiff_variant(int p, int tag_bits, const std::vector<int>& built, const std::string& rings,
                           const std::string& cmake_list) {
  const std::string otherwise = "run those units at TLM: --model tlm, or mixed: naming neither interp nor gradient";
  if (tag_bits > 0)
    throw std::invalid_argument("z_gradient voxel_differences with voxel tags: no " + rings + " have both; " +
                                otherwise);
  require_variant(p, built, rings + " for z_gradient voxel_differences", cmake_list, otherwise);
}

// A switch over the built p found none: refused as require_rtl() refuses.
[[noreturn]] void unavailable(int p) {
  require_rtl(p);
  throw std::logic_error("rtl_factory: p = " + std::to_string(p) + " is built but has no case");
}

}  // namespace

golden::Precision rtl_precision() {
  struct Width {
    const char* name;
    int value;
  };
  static constexpr Width kWidths[] = {
#define CUBE4_RTL_WIDTH(name, value) {#name, value},
#include "rtl_widths.inc"
#undef CUBE4_RTL_WIDTH
      {nullptr, 0}};
  golden::Precision p;
  for (const Width& w : kWidths) {
    if (!w.name) break;
    const golden::PrecisionField* field = nullptr;
    for (const golden::PrecisionField& f : golden::kPrecisionFields)
      if (f.rtl_parameter && std::strcmp(f.rtl_parameter, w.name) == 0) field = &f;
    // cmake/system_widths.cmake takes only the table's names.
    if (!field) throw std::logic_error(std::string("CUBE4_SYSTEM_WIDTHS: no precision field ") + w.name);
    p.*field->member = w.value;
  }
  return p;
}

std::vector<int> rtl_pipes() {
  return {
#define CUBE4_RTL_P(p) p,
#include "rtl_variant_list.inc"
#undef CUBE4_RTL_P
  };
}

bool rtl_available(int p) {
  for (int q : rtl_pipes())
    if (q == p) return true;
  return false;
}

void require_rtl(int p) { require_variant(p, rtl_pipes(), "RTL build", "CUBE4_SYSTEM_PIPES", "run --model tlm"); }

std::vector<int> rtl_tag_pipes() {
  return {
#define CUBE4_RTL_TAG_P(p) p,
#include "rtl_tag_variant_list.inc"
#undef CUBE4_RTL_TAG_P
  };
}

void require_rtl_tags(int p, int tag_bits) {
  if (tag_bits == 0) return;
  if (tag_bits > kRtlVoxelTagBits)
    throw std::invalid_argument("precision: tag_bits = " + std::to_string(tag_bits) + ", but the RTL has " +
                                std::to_string(kRtlVoxelTagBits) + "-bit voxel tags; run with --model tlm");
  require_variant(p, rtl_tag_pipes(), "RTL with voxel tags", "CUBE4_SYSTEM_TAG_PIPES", "run --model tlm");
}

std::vector<int> rtl_polygon_pipes() {
  return {
#define CUBE4_RTL_POLY_P(p) p,
#include "rtl_poly_variant_list.inc"
#undef CUBE4_RTL_POLY_P
  };
}

void require_rtl_polygons(int p) {
  require_variant(p, rtl_polygon_pipes(), "RTL compositing unit with polygon hardware", "CUBE4_SYSTEM_POLYGON_PIPES",
                  "run the compositing unit at TLM");
}

std::vector<int> rtl_zdiff_pipes() {
  return {
#define CUBE4_RTL_ZDIFF_P(p) p,
#include "rtl_zdiff_variant_list.inc"
#undef CUBE4_RTL_ZDIFF_P
  };
}

void require_rtl_zdiff(int p, int tag_bits) {
  require_zdiff_variant(p, tag_bits, rtl_zdiff_pipes(), "RTL interpolation and gradient rings",
                        "CUBE4_SYSTEM_ZDIFF_PIPES");
}

std::vector<int> rtl_persp_pipes() {
  return {
#define CUBE4_RTL_PERSP_P(p) p,
#include "rtl_persp_variant_list.inc"
#undef CUBE4_RTL_PERSP_P
  };
}

void require_rtl_perspective(int p) {
  require_variant(p, rtl_persp_pipes(), "RTL perspective rings",
                  "CUBE4_SYSTEM_PERSP_PIPES", "run the perspective units at TLM");
}

std::vector<int> rtl_persp_polygon_pipes() {
  return {
#define CUBE4_RTL_PERSP_POLY_P(p) p,
#include "rtl_persp_poly_variant_list.inc"
#undef CUBE4_RTL_PERSP_POLY_P
  };
}

void require_rtl_persp_polygons(int p) {
  require_variant(p, rtl_persp_polygon_pipes(), "RTL perspective compositing ring with polygon hardware",
                  "CUBE4_SYSTEM_PERSP_PIPES and CUBE4_SYSTEM_POLYGON_PIPES",
                  "run the compositing unit at TLM (--model mixed: without composite)");
}

std::vector<int> rtl_persp_zdiff_pipes() {
  return {
#define CUBE4_RTL_PERSP_ZDIFF_P(p) p,
#include "rtl_persp_zdiff_variant_list.inc"
#undef CUBE4_RTL_PERSP_ZDIFF_P
  };
}

void require_rtl_persp_zdiff(int p, int tag_bits) {
  require_zdiff_variant(p, tag_bits, rtl_persp_zdiff_pipes(), "RTL perspective interpolation and gradient rings",
                        "CUBE4_SYSTEM_PERSP_PIPES and CUBE4_SYSTEM_ZDIFF_PIPES");
}

std::unique_ptr<PerspInterpIf> make_rtl_interp_persp(const FramePlan& plan, VerilatedContext& ctx,
                                                     const TraceWindow& trace) {
  require_rtl_perspective(plan.p);
  if (plan.zdiff) {
    require_rtl_persp_zdiff(plan.p, plan.r.p.tag_bits);
    switch (plan.p) {
#define CUBE4_RTL_PERSP_ZDIFF_P(p) \
  case p: return std::make_unique<RtlInterpPersp<Vsys_interp_persp_zdiff_p##p>>(plan, ctx, trace);
#include "rtl_persp_zdiff_variant_list.inc"
#undef CUBE4_RTL_PERSP_ZDIFF_P
    }
  } else if (plan.r.p.tag_bits > 0) {
    // The tag variants are those of the p with the parallel rings' ones too.
    require_rtl_tags(plan.p, plan.r.p.tag_bits);
    switch (plan.p) {
#define CUBE4_RTL_PERSP_TAG_P(p) \
  case p: return std::make_unique<RtlInterpPersp<Vsys_interp_persp_tags_p##p>>(plan, ctx, trace);
#include "rtl_persp_tag_variant_list.inc"
#undef CUBE4_RTL_PERSP_TAG_P
    }
  } else {
    switch (plan.p) {
#define CUBE4_RTL_PERSP_P(p) \
  case p: return std::make_unique<RtlInterpPersp<Vsys_interp_persp_p##p>>(plan, ctx, trace);
#include "rtl_persp_variant_list.inc"
#undef CUBE4_RTL_PERSP_P
    }
  }
  throw std::logic_error("make_rtl_interp_persp: p = " + std::to_string(plan.p));
}

std::unique_ptr<PerspGradientIf> make_rtl_gradient_persp(const FramePlan& plan, VerilatedContext& ctx,
                                                         const TraceWindow& trace) {
  require_rtl_perspective(plan.p);
  if (plan.zdiff) {
    require_rtl_persp_zdiff(plan.p, plan.r.p.tag_bits);
    switch (plan.p) {
#define CUBE4_RTL_PERSP_ZDIFF_P(p) \
  case p: return std::make_unique<RtlGradientPersp<Vsys_gradient_persp_zdiff_p##p>>(plan, ctx, trace);
#include "rtl_persp_zdiff_variant_list.inc"
#undef CUBE4_RTL_PERSP_ZDIFF_P
    }
  } else if (plan.r.p.tag_bits > 0) {
    require_rtl_tags(plan.p, plan.r.p.tag_bits);
    switch (plan.p) {
#define CUBE4_RTL_PERSP_TAG_P(p) \
  case p: return std::make_unique<RtlGradientPersp<Vsys_gradient_persp_tags_p##p>>(plan, ctx, trace);
#include "rtl_persp_tag_variant_list.inc"
#undef CUBE4_RTL_PERSP_TAG_P
    }
  } else {
    switch (plan.p) {
#define CUBE4_RTL_PERSP_P(p) \
  case p: return std::make_unique<RtlGradientPersp<Vsys_gradient_persp_p##p>>(plan, ctx, trace);
#include "rtl_persp_variant_list.inc"
#undef CUBE4_RTL_PERSP_P
    }
  }
  throw std::logic_error("make_rtl_gradient_persp: p = " + std::to_string(plan.p));
}

std::unique_ptr<PerspCompositor> make_rtl_composite_persp(const FramePlan& plan, bool accumulators,
                                                          VerilatedContext& ctx, const TraceWindow& trace,
                                                          const golden::PolygonFrame* polygons) {
  require_rtl_perspective(plan.p);
  if (polygons) {
    require_rtl_persp_polygons(plan.p);
    switch (plan.p) {
#define CUBE4_RTL_PERSP_POLY_P(p)                                                                                \
  case p:                                                                                                        \
    return std::make_unique<RtlCompositePersp<Vsys_composite_persp_poly_p##p>>(                                 \
        plan, accumulators, ctx, trace, polygons,                                                                \
        std::make_unique<RtlPerspSlabDecode<Vsys_persp_slab_decode_p##p>>(plan, *polygons, ctx, trace));
#include "rtl_persp_poly_variant_list.inc"
#undef CUBE4_RTL_PERSP_POLY_P
    }
  }
  switch (plan.p) {
#define CUBE4_RTL_PERSP_P(p) \
  case p: return std::make_unique<RtlCompositePersp<Vsys_composite_persp_p##p>>(plan, accumulators, ctx, trace);
#include "rtl_persp_variant_list.inc"
#undef CUBE4_RTL_PERSP_P
  }
  throw std::logic_error("make_rtl_composite_persp: p = " + std::to_string(plan.p));
}

std::vector<golden::SliceControl> rtl_slice_controls(const golden::Registers& r, VerilatedContext& ctx) {
  return run_rtl_dda<Vsys_dda>(r, ctx);
}

std::vector<golden::PerspectiveSlice> rtl_perspective_slices(const golden::Registers& r, VerilatedContext& ctx) {
  return run_rtl_dda_perspective<Vsys_dda_persp>(r, ctx);
}

std::unique_ptr<AddrIf> make_rtl_addr(const FramePlan& plan, const golden::SkewLayout& layout, VerilatedContext& ctx,
                                      const TraceWindow& trace) {
  switch (plan.p) {
#define CUBE4_RTL_P(p) \
  case p: return std::make_unique<RtlAddr<Vsys_addr_p##p>>(plan, layout, ctx, trace);
#include "rtl_variant_list.inc"
#undef CUBE4_RTL_P
    default: unavailable(plan.p);
  }
}

std::unique_ptr<InterpIf> make_rtl_interp(const FramePlan& plan, VerilatedContext& ctx, const TraceWindow& trace) {
  if (plan.zdiff) {
    require_rtl_zdiff(plan.p, plan.r.p.tag_bits);
    switch (plan.p) {
#define CUBE4_RTL_ZDIFF_P(p) \
  case p: return std::make_unique<RtlInterp<Vsys_interp_zdiff_p##p>>(plan, ctx, trace);
#include "rtl_zdiff_variant_list.inc"
#undef CUBE4_RTL_ZDIFF_P
    }
  }
  if (plan.r.p.tag_bits > 0) {
    require_rtl_tags(plan.p, plan.r.p.tag_bits);
    switch (plan.p) {
#define CUBE4_RTL_TAG_P(p) \
  case p: return std::make_unique<RtlInterp<Vsys_interp_tags_p##p>>(plan, ctx, trace);
#include "rtl_tag_variant_list.inc"
#undef CUBE4_RTL_TAG_P
    }
  }
  switch (plan.p) {
#define CUBE4_RTL_P(p) \
  case p: return std::make_unique<RtlInterp<Vsys_interp_p##p>>(plan, ctx, trace);
#include "rtl_variant_list.inc"
#undef CUBE4_RTL_P
    default: unavailable(plan.p);
  }
}

std::unique_ptr<GradientIf> make_rtl_gradient(const FramePlan& plan, VerilatedContext& ctx, const TraceWindow& trace) {
  if (plan.zdiff) {
    require_rtl_zdiff(plan.p, plan.r.p.tag_bits);
    switch (plan.p) {
#define CUBE4_RTL_ZDIFF_P(p) \
  case p: return std::make_unique<RtlGradient<Vsys_gradient_zdiff_p##p>>(plan, kRtlMaxDim, ctx, trace);
#include "rtl_zdiff_variant_list.inc"
#undef CUBE4_RTL_ZDIFF_P
    }
  }
  if (plan.r.p.tag_bits > 0) {
    require_rtl_tags(plan.p, plan.r.p.tag_bits);
    switch (plan.p) {
#define CUBE4_RTL_TAG_P(p) \
  case p: return std::make_unique<RtlGradient<Vsys_gradient_tags_p##p>>(plan, kRtlMaxDim, ctx, trace);
#include "rtl_tag_variant_list.inc"
#undef CUBE4_RTL_TAG_P
    }
  }
  switch (plan.p) {
#define CUBE4_RTL_P(p) \
  case p: return std::make_unique<RtlGradient<Vsys_gradient_p##p>>(plan, kRtlMaxDim, ctx, trace);
#include "rtl_variant_list.inc"
#undef CUBE4_RTL_P
    default: unavailable(plan.p);
  }
}

std::unique_ptr<ShadeIf> make_rtl_shade(const FramePlan& plan, VerilatedContext& ctx, const TraceWindow& trace,
                                        bool full, int first, int last) {
  if (!rtl_available(plan.p)) unavailable(plan.p);
  // Tags need the classifier's wider address and the material RAM (one
  // unit model serves every p).
  if (plan.r.p.tag_bits > 0) return std::make_unique<RtlShade<Vsys_shade_tags>>(plan, ctx, trace, first, last);
  if (!full && !plan.r.shading && !plan.r.magnitude)
    return std::make_unique<RtlShade<Vsys_shade_lean>>(plan, ctx, trace, first, last);
  return std::make_unique<RtlShade<Vsys_shade_unit>>(plan, ctx, trace, first, last);
}

std::unique_ptr<PerspShadeIf> make_rtl_shade_persp(const FramePlan& plan, VerilatedContext& ctx,
                                                   const TraceWindow& trace, bool full) {
  if (!rtl_available(plan.p)) unavailable(plan.p);
  if (plan.r.p.tag_bits > 0) return std::make_unique<RtlShadePersp<Vsys_shade_tags>>(plan, ctx, trace);
  if (!full && !plan.r.shading && !plan.r.magnitude)
    return std::make_unique<RtlShadePersp<Vsys_shade_lean>>(plan, ctx, trace);
  return std::make_unique<RtlShadePersp<Vsys_shade_unit>>(plan, ctx, trace);
}

std::unique_ptr<CompositeIf> make_rtl_composite(const FramePlan& plan, PixelMemory& pixels, VerilatedContext& ctx,
                                                const TraceWindow& trace, bool full,
                                                const golden::PolygonFrame* polygons, int frames) {
  if (polygons) {
    require_rtl_polygons(plan.p);
    switch (plan.p) {
#define CUBE4_RTL_POLY_P(p) \
  case p: return std::make_unique<RtlComposite<Vsys_composite_poly_p##p>>(plan, pixels, ctx, trace, polygons, frames);
#include "rtl_poly_variant_list.inc"
#undef CUBE4_RTL_POLY_P
    }
  }
  switch (plan.p) {
#define CUBE4_RTL_P(p)                                                                              \
  case p:                                                                                           \
    if (full || plan.r.cut_enabled) return std::make_unique<RtlComposite<Vsys_composite_p##p>>(plan, pixels, ctx, trace); \
    return std::make_unique<RtlComposite<Vsys_composite_nocut_p##p>>(plan, pixels, ctx, trace);
#include "rtl_variant_list.inc"
#undef CUBE4_RTL_P
    default: unavailable(plan.p);
  }
}

std::unique_ptr<ComposeNodeIf> make_rtl_compose_node(golden::BlendMode mode, const golden::Precision& p,
                                                     VerilatedContext& ctx, const TraceWindow& trace, size_t index) {
  require_rtl_widths(p, "the composition network's RTL");
  return std::make_unique<RtlComposeNode<Vsys_compose_node>>(mode, p, ctx, trace, "node" + std::to_string(index));
}

std::unique_ptr<ComposeOutIf> make_rtl_compose_out(const golden::Precision& p, VerilatedContext& ctx) {
  require_rtl_widths(p, "the composition network's RTL");
  return std::make_unique<RtlComposeOut<Vsys_compose_out>>(ctx);
}

}  // namespace cube4::sysc
