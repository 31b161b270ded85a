// A frame with every unit at transaction level: one transaction through
// the golden renderer's slice steps (golden/slice_steps.hpp: the same
// interpolation, neighbourhood, shading and slice compositor the per-unit
// TLM models of systemc/tlm/ call), loosely timed: the cycles are the cycle
// model's (systemc/core/cycle_model.cpp), which the system tests check
// against the RTL run. No clock is simulated, so a frame costs what the
// golden renderer costs (docs/performance.md). With polygons the golden
// slice compositor draws them too (front image, Z test, slabs, back image).
#pragma once
#include "golden/renderers.hpp"
#include "golden/volume.hpp"
#include "systemc/core/frame_plan.hpp"

namespace cube4::sysc {

inline golden::BasePlane run_tlm_frame(const FramePlan& plan, const golden::Volume& vol,
                                       const golden::Progress& progress, bool accumulators = false,
                                       const golden::PolygonFrame* polygons = nullptr) {
  golden::FixedOptions opt;
  opt.progress = progress;
  opt.accumulators = accumulators;
  opt.polygons = polygons;
  return golden::render_fixed(vol, plan.r, opt);
}

}  // namespace cube4::sysc
