// The build without verilated RTL (CUBE4_RTL=OFF): no p has an RTL level.
#include <stdexcept>

#include "systemc/rtl/rtl_factory.hpp"
#include "systemc/core/compose_network.hpp"

namespace cube4::sysc {

golden::Precision rtl_precision() { return {}; }
std::vector<int> rtl_pipes() { return {}; }
bool rtl_available(int) { return false; }

namespace {
[[noreturn]] void unavailable() {
  throw std::invalid_argument("this build has no RTL (configured with CUBE4_RTL=OFF): run --model tlm");
}
}  // namespace

void require_rtl(int) { unavailable(); }
std::vector<int> rtl_tag_pipes() { return {}; }
void require_rtl_tags(int, int) { unavailable(); }
std::vector<int> rtl_polygon_pipes() { return {}; }
std::vector<int> rtl_zdiff_pipes() { return {}; }
void require_rtl_zdiff(int, int) { unavailable(); }
void require_rtl_polygons(int) { unavailable(); }
std::vector<int> rtl_persp_pipes() { return {}; }
void require_rtl_perspective(int) { unavailable(); }
std::vector<int> rtl_persp_polygon_pipes() { return {}; }
void require_rtl_persp_polygons(int) { unavailable(); }
std::vector<int> rtl_persp_zdiff_pipes() { return {}; }
void require_rtl_persp_zdiff(int, int) { unavailable(); }
std::unique_ptr<PerspInterpIf> make_rtl_interp_persp(const FramePlan&, VerilatedContext&, const TraceWindow&) {
  unavailable();
}
std::unique_ptr<PerspGradientIf> make_rtl_gradient_persp(const FramePlan&, VerilatedContext&, const TraceWindow&) {
  unavailable();
}
std::unique_ptr<PerspCompositor> make_rtl_composite_persp(const FramePlan&, bool, VerilatedContext&,
                                                          const TraceWindow&, const golden::PolygonFrame*) {
  unavailable();
}
std::vector<golden::SliceControl> rtl_slice_controls(const golden::Registers&, VerilatedContext&) { unavailable(); }
std::vector<golden::PerspectiveSlice> rtl_perspective_slices(const golden::Registers&, VerilatedContext&) {
  unavailable();
}
std::unique_ptr<AddrIf> make_rtl_addr(const FramePlan&, const golden::SkewLayout&, VerilatedContext&, const TraceWindow&) {
  unavailable();
}
std::unique_ptr<InterpIf> make_rtl_interp(const FramePlan&, VerilatedContext&, const TraceWindow&) { unavailable(); }
std::unique_ptr<GradientIf> make_rtl_gradient(const FramePlan&, VerilatedContext&, const TraceWindow&) { unavailable(); }
std::unique_ptr<ShadeIf> make_rtl_shade(const FramePlan&, VerilatedContext&, const TraceWindow&, bool, int, int) {
  unavailable();
}
std::unique_ptr<PerspShadeIf> make_rtl_shade_persp(const FramePlan&, VerilatedContext&, const TraceWindow&, bool) {
  unavailable();
}
std::unique_ptr<CompositeIf> make_rtl_composite(const FramePlan&, PixelMemory&, VerilatedContext&, const TraceWindow&,
                                                bool, const golden::PolygonFrame*, int) {
  unavailable();
}

std::unique_ptr<ComposeNodeIf> make_rtl_compose_node(golden::BlendMode, const golden::Precision&, VerilatedContext&,
                                                     const TraceWindow&, size_t) {
  unavailable();
}
std::unique_ptr<ComposeOutIf> make_rtl_compose_out(const golden::Precision&, VerilatedContext&) { unavailable(); }

}  // namespace cube4::sysc
