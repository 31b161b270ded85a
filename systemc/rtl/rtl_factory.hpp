// The RTL level of each unit, for the pipeline counts the build verilated
// (CMake CUBE4_SYSTEM_PIPES). Without a verilated build (CUBE4_RTL=OFF)
// no p is available and the system runs at transaction level only.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "golden/polygon_frame.hpp"
#include "systemc/core/frame_plan.hpp"
#include "systemc/core/pixel_memory.hpp"
#include "systemc/core/unit_if.hpp"

#include "golden/units/compose.hpp"

class VerilatedContext;

namespace cube4::sysc {

struct TraceWindow;

// Largest permuted nx, ny the verilated rings' storage holds: their MaxDim,
// CMake's CUBE4_SYSTEM_MAX_DIM (systemc/CMakeLists.txt verilates the rings
// with it and defines this).
#ifdef CUBE4_RTL_MAX_DIM
constexpr int kRtlMaxDim = CUBE4_RTL_MAX_DIM;
#else
constexpr int kRtlMaxDim = 256;
#endif
// cube4_addr's DimBits: its dimension registers (rtl/cube4_pkg.sv; checked
// in rtl_factory.cpp).
constexpr int kRtlAddrDimBits = 10;
// The voxel tag width of the rings and shading unit verilated with tags
// (bela §III; CMake CUBE4_SYSTEM_TAG_PIPES, checked in rtl_factory.cpp): a
// scene's tags of up to this many bits use them, in their low bits.
constexpr int kRtlVoxelTagBits = 4;

// The widths the system's RTL is verilated with: the defaults, or CMake's
// CUBE4_SYSTEM_WIDTHS (cmake/system_widths.cmake); tag_bits is 0 (voxel
// tags have variants of their own).
golden::Precision rtl_precision();
// Throws, naming the first width (tags aside) in which p differs from
// rtl_precision(), if it does; `what` names the hardware that needs them.
void require_rtl_widths(const golden::Precision& p, const std::string& what);

std::vector<int> rtl_pipes();
bool rtl_available(int p);
// Throws, naming the p values that have RTL, if p has none.
void require_rtl(int p);
// The p values verilated with voxel tags; throws, naming them, if a scene
// with tags (tag_bits > 0) has no such RTL at p.
std::vector<int> rtl_tag_pipes();
void require_rtl_tags(int p, int tag_bits);
// The p values whose compositing ring is verilated with polygon hardware
// (Cube-5; CMake CUBE4_SYSTEM_POLYGON_PIPES); throws, naming them, if p has none.
std::vector<int> rtl_polygon_pipes();
void require_rtl_polygons(int p);
// The p values whose interpolation and gradient rings are verilated with
// VolumePro's z gradient (HasZDiff, HasVoxelZ; CMake
// CUBE4_SYSTEM_ZDIFF_PIPES); throws, naming them, if p has none, or if the
// scene also has voxel tags (no ring has both).
std::vector<int> rtl_zdiff_pipes();
void require_rtl_zdiff(int p, int tag_bits);
// The p values with the perspective interpolation and gradient rings
// (Cube-4 §3; CMake CUBE4_SYSTEM_PERSP_PIPES); throws, naming them, if p
// has none.
std::vector<int> rtl_persp_pipes();
void require_rtl_perspective(int p);
// The p values whose perspective compositing ring is verilated with polygon
// hardware (both CUBE4_SYSTEM_PERSP_PIPES and CUBE4_SYSTEM_POLYGON_PIPES);
// throws, naming them, if p has none.
std::vector<int> rtl_persp_polygon_pipes();
void require_rtl_persp_polygons(int p);
// The p values whose perspective interpolation and gradient rings are
// verilated with VolumePro's z gradient (both CUBE4_SYSTEM_PERSP_PIPES and
// CUBE4_SYSTEM_ZDIFF_PIPES); throws, naming them, if p has none, or if the
// scene also has voxel tags (no ring has both).
std::vector<int> rtl_persp_zdiff_pipes();
void require_rtl_persp_zdiff(int p, int tag_bits);
std::unique_ptr<PerspInterpIf> make_rtl_interp_persp(const FramePlan& plan, VerilatedContext& ctx,
                                                     const TraceWindow& trace);
// The perspective gradient ring (cube4_gradient_persp_ring), on
// TlmGradientPersp's schedule; check_perspective_levels() (system.cpp)
// refuses the frames outside its preconditions first: at least
// kRtlGradientPerspMinRows rows (ny) and kRtlGradientPerspMinRow stream
// positions a beam (ceil(nx / p) * p).
constexpr int kRtlGradientPerspMinRows = 6, kRtlGradientPerspMinRow = 7;
std::unique_ptr<PerspGradientIf> make_rtl_gradient_persp(const FramePlan& plan, VerilatedContext& ctx,
                                                         const TraceWindow& trace);
// The perspective compositing ring (cube4_composite_persp_ring, reach
// kPerspectiveReach), on TlmCompositePersp's schedule; frames with fewer
// than kRtlGradientPerspMinRows rows or beams shorter than
// kRtlCompositePerspMinRow positions are refused first. A frame with
// polygons gets the ring with polygon hardware, fed the polygon images.
constexpr int kRtlCompositePerspMinRow = 8 + kPerspectiveReach;
std::unique_ptr<PerspCompositor> make_rtl_composite_persp(const FramePlan& plan, bool accumulators,
                                                          VerilatedContext& ctx, const TraceWindow& trace,
                                                          const golden::PolygonFrame* polygons = nullptr);
// The weight generator at RTL (cube4_dda, one for all pipelines): the
// control of slices 0 .. K of a parallel-projection frame (FramePlan's
// slice_controls), clocked through the frame's slices before it starts
// (set-up clocks, not traced: docs/rtl-dda.md says why the frame's cycles
// are the same).
std::vector<golden::SliceControl> rtl_slice_controls(const golden::Registers& r, VerilatedContext& ctx);
// The same unit in a perspective frame (its divisions, cube4_persp_slice,
// included): the constants of slices 0 .. K - 1 (FramePlan's
// perspective_slices), set-up clocks before the frame likewise.
std::vector<golden::PerspectiveSlice> rtl_perspective_slices(const golden::Registers& r, VerilatedContext& ctx);
std::unique_ptr<AddrIf> make_rtl_addr(const FramePlan& plan, const golden::SkewLayout& layout, VerilatedContext& ctx,
                                      const TraceWindow& trace);
std::unique_ptr<InterpIf> make_rtl_interp(const FramePlan& plan, VerilatedContext& ctx, const TraceWindow& trace);
std::unique_ptr<GradientIf> make_rtl_gradient(const FramePlan& plan, VerilatedContext& ctx, const TraceWindow& trace);
// Scenes without shading and without gradient-magnitude modulation get the
// shading unit without reflectance-map, Phong and magnitude hardware.
// full: the complete hardware whatever the scene needs (--simulate-all).
// Only pipelines [first, last) (last < 0: to p), on ctx: the shading units
// split between two threads (RtlShade).
std::unique_ptr<ShadeIf> make_rtl_shade(const FramePlan& plan, VerilatedContext& ctx, const TraceWindow& trace,
                                        bool full = false, int first = 0, int last = -1);
// The same units shading a perspective frame's ray beats (RtlShadePersp).
std::unique_ptr<PerspShadeIf> make_rtl_shade_persp(const FramePlan& plan, VerilatedContext& ctx,
                                                   const TraceWindow& trace, bool full = false);
// Scenes without a cut plane get the ring without cut-plane hardware
// (HasCutPlane = 0): that logic is not simulated. A frame with polygons
// gets the ring with polygon hardware (and cut plane), fed the frame's
// polygon images once per frame of a stream of `frames`.
std::unique_ptr<CompositeIf> make_rtl_composite(const FramePlan& plan, PixelMemory& pixels, VerilatedContext& ctx,
                                                const TraceWindow& trace, bool full = false,
                                                const golden::PolygonFrame* polygons = nullptr, int frames = 1);

// The composition network's units (systemc/core/compose_network.hpp),
// verilated once at rtl_precision(); `index` names the node.
struct ComposeNodeIf;
struct ComposeOutIf;
std::unique_ptr<ComposeNodeIf> make_rtl_compose_node(golden::BlendMode mode, const golden::Precision& p,
                                                     VerilatedContext& ctx, const TraceWindow& trace, size_t index);
std::unique_ptr<ComposeOutIf> make_rtl_compose_out(const golden::Precision& p, VerilatedContext& ctx);

}  // namespace cube4::sysc
