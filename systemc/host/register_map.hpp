// The host interface's address map (docs/registers.md): one byte-addressed
// 64-bit address space of 32-bit registers and table windows. 64-bit values
// are two words, low word first, 8-byte aligned, so one 8-byte transaction
// moves a whole value. Signed values are two's complement in 32 (or 64) bits.
//
// kRegisters declares every register once: its address, access, hardware
// width, the golden::Registers field it carries and the RTL input it drives.
// The address constants below, the register file's decoder and checks, the
// host program's writes and the tables of docs/registers.md (register_doc)
// are all derived from it.
#pragma once
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>

#include "golden/registers.hpp"
#include "golden/volume.hpp"

namespace cube4::sysc {

// The hardware's fixed parameters: what the identification and precision
// registers report and what bounds the writable fields.
struct HardwareParams {
  golden::Precision precision;
  int pipelines = 4;
  int max_dim = 256;
  // Voxels the voxel memory holds, for every resident subvolume together
  // (VolumePro §4.2; 2^30: 1024³, the volume window's largest volume).
  uint64_t voxel_memory = uint64_t{1} << 30;
};

}  // namespace cube4::sysc

namespace cube4::sysc::regmap {

// Subvolumes (VolumePro §4.2): volumes resident in voxel memory at once;
// VOL_INDEX says which one the volume registers and windows address,
// VOL_SELECT which one START renders.
constexpr int kSubvolumes = 8;

// What the writable registers hold: a frame's registers, each subvolume's
// object-order dimensions, the subvolume addressed and the one rendered,
// and the slab the slab window reads and writes.
struct RegisterValues {
  golden::Registers regs;
  std::array<std::array<int, 3>, kSubvolumes> vol_dims{};
  int vol_index = 0, vol_select = 0;
  std::array<int, 3> slab_origin{0, 0, 0}, slab_size{0, 0, 0};
  // The polygon images (Cube-5) the next START composites: whether it does,
  // and the base plane's width and height and the sample slices they were
  // made for (START checks them against the frame's).
  bool poly_enable = false;
  std::array<int, 3> poly_size{0, 0, 0};
  const std::array<int, 3>& vol_dim() const { return vol_dims[static_cast<size_t>(vol_index)]; }
  std::array<int, 3>& vol_dim() { return vol_dims[static_cast<size_t>(vol_index)]; }
};

enum class Block { Control, Identification, Precision, View, Mode, Cropping, Window, CutPlane, Shading, Volume, Polygons };
enum class Access { R, W, RW };
// Symmetric: ±(2^(width-1)-1), as golden saturates.
enum class Sign { Unsigned, Signed, Symmetric };
// The values a write may take: those of the width, or a rule of its own.
enum class Rule { Width, Dim, Supersampling, Permutation, Mode };

// A hardware field's width: `bits`, plus the golden::Precision width `plus` names.
struct Width {
  int bits = 32;
  int golden::Precision::*plus = nullptr;
  constexpr int of(const golden::Precision& p) const { return bits + (plus ? p.*plus : 0); }
};

using Getter = uint64_t (*)(const RegisterValues&, const HardwareParams&);
using Setter = void (*)(RegisterValues&, uint64_t);

struct Register {
  const char* name = "";
  uint64_t addr = 0;
  Block block = Block::Control;
  Access access = Access::R;
  int words = 1;                  // 2: a 64-bit value, NAME_LO at addr, NAME_HI at addr + 4
  Width width;
  Sign sign = Sign::Unsigned;
  Rule rule = Rule::Width;
  const char* golden_field = "";  // in golden::Registers (VOL_DIM: golden::Volume::dim)
  Getter get = nullptr;           // nullptr: the control block, which HostInterface reads
  Setter set = nullptr;           // nullptr: not writable through the register file
  const char* rtl_port = "";      // the RTL input it drives (or the RTL parameter it reports)
  const char* meaning = "";
};

constexpr int kMaxDimLimit = 1024;   // volume window: 2 bytes * 1024^3 = 2 GiB
constexpr int kMaxPipelines = 256;
constexpr int kMaxSupersampling = 8;

constexpr uint32_t kMagic = 0x43554234;       // "CUB4"
constexpr uint32_t kVersion = 0x00010000;     // 1.0

constexpr uint32_t kCtrlStart = 1u << 0;
constexpr uint32_t kCtrlReset = 1u << 1;       // register file, error state and DONE
constexpr uint32_t kCtrlClearError = 1u << 2;
constexpr uint32_t kCtrlMask = 0x7;

constexpr uint32_t kStatusBusy = 1u << 0;
constexpr uint32_t kStatusDone = 1u << 1;      // the frame started last has completed
constexpr uint32_t kStatusError = 1u << 2;     // sticky until CLEAR_ERROR or RESET

constexpr uint32_t kModeGradient = 1u << 0;
constexpr uint32_t kModeMagnitude = 1u << 1;
constexpr uint32_t kModeShading = 1u << 2;
constexpr uint32_t kModeSpecular = 1u << 3;
constexpr uint32_t kModeGmOpacity = 1u << 4;
constexpr uint32_t kModeGmDiffuse = 1u << 5;
constexpr uint32_t kModeGmSpecular = 1u << 6;
constexpr int kModeBlendShift = 8;            // bits 9:8, golden::BlendMode 0..2
constexpr uint32_t kModeBlendMask = 3u << kModeBlendShift;
constexpr uint32_t kModeCrop = 1u << 12;
constexpr uint32_t kModeCut = 1u << 13;
constexpr uint32_t kModeWindow = 1u << 14;
constexpr uint32_t kModeVoxelZGradient = 1u << 15;  // golden::ZGradient::VoxelDifferences
constexpr uint32_t kModePerspective = 1u << 16;
constexpr uint32_t kModeMask =
    0x7F | kModeBlendMask | kModeCrop | kModeCut | kModeWindow | kModeVoxelZGradient | kModePerspective;

constexpr uint32_t kCutKeepInside = 1u << 0;

// The MODE register's word for the registers' mode bits, and back.
constexpr uint32_t mode_word(const golden::Registers& r) {
  uint32_t m = static_cast<uint32_t>(r.blend) << kModeBlendShift;
  if (r.gradient) m |= kModeGradient;
  if (r.magnitude) m |= kModeMagnitude;
  if (r.shading) m |= kModeShading;
  if (r.specular) m |= kModeSpecular;
  if (r.gm_opacity) m |= kModeGmOpacity;
  if (r.gm_diffuse) m |= kModeGmDiffuse;
  if (r.gm_specular) m |= kModeGmSpecular;
  if (r.crop_enabled) m |= kModeCrop;
  if (r.cut_enabled) m |= kModeCut;
  if (r.window_enabled) m |= kModeWindow;
  if (r.z_gradient == golden::ZGradient::VoxelDifferences) m |= kModeVoxelZGradient;
  if (r.perspective) m |= kModePerspective;
  return m;
}
constexpr void set_mode(golden::Registers& r, uint64_t v) {
  r.gradient = v & kModeGradient;
  r.magnitude = v & kModeMagnitude;
  r.shading = v & kModeShading;
  r.specular = v & kModeSpecular;
  r.gm_opacity = v & kModeGmOpacity;
  r.gm_diffuse = v & kModeGmDiffuse;
  r.gm_specular = v & kModeGmSpecular;
  r.blend = static_cast<golden::BlendMode>((v & kModeBlendMask) >> kModeBlendShift);
  r.crop_enabled = v & kModeCrop;
  r.cut_enabled = v & kModeCut;
  r.window_enabled = v & kModeWindow;
  r.z_gradient = v & kModeVoxelZGradient ? golden::ZGradient::VoxelDifferences : golden::ZGradient::Abc;
  r.perspective = v & kModePerspective;
}

// The classification table's address is {tag, value} (golden class_address).
constexpr size_t class_entries(const golden::Precision& p) { return size_t{1} << (p.voxel_bits + p.tag_bits); }
// One material per tag with tags (golden Registers::tag_coefs), none without.
constexpr size_t material_entries(const golden::Precision& p) { return p.tag_bits ? size_t{1} << p.tag_bits : 0; }
// A voxel memory word is {tag, value}: the tag above voxel_bits (bela's
// "bits per voxel and tag"; scene_io keeps the pair within 16 bits).
constexpr uint32_t voxel_word_max(const golden::Precision& p) {
  return (uint32_t{1} << (p.voxel_bits + p.tag_bits)) - 1;
}
// Voxel i of vol as that word (its tag 0 when vol has none).
inline uint32_t voxel_word(const golden::Volume& vol, size_t i) {
  return uint32_t{vol.data[i]} | (vol.tags.empty() ? 0u : uint32_t{vol.tags[i]} << vol.bits);
}
constexpr size_t gm_entries(const golden::Precision& p) { return size_t{1} << p.magnitude_bits; }
constexpr size_t map_entries(const golden::Precision& p) { return size_t{6} * p.map_face_res * p.map_face_res; }

constexpr uint64_t kPrecisionBase = 0x080;
constexpr uint64_t kPrecisionEnd = 0x100;  // room for 32 widths
static_assert(kPrecisionBase + 4 * golden::kPrecisionFieldCount <= kPrecisionEnd,
              "the precision block is full: move the view block up");

namespace detail {

// A golden::Registers (or RegisterValues) member as a register: its name for
// the docs, a getter and a setter. Signed members reach the bus sign-extended.
#define CUBE4_REG_BITS(member, expr_get, expr_set)                                                        \
  #member, [](const RegisterValues& v, const HardwareParams&) -> uint64_t { const auto& f = v.regs.member; return expr_get; }, \
      [](RegisterValues& v, uint64_t w) { auto& f = v.regs.member; expr_set; }
#define CUBE4_REG_FIELD(member) \
  CUBE4_REG_BITS(member, static_cast<uint64_t>(f), f = static_cast<std::remove_reference_t<decltype(f)>>(w))
#define CUBE4_REG_HW(expr) \
  "", [](const RegisterValues&, [[maybe_unused]] const HardwareParams& hw) { return static_cast<uint64_t>(expr); }, nullptr

using golden::Precision;
constexpr Width bits(int n) { return Width{n, nullptr}; }
constexpr Width precision_bits(int Precision::*w, int plus = 0) { return Width{plus, w}; }

// Everything but the precision block, which golden::kPrecisionFields lays out.
inline constexpr Register kListed[] = {
    // ---- Control and status: HostInterface's, as they act on the system model.
    {"CTRL", 0x000, Block::Control, Access::W, 1, bits(3), Sign::Unsigned, Rule::Width, "", nullptr, nullptr, "",
     "bit 0 START, bit 1 RESET, bit 2 CLEAR_ERROR; applied RESET, CLEAR_ERROR, START in that order"},
    {"STATUS", 0x004, Block::Control, Access::R, 1, bits(3), Sign::Unsigned, Rule::Width, "", nullptr, nullptr, "",
     "bit 0 BUSY (a frame is running), bit 1 DONE (the frame started last has completed), bit 2 ERROR (sticky)"},
    {"LAST_ERROR", 0x008, Block::Control, Access::R, 1, bits(32), Sign::Unsigned, Rule::Width, "", nullptr, nullptr, "",
     "error code of the latest error response (table below); 0 after RESET"},
    {"ERROR_ADDR", 0x010, Block::Control, Access::R, 2, bits(64), Sign::Unsigned, Rule::Width, "", nullptr, nullptr, "",
     "address of the word at fault (START checks: CTRL, or the 64-bit register out of range); 0 after RESET"},
    {"FRAME_COUNT", 0x018, Block::Control, Access::R, 2, bits(64), Sign::Unsigned, Rule::Width, "", nullptr, nullptr, "",
     "frames completed by the system model"},
    {"CYCLES", 0x020, Block::Control, Access::R, 2, bits(64), Sign::Unsigned, Rule::Width, "", nullptr, nullptr, "",
     "clock cycles of the last frame"},
    {"BASE_WIDTH", 0x028, Block::Control, Access::R, 1, bits(32), Sign::Unsigned, Rule::Width, "", nullptr, nullptr, "",
     "last frame's base-plane width (0 before a frame)"},
    {"BASE_HEIGHT", 0x02C, Block::Control, Access::R, 1, bits(32), Sign::Unsigned, Rule::Width, "", nullptr, nullptr, "",
     "last frame's base-plane height"},

    // ---- Identification: what the built hardware is.
    {"ID_MAGIC", 0x040, Block::Identification, Access::R, 1, bits(32), Sign::Unsigned, Rule::Width,
     CUBE4_REG_HW(kMagic), "", "0x43554234 (\"CUB4\")"},
    {"ID_VERSION", 0x044, Block::Identification, Access::R, 1, bits(32), Sign::Unsigned, Rule::Width,
     CUBE4_REG_HW(kVersion), "", "major.minor in 16.16; a host refuses another major"},
    {"ID_PIPELINES", 0x048, Block::Identification, Access::R, 1, bits(32), Sign::Unsigned, Rule::Width,
     CUBE4_REG_HW(hw.pipelines), "NumPipes", "p"},
    {"ID_MAX_DIM", 0x04C, Block::Identification, Access::R, 1, bits(32), Sign::Unsigned, Rule::Width,
     CUBE4_REG_HW(hw.max_dim), "MaxDim", "largest volume dimension (2..1024)"},
    {"ID_VOXEL_BITS", 0x050, Block::Identification, Access::R, 1, bits(32), Sign::Unsigned, Rule::Width,
     CUBE4_REG_HW(hw.precision.voxel_bits), "VoxelBits", "`voxel_bits`"},
    {"ID_CLASS_ENTRIES", 0x054, Block::Identification, Access::R, 1, bits(32), Sign::Unsigned, Rule::Width,
     CUBE4_REG_HW(class_entries(hw.precision)), "", "2^(`voxel_bits` + `tag_bits`): address {tag, value}"},
    {"ID_GMLUT_ENTRIES", 0x058, Block::Identification, Access::R, 1, bits(32), Sign::Unsigned, Rule::Width,
     CUBE4_REG_HW(gm_entries(hw.precision)), "", "2^`magnitude_bits`"},
    {"ID_MAP_ENTRIES", 0x05C, Block::Identification, Access::R, 1, bits(32), Sign::Unsigned, Rule::Width,
     CUBE4_REG_HW(map_entries(hw.precision)), "", "6·`map_face_res`² per reflectance map"},
    {"ID_BASE_MAX", 0x060, Block::Identification, Access::R, 1, bits(32), Sign::Unsigned, Rule::Width,
     CUBE4_REG_HW(2 * hw.max_dim), "", "2·max dim: largest base-plane width and height (pixel memory)"},
    {"ID_VOXEL_MEMORY", 0x064, Block::Identification, Access::R, 1, bits(32), Sign::Unsigned, Rule::Width,
     CUBE4_REG_HW(hw.voxel_memory >> 10), "",
     "voxel memory in units of 1024 voxels: every resident subvolume together"},
    {"ID_SUBVOLUMES", 0x068, Block::Identification, Access::R, 1, bits(32), Sign::Unsigned, Rule::Width,
     CUBE4_REG_HW(kSubvolumes), "", "subvolumes the voxel memory holds at once (VOL_INDEX, VOL_SELECT)"},

    // ---- View and DDA.
    {"DIM_X", 0x100, Block::View, Access::RW, 1, bits(32), Sign::Unsigned, Rule::Dim, CUBE4_REG_FIELD(dim[0]),
     "cube4_addr.dim_i, cube4_composite_ring.nx_i", "permuted nx"},
    {"DIM_Y", 0x104, Block::View, Access::RW, 1, bits(32), Sign::Unsigned, Rule::Dim, CUBE4_REG_FIELD(dim[1]),
     "cube4_addr.dim_i", "permuted ny"},
    {"DIM_Z", 0x108, Block::View, Access::RW, 1, bits(32), Sign::Unsigned, Rule::Dim, CUBE4_REG_FIELD(dim[2]),
     "cube4_addr.dim_i", "permuted nz"},
    {"PERM", 0x10C, Block::View, Access::RW, 1, bits(6), Sign::Unsigned, Rule::Permutation,
     CUBE4_REG_BITS(perm, uint64_t(f[0] | f[1] << 2 | f[2] << 4),
                    for (int i = 0; i < 3; ++i) f[i] = static_cast<int>(w >> (2 * i) & 3)),
     "cube4_addr.perm_i", "`perm[i]` in bits 2i+1:2i; must be a permutation of 0, 1, 2"},
    {"FLIP", 0x110, Block::View, Access::RW, 1, bits(3), Sign::Unsigned, Rule::Width,
     CUBE4_REG_BITS(flip, uint64_t(f[0] | f[1] << 1 | f[2] << 2),
                    for (int i = 0; i < 3; ++i) f[i] = (w >> i & 1) != 0),
     "cube4_addr.flip_i", "`flip[i]` in bit i"},
    {"SUPERSAMPLING", 0x114, Block::View, Access::RW, 1, bits(32), Sign::Unsigned, Rule::Supersampling,
     CUBE4_REG_FIELD(supersampling), "cube4_addr.repeat_slice_i", "samples per voxel along the rays"},
    {"X_START", 0x118, Block::View, Access::RW, 2, bits(64), Sign::Signed, Rule::Width, CUBE4_REG_FIELD(x_start),
     "cube4_dda.x_start_i", "`dda_frac_bits` fraction"},
    {"X_STEP", 0x120, Block::View, Access::RW, 2, bits(64), Sign::Signed, Rule::Width, CUBE4_REG_FIELD(x_step),
     "cube4_dda.x_step_i", "per sample slice"},
    {"Y_START", 0x128, Block::View, Access::RW, 2, bits(64), Sign::Signed, Rule::Width, CUBE4_REG_FIELD(y_start),
     "cube4_dda.y_start_i", ""},
    {"Y_STEP", 0x130, Block::View, Access::RW, 2, bits(64), Sign::Signed, Rule::Width, CUBE4_REG_FIELD(y_step),
     "cube4_dda.y_step_i", ""},
#define CUBE4_MARGIN(reg, addr, axis, meaning)                                                                     \
    {reg, addr, Block::View, Access::RW, 1, bits(32), Sign::Unsigned, Rule::Width,                                 \
     "margin_lo[" #axis "], margin_hi[" #axis "]",                                                                 \
     [](const RegisterValues& v, const HardwareParams&) {                                                          \
       return static_cast<uint64_t>(v.regs.margin_lo[axis]) | static_cast<uint64_t>(v.regs.margin_hi[axis]) << 16; \
     },                                                                                                            \
     [](RegisterValues& v, uint64_t w) {                                                                           \
       v.regs.margin_lo[axis] = static_cast<int>(w & 0xFFFF);                                                      \
       v.regs.margin_hi[axis] = static_cast<int>(w >> 16 & 0xFFFF);                                                \
     },                                                                                                            \
     "— (pixel memory: the base plane's size and origin)", meaning}
    CUBE4_MARGIN("MARGIN_U", 0x138, 0,
                 "polygon margins (Cube-5): base-plane pixels before (bits 15:0) and after (31:16) the volume's rays "
                 "in u; 0 without polygons"),
    CUBE4_MARGIN("MARGIN_V", 0x13C, 1, "the same in v"),
#undef CUBE4_MARGIN

    // ---- Mode.
    {"MODE", 0x140, Block::Mode, Access::RW, 1, bits(17), Sign::Unsigned, Rule::Mode,
     "gradient … perspective",
     [](const RegisterValues& v, const HardwareParams&) { return uint64_t{mode_word(v.regs)}; },
     [](RegisterValues& v, uint64_t w) { set_mode(v.regs, w); },
     "cube4_shade_unit magnitude_i … gm_specular_i, cube4_composite_ring blend_mode_i, crop_enabled_i, "
     "cut_enabled_i, window_enabled_i, cube4_dda perspective_i",
     "bit 0 `gradient`, 1 `magnitude`, 2 `shading`, 3 `specular`, 4 `gm_opacity`, 5 `gm_diffuse`, "
     "6 `gm_specular`, bits 9:8 `blend` (0 composite, 1 MIP, 2 MinIP; 3 is out of range), "
     "bit 12 `crop_enabled`, bit 13 `cut_enabled`, bit 14 `window_enabled` (a block of a partitioned volume), "
     "bit 15 `z_gradient` (0 the 12-neighbourhood, 1 VolumePro's interpolated voxel differences: the rings "
     "built with HasZDiff and HasVoxelZ, the stream primed each frame; docs/rtl-interp-zdiff.md), bit 16 `perspective` (Cube-4's perspective projection: X_START … Y_STEP then give ray "
     "0's position per slice, which cube4_dda walks as in parallel projection; docs/perspective.md)"},
    // Perspective: the rays' spacing per sample slice (golden Registers::ray_spacing()).
    {"SCALE_START", 0x150, Block::View, Access::RW, 2, bits(64), Sign::Signed, Rule::Width,
     CUBE4_REG_FIELD(scale_start), "cube4_dda.scale_start_i",
     "perspective: the rays' spacing on the first sample slice, `dda_frac_bits` fraction (one for a whole volume, "
     "that slice's spacing for a block: golden/blocks.hpp); START refuses it below one or above three"},
    {"SCALE_STEP", 0x158, Block::View, Access::RW, 2, bits(64), Sign::Signed, Rule::Width,
     CUBE4_REG_FIELD(scale_step), "cube4_dda.scale_step_i",
     "perspective: the spacing's growth per sample slice; START refuses it negative or taking the last slice's "
     "spacing above three (the box filter's reach)"},

    // ---- Cropping.
    {"CROP_X_LO", 0x180, Block::Cropping, Access::RW, 1, bits(golden::kPositionBits), Sign::Unsigned, Rule::Width,
     CUBE4_REG_FIELD(crop.slab[0][0]), "cube4_composite_ring.crop_x_lo_i",
     "inclusive slab, permuted voxel coordinates"},
    {"CROP_X_HI", 0x184, Block::Cropping, Access::RW, 1, bits(golden::kPositionBits), Sign::Unsigned, Rule::Width,
     CUBE4_REG_FIELD(crop.slab[0][1]), "cube4_composite_ring.crop_x_hi_i", ""},
    {"CROP_Y_LO", 0x188, Block::Cropping, Access::RW, 1, bits(golden::kPositionBits), Sign::Unsigned, Rule::Width,
     CUBE4_REG_FIELD(crop.slab[1][0]), "cube4_composite_ring.crop_y_lo_i", ""},
    {"CROP_Y_HI", 0x18C, Block::Cropping, Access::RW, 1, bits(golden::kPositionBits), Sign::Unsigned, Rule::Width,
     CUBE4_REG_FIELD(crop.slab[1][1]), "cube4_composite_ring.crop_y_hi_i", ""},
    {"CROP_Z_LO", 0x190, Block::Cropping, Access::RW, 1, bits(golden::kPositionBits), Sign::Unsigned, Rule::Width,
     CUBE4_REG_FIELD(crop.slab[2][0]), "cube4_composite_ring.crop_z_lo_i", ""},
    {"CROP_Z_HI", 0x194, Block::Cropping, Access::RW, 1, bits(golden::kPositionBits), Sign::Unsigned, Rule::Width,
     CUBE4_REG_FIELD(crop.slab[2][1]), "cube4_composite_ring.crop_z_hi_i", ""},
    {"CROP_MASK", 0x198, Block::Cropping, Access::RW, 1, bits(8), Sign::Unsigned, Rule::Width,
     CUBE4_REG_FIELD(crop.mask), "cube4_composite_ring.crop_mask_i",
     "visible iff bit (inX \\| inY<<1 \\| inZ<<2)"},

    // ---- Block window (golden/blocks.hpp): what a block machine composites.
    {"WINDOW_X_LO", 0x1A0, Block::Window, Access::RW, 1, bits(golden::kPositionBits), Sign::Unsigned, Rule::Width,
     CUBE4_REG_FIELD(window.range[0][0]), "cube4_composite_ring.window_x_lo_i",
     "inclusive range, permuted voxel coordinates of the block"},
    {"WINDOW_X_HI", 0x1A4, Block::Window, Access::RW, 1, bits(golden::kPositionBits), Sign::Unsigned, Rule::Width,
     CUBE4_REG_FIELD(window.range[0][1]), "cube4_composite_ring.window_x_hi_i", ""},
    {"WINDOW_Y_LO", 0x1A8, Block::Window, Access::RW, 1, bits(golden::kPositionBits), Sign::Unsigned, Rule::Width,
     CUBE4_REG_FIELD(window.range[1][0]), "cube4_composite_ring.window_y_lo_i", ""},
    {"WINDOW_Y_HI", 0x1AC, Block::Window, Access::RW, 1, bits(golden::kPositionBits), Sign::Unsigned, Rule::Width,
     CUBE4_REG_FIELD(window.range[1][1]), "cube4_composite_ring.window_y_hi_i", ""},
    {"WINDOW_Z_LO", 0x1B0, Block::Window, Access::RW, 1, bits(golden::kPositionBits), Sign::Unsigned, Rule::Width,
     CUBE4_REG_FIELD(window.range[2][0]), "cube4_composite_ring.window_z_lo_i", "voxel slices"},
    {"WINDOW_Z_HI", 0x1B4, Block::Window, Access::RW, 1, bits(golden::kPositionBits), Sign::Unsigned, Rule::Width,
     CUBE4_REG_FIELD(window.range[2][1]), "cube4_composite_ring.window_z_hi_i", ""},

    // ---- Cut plane.
    {"CUT_A", 0x1C0, Block::CutPlane, Access::RW, 1, bits(golden::kCutCoefBits), Sign::Signed, Rule::Width,
     CUBE4_REG_FIELD(cut.a), "cube4_composite_ring.cut_a_i", "normal, 2^10 scale (`kCutNormalBits`)"},
    {"CUT_B", 0x1C4, Block::CutPlane, Access::RW, 1, bits(golden::kCutCoefBits), Sign::Signed, Rule::Width,
     CUBE4_REG_FIELD(cut.b), "cube4_composite_ring.cut_b_i", ""},
    {"CUT_C", 0x1C8, Block::CutPlane, Access::RW, 1, bits(golden::kCutCoefBits), Sign::Signed, Rule::Width,
     CUBE4_REG_FIELD(cut.c), "cube4_composite_ring.cut_c_i", ""},
    {"CUT_FLAGS", 0x1CC, Block::CutPlane, Access::RW, 1, bits(1), Sign::Unsigned, Rule::Width,
     CUBE4_REG_BITS(cut.keep_inside, f ? kCutKeepInside : 0, f = (w & kCutKeepInside) != 0),
     "cube4_composite_ring.cut_keep_inside_i", "bit 0"},
    {"CUT_DMIN", 0x1D0, Block::CutPlane, Access::RW, 2, precision_bits(&Precision::cut_bits), Sign::Signed,
     Rule::Width, CUBE4_REG_FIELD(cut.dmin), "cube4_composite_ring.cut_dmin_i", "distance units of d"},
    {"CUT_DMAX", 0x1D8, Block::CutPlane, Access::RW, 2, precision_bits(&Precision::cut_bits), Sign::Signed,
     Rule::Width, CUBE4_REG_FIELD(cut.dmax), "cube4_composite_ring.cut_dmax_i", ""},
    {"CUT_FALLOFF", 0x1E0, Block::CutPlane, Access::RW, 2, precision_bits(&Precision::cut_bits), Sign::Unsigned,
     Rule::Width, CUBE4_REG_FIELD(cut.falloff), "cube4_composite_ring.cut_falloff_i", "0: hard cut"},
    {"CUT_INV_FALLOFF", 0x1E8, Block::CutPlane, Access::RW, 2,
     precision_bits(&Precision::alpha_bits, golden::kCutInvShift), Sign::Unsigned, Rule::Width,
     CUBE4_REG_FIELD(cut.inv_falloff), "cube4_composite_ring.cut_inv_falloff_i", "host-computed reciprocal"},

    // ---- Shading.
    {"KE", 0x200, Block::Shading, Access::RW, 1, precision_bits(&Precision::coef_bits), Sign::Unsigned, Rule::Width,
     CUBE4_REG_FIELD(coefs.ke), "cube4_shade_unit.ke_i", "`coef_frac_bits` fraction"},
    {"KD", 0x204, Block::Shading, Access::RW, 1, precision_bits(&Precision::coef_bits), Sign::Unsigned, Rule::Width,
     CUBE4_REG_FIELD(coefs.kd), "cube4_shade_unit.kd_i", ""},
    {"KS", 0x208, Block::Shading, Access::RW, 1, precision_bits(&Precision::coef_bits), Sign::Unsigned, Rule::Width,
     CUBE4_REG_FIELD(coefs.ks), "cube4_shade_unit.ks_i", ""},
    {"SPEC_R", 0x20C, Block::Shading, Access::RW, 1, precision_bits(&Precision::alpha_bits), Sign::Unsigned,
     Rule::Width, CUBE4_REG_FIELD(coefs.specular[0]), "cube4_shade_unit.spec_red_i", "specular colour"},
    {"SPEC_G", 0x210, Block::Shading, Access::RW, 1, precision_bits(&Precision::alpha_bits), Sign::Unsigned,
     Rule::Width, CUBE4_REG_FIELD(coefs.specular[1]), "cube4_shade_unit.spec_green_i", ""},
    {"SPEC_B", 0x214, Block::Shading, Access::RW, 1, precision_bits(&Precision::alpha_bits), Sign::Unsigned,
     Rule::Width, CUBE4_REG_FIELD(coefs.specular[2]), "cube4_shade_unit.spec_blue_i", ""},
    {"EYE_X", 0x218, Block::Shading, Access::RW, 1, precision_bits(&Precision::eye_bits), Sign::Symmetric,
     Rule::Width, CUBE4_REG_FIELD(eye[0]), "cube4_shade_unit.eye_x_i", "sign-extended to 32 bits"},
    {"EYE_Y", 0x21C, Block::Shading, Access::RW, 1, precision_bits(&Precision::eye_bits), Sign::Symmetric,
     Rule::Width, CUBE4_REG_FIELD(eye[1]), "cube4_shade_unit.eye_y_i", ""},
    {"EYE_Z", 0x220, Block::Shading, Access::RW, 1, precision_bits(&Precision::eye_bits), Sign::Symmetric,
     Rule::Width, CUBE4_REG_FIELD(eye[2]), "cube4_shade_unit.eye_z_i", ""},

    // ---- Volume.
    {"VOL_DIM_X", 0x240, Block::Volume, Access::RW, 1, bits(32), Sign::Unsigned, Rule::Dim, "golden::Volume::dim[0]",
     [](const RegisterValues& v, const HardwareParams&) { return static_cast<uint64_t>(v.vol_dim()[0]); },
     [](RegisterValues& v, uint64_t w) { v.vol_dim()[0] = static_cast<int>(w); }, "— (voxel memory layout)",
     "object-order nx of subvolume VOL_INDEX; a new size clears the subvolume"},
    {"VOL_DIM_Y", 0x244, Block::Volume, Access::RW, 1, bits(32), Sign::Unsigned, Rule::Dim, "golden::Volume::dim[1]",
     [](const RegisterValues& v, const HardwareParams&) { return static_cast<uint64_t>(v.vol_dim()[1]); },
     [](RegisterValues& v, uint64_t w) { v.vol_dim()[1] = static_cast<int>(w); }, "— (voxel memory layout)", "ny"},
    {"VOL_DIM_Z", 0x248, Block::Volume, Access::RW, 1, bits(32), Sign::Unsigned, Rule::Dim, "golden::Volume::dim[2]",
     [](const RegisterValues& v, const HardwareParams&) { return static_cast<uint64_t>(v.vol_dim()[2]); },
     [](RegisterValues& v, uint64_t w) { v.vol_dim()[2] = static_cast<int>(w); }, "— (voxel memory layout)", "nz"},
    {"VOL_INDEX", 0x24C, Block::Volume, Access::RW, 1, bits(3), Sign::Unsigned, Rule::Width, "— (subvolume)",
     [](const RegisterValues& v, const HardwareParams&) { return static_cast<uint64_t>(v.vol_index); },
     [](RegisterValues& v, uint64_t w) { v.vol_index = static_cast<int>(w); }, "— (voxel memory)",
     "the subvolume VOL_DIM, the volume window and the slab window address (0..ID_SUBVOLUMES-1)"},
    {"VOL_SELECT", 0x250, Block::Volume, Access::RW, 1, bits(3), Sign::Unsigned, Rule::Width, "— (subvolume)",
     [](const RegisterValues& v, const HardwareParams&) { return static_cast<uint64_t>(v.vol_select); },
     [](RegisterValues& v, uint64_t w) { v.vol_select = static_cast<int>(w); }, "cube4_addr (module base address)",
     "the subvolume START renders"},
#define CUBE4_SLAB(reg, addr, field, i, meaning)                                                                  \
    {reg, addr, Block::Volume, Access::RW, 1, bits(16), Sign::Unsigned, Rule::Width, "— (slab)",                   \
     [](const RegisterValues& v, const HardwareParams&) { return static_cast<uint64_t>(v.field[i]); },             \
     [](RegisterValues& v, uint64_t w) { v.field[i] = static_cast<int>(w); }, "— (voxel memory)", meaning}
    CUBE4_SLAB("SLAB_X0", 0x254, slab_origin, 0, "the slab window's box in subvolume VOL_INDEX: first voxel"),
    CUBE4_SLAB("SLAB_Y0", 0x258, slab_origin, 1, ""),
    CUBE4_SLAB("SLAB_Z0", 0x25C, slab_origin, 2, ""),
    CUBE4_SLAB("SLAB_NX", 0x260, slab_size, 0, "its size (a voxel: 1, 1, 1; a slice: nx, ny, 1)"),
    CUBE4_SLAB("SLAB_NY", 0x264, slab_size, 1, ""),
    CUBE4_SLAB("SLAB_NZ", 0x268, slab_size, 2, ""),
#undef CUBE4_SLAB

    // ---- Polygons (Cube-5): what the POLY_* windows hold, for the next START.
    {"POLY_ENABLE", 0x26C, Block::Polygons, Access::RW, 1, bits(1), Sign::Unsigned, Rule::Width, "— (frame input)",
     [](const RegisterValues& v, const HardwareParams&) { return static_cast<uint64_t>(v.poly_enable); },
     [](RegisterValues& v, uint64_t w) { v.poly_enable = w != 0; }, "— (composite buffer)",
     "START composites the polygon images of the POLY_* windows with the volume; they are consumed by it"},
#define CUBE4_POLY(reg, addr, i, meaning)                                                                         \
    {reg, addr, Block::Polygons, Access::RW, 1, bits(16), Sign::Unsigned, Rule::Width, "— (golden::PolygonFrame)", \
     [](const RegisterValues& v, const HardwareParams&) { return static_cast<uint64_t>(v.poly_size[i]); },         \
     [](RegisterValues& v, uint64_t w) { v.poly_size[i] = static_cast<int>(w); }, "— (composite buffer)", meaning}
    CUBE4_POLY("POLY_WIDTH", 0x270, 0, "the polygon images' width: the frame's BASE_WIDTH, margins included"),
    CUBE4_POLY("POLY_HEIGHT", 0x274, 1, "their height (BASE_HEIGHT); writing any of the three clears the images"),
    CUBE4_POLY("POLY_SLICES", 0x278, 2, "slab images: the frame's sample slices (DIM_Z · SUPERSAMPLING)"),
#undef CUBE4_POLY
};

#undef CUBE4_REG_FIELD
#undef CUBE4_REG_BITS
#undef CUBE4_REG_HW


template <size_t I>
constexpr Register precision_register() {
  constexpr const golden::PrecisionField& f = golden::kPrecisionFields[I];
  Register r;
  r.name = f.register_name;
  r.addr = kPrecisionBase + 4 * I;
  r.block = Block::Precision;
  r.golden_field = f.key;
  r.rtl_port = f.rtl_parameter ? f.rtl_parameter : "—";
  r.get = [](const RegisterValues&, const HardwareParams& hw) {
    return static_cast<uint64_t>(hw.precision.*golden::kPrecisionFields[I].member);
  };
  return r;
}

constexpr size_t kRegisterCount = std::size(kListed) + golden::kPrecisionFieldCount;

template <size_t... I>
constexpr std::array<Register, kRegisterCount> sorted_registers(std::index_sequence<I...>) {
  std::array<Register, kRegisterCount> all{};
  size_t n = 0;
  for (const Register& r : kListed) all[n++] = r;
  ((all[n++] = precision_register<I>()), ...);
  for (size_t i = 1; i < n; ++i)
    for (size_t j = i; j > 0 && all[j - 1].addr > all[j].addr; --j) {
      const Register t = all[j];
      all[j] = all[j - 1];
      all[j - 1] = t;
    }
  return all;
}

}  // namespace detail

// Every register, by address.
inline constexpr std::array<Register, detail::kRegisterCount> kRegisters =
    detail::sorted_registers(std::make_index_sequence<golden::kPrecisionFieldCount>{});

// Whether a register carries a writable field of golden::Registers: not the
// voxel memory's (VOL_*, SLAB_*) nor the polygon images' (POLY_*), which the
// host writes beside a frame's registers.
constexpr bool carries_frame_field(const Register& r) {
  return r.set && r.block != Block::Volume && r.block != Block::Polygons;
}

// The register named `name` (for 64-bit ones also NAME_LO and NAME_HI), or nullptr.
constexpr const Register* find_register(std::string_view name) {
  for (const Register& r : kRegisters) {
    if (name == r.name) return &r;
    if (r.words == 2 && name.size() == std::string_view(r.name).size() + 3 &&
        name.substr(0, name.size() - 3) == r.name && (name.substr(name.size() - 3) == "_LO" ||
                                                     name.substr(name.size() - 3) == "_HI"))
      return &r;
  }
  return nullptr;
}

// The register holding the word at a (4-byte aligned), or nullptr.
constexpr const Register* register_at(uint64_t a) {
  for (const Register& r : kRegisters)
    if (a >= r.addr && a < r.addr + 4 * uint64_t(r.words)) return &r;
  return nullptr;
}

// A name's address: unknown names do not compile where a constant is needed.
constexpr uint64_t address_of(std::string_view name) {
  const Register* r = find_register(name);
  if (!r) throw "no such register";
  return r->addr + (name.size() > 3 && name.substr(name.size() - 3) == "_HI" && r->words == 2 ? 4 : 0);
}

// ---- Addresses ---------------------------------------------------------------------
constexpr uint64_t kCtrl = address_of("CTRL");
constexpr uint64_t kStatus = address_of("STATUS");
constexpr uint64_t kLastError = address_of("LAST_ERROR");
constexpr uint64_t kErrorAddrLo = address_of("ERROR_ADDR_LO");
constexpr uint64_t kErrorAddrHi = address_of("ERROR_ADDR_HI");
constexpr uint64_t kFrameCountLo = address_of("FRAME_COUNT_LO");
constexpr uint64_t kFrameCountHi = address_of("FRAME_COUNT_HI");
constexpr uint64_t kCyclesLo = address_of("CYCLES_LO");
constexpr uint64_t kCyclesHi = address_of("CYCLES_HI");
constexpr uint64_t kBaseWidth = address_of("BASE_WIDTH");
constexpr uint64_t kBaseHeight = address_of("BASE_HEIGHT");
constexpr uint64_t kIdMagic = address_of("ID_MAGIC");
constexpr uint64_t kIdVersion = address_of("ID_VERSION");
constexpr uint64_t kIdPipelines = address_of("ID_PIPELINES");
constexpr uint64_t kIdMaxDim = address_of("ID_MAX_DIM");
constexpr uint64_t kIdVoxelBits = address_of("ID_VOXEL_BITS");
constexpr uint64_t kIdClassEntries = address_of("ID_CLASS_ENTRIES");
constexpr uint64_t kIdGmLutEntries = address_of("ID_GMLUT_ENTRIES");
constexpr uint64_t kIdMapEntries = address_of("ID_MAP_ENTRIES");
constexpr uint64_t kIdBaseMax = address_of("ID_BASE_MAX");
constexpr uint64_t kPrecision = kPrecisionBase;
constexpr int kPrecisionFields = golden::kPrecisionFieldCount;
constexpr uint64_t kDimX = address_of("DIM_X");
constexpr uint64_t kDimY = address_of("DIM_Y");
constexpr uint64_t kDimZ = address_of("DIM_Z");
constexpr uint64_t kPerm = address_of("PERM");
constexpr uint64_t kFlip = address_of("FLIP");
constexpr uint64_t kSupersampling = address_of("SUPERSAMPLING");
constexpr uint64_t kXStartLo = address_of("X_START_LO");
constexpr uint64_t kXStartHi = address_of("X_START_HI");
constexpr uint64_t kXStepLo = address_of("X_STEP_LO");
constexpr uint64_t kXStepHi = address_of("X_STEP_HI");
constexpr uint64_t kYStartLo = address_of("Y_START_LO");
constexpr uint64_t kYStartHi = address_of("Y_START_HI");
constexpr uint64_t kYStepLo = address_of("Y_STEP_LO");
constexpr uint64_t kYStepHi = address_of("Y_STEP_HI");
constexpr uint64_t kMode = address_of("MODE");
constexpr uint64_t kCropSlab = address_of("CROP_X_LO");  // x lo, x hi, y lo, y hi, z lo, z hi
constexpr uint64_t kCropMask = address_of("CROP_MASK");
constexpr uint64_t kCutA = address_of("CUT_A");
constexpr uint64_t kCutB = address_of("CUT_B");
constexpr uint64_t kCutC = address_of("CUT_C");
constexpr uint64_t kCutFlags = address_of("CUT_FLAGS");
constexpr uint64_t kCutDminLo = address_of("CUT_DMIN_LO");
constexpr uint64_t kCutDminHi = address_of("CUT_DMIN_HI");
constexpr uint64_t kCutDmaxLo = address_of("CUT_DMAX_LO");
constexpr uint64_t kCutDmaxHi = address_of("CUT_DMAX_HI");
constexpr uint64_t kCutFalloffLo = address_of("CUT_FALLOFF_LO");
constexpr uint64_t kCutFalloffHi = address_of("CUT_FALLOFF_HI");
constexpr uint64_t kCutInvFalloffLo = address_of("CUT_INV_FALLOFF_LO");
constexpr uint64_t kCutInvFalloffHi = address_of("CUT_INV_FALLOFF_HI");
constexpr uint64_t kKe = address_of("KE");
constexpr uint64_t kKd = address_of("KD");
constexpr uint64_t kKs = address_of("KS");
constexpr uint64_t kSpecularColor = address_of("SPEC_R");  // r, g, b
constexpr uint64_t kEye = address_of("EYE_X");             // x, y, z
constexpr uint64_t kVolDim = address_of("VOL_DIM_X");      // x, y, z
constexpr uint64_t kVolIndex = address_of("VOL_INDEX");
constexpr uint64_t kVolSelect = address_of("VOL_SELECT");
constexpr uint64_t kSlab = address_of("SLAB_X0");          // x0, y0, z0, nx, ny, nz
constexpr uint64_t kPolyEnable = address_of("POLY_ENABLE");
constexpr uint64_t kPolySize = address_of("POLY_WIDTH");   // width, height, slices

constexpr uint64_t kRegisterSpace = 0x1000;   // everything above is a window
static_assert(kRegisters.back().addr + 4 * kRegisters.back().words <= kRegisterSpace);

// ---- Windows ---------------------------------------------------------------------
// Each window is sized for the largest parameters the map allows; only the
// part the constructed hardware holds is mapped (the rest: ADDRESS_ERROR).
constexpr uint64_t kClassBase = 0x0010'0000;   // 8 bytes per entry: {r|g<<8|b<<16, a}
constexpr uint64_t kClassSize = 0x0008'0000;   // 2^16 entries
constexpr uint64_t kGmLutBase = 0x0018'0000;   // one word per entry
constexpr uint64_t kGmLutSize = 0x0004'0000;
constexpr uint64_t kDiffuseBase = 0x0020'0000; // one word per entry, golden map_index order
constexpr uint64_t kSpecularBase = 0x0022'0000;
constexpr uint64_t kMapSize = 0x0002'0000;     // 6 * 64^2 entries
constexpr uint64_t kMaterialBase = 0x0024'0000; // 8 words per tag: ke, kd, ks, spec r, g, b, two zero words
constexpr uint64_t kMaterialSize = 0x0000'2000; // 256 tags
constexpr int kMaterialWords = 8;
constexpr uint64_t kBaseBase = 0x0800'0000;    // 8 bytes per pixel: {r|g<<16, b|a<<16}, row-major
constexpr uint64_t kBaseSize = 0x0800'0000;
constexpr uint64_t kVolumeBase = 0x1'0000'0000;  // two voxels per word, x fastest
constexpr uint64_t kVolumeSize = 0x1'0000'0000;
constexpr uint64_t kSlabBase = 0x2'0000'0000;    // the slab's voxels, two per word, x fastest
constexpr uint64_t kSlabSize = 0x1'0000'0000;
// Polygon images (Cube-5), base-plane pixels row-major, POLY_WIDTH wide:
constexpr uint64_t kPolyFrontBase = 0x1000'0000;  // 8 bytes per pixel, as BASE_PLANE: the rays' starting values
constexpr uint64_t kPolyBackBase = 0x1800'0000;   // the same: composited behind each ray
constexpr uint64_t kPolyPixelSize = 0x0800'0000;
constexpr uint64_t kPolyZBase = 0x2000'0000;      // 1 word per pixel: the Z test's depth
constexpr uint64_t kPolyZSize = 0x0400'0000;
// One run-length slab image per sample slice k at kPolySlabBase + k·kPolySlabStride:
// its lines, beam by beam and lane by lane, each a word holding the line's
// 16-bit word count and then those words, two a word, low half first.
constexpr uint64_t kPolySlabBase = 0x100'0000'0000;
constexpr uint64_t kPolySlabStride = 0x200'0000;  // 32 MiB
constexpr uint64_t kPolySlabSize = kPolySlabStride * kMaxSupersampling * kMaxDimLimit;

enum class Region { None, Registers, Class, GmLut, Diffuse, Specular, Material, Base, Volume, Slab, PolyFront, PolyBack,
                    PolyZ, PolySlab };

constexpr Region region_of(uint64_t a) {
  if (a < kRegisterSpace) return Region::Registers;
  if (a >= kClassBase && a - kClassBase < kClassSize) return Region::Class;
  if (a >= kGmLutBase && a - kGmLutBase < kGmLutSize) return Region::GmLut;
  if (a >= kDiffuseBase && a - kDiffuseBase < kMapSize) return Region::Diffuse;
  if (a >= kSpecularBase && a - kSpecularBase < kMapSize) return Region::Specular;
  if (a >= kMaterialBase && a - kMaterialBase < kMaterialSize) return Region::Material;
  if (a >= kBaseBase && a - kBaseBase < kBaseSize) return Region::Base;
  if (a >= kVolumeBase && a - kVolumeBase < kVolumeSize) return Region::Volume;
  if (a >= kSlabBase && a - kSlabBase < kSlabSize) return Region::Slab;
  if (a >= kPolyFrontBase && a - kPolyFrontBase < kPolyPixelSize) return Region::PolyFront;
  if (a >= kPolyBackBase && a - kPolyBackBase < kPolyPixelSize) return Region::PolyBack;
  if (a >= kPolyZBase && a - kPolyZBase < kPolyZSize) return Region::PolyZ;
  if (a >= kPolySlabBase && a - kPolySlabBase < kPolySlabSize) return Region::PolySlab;
  return Region::None;
}

// ---- Field values --------------------------------------------------------------------

// The smallest and largest value of a field, for the rules that are a range.
struct Limits {
  int64_t lo, hi;
};
std::optional<Limits> limits(const Register& r, const HardwareParams& hw);

// The value a register's word(s) carry: one word sign-extended when signed.
constexpr int64_t field_value(const Register& r, uint64_t raw) {
  if (r.words == 1 && r.sign != Sign::Unsigned) return static_cast<int32_t>(static_cast<uint32_t>(raw));
  return static_cast<int64_t>(raw);
}

// Whether the hardware takes raw (the register's whole value, both words of a 64-bit one).
bool fits(const Register& r, uint64_t raw, const HardwareParams& hw);

// The register's reset value (golden::Registers' defaults).
uint64_t reset_value(const Register& r, const HardwareParams& hw);

// LAST_ERROR codes. Every error response sets STATUS.ERROR and records one.
enum class ErrorCode : uint32_t {
  None = 0,
  Unmapped = 1,           // ADDRESS_ERROR: no register or window entry there
  Alignment = 2,          // BURST_ERROR: address or length not a multiple of 4, or no data
  Streaming = 3,          // BURST_ERROR: streaming width below the data length
  ByteEnable = 4,         // BYTE_ENABLE_ERROR: byte enables are not supported
  ReadOnly = 5,           // COMMAND_ERROR: write to a read-only register or window
  WriteOnly = 6,          // COMMAND_ERROR: read of the volume window (the slab window reads)
  CtrlInBurst = 7,        // BURST_ERROR: CTRL must be written alone (it has side effects)
  FieldRange = 8,         // GENERIC_ERROR: value out of range for its field
  Busy = 9,               // GENERIC_ERROR: START, volume write or base-plane read while busy
  VolumeDimsUnset = 10,   // GENERIC_ERROR: volume window or START before VOL_DIM is set
  VoxelOutOfVolume = 11,  // GENERIC_ERROR: voxel index past nx*ny*nz
  ViewMismatch = 12,      // GENERIC_ERROR at START: DIM[i] != VOL_DIM[perm[i]]
  BasePlaneTooLarge = 13, // GENERIC_ERROR at START: base plane outside 1..BASE_MAX
  CutFalloffNegative = 14,// GENERIC_ERROR at START
  PixelOutOfImage = 15,   // GENERIC_ERROR: base-plane pixel past width*height
  BackendFailure = 16,    // GENERIC_ERROR: the system model refused the frame
  SlabOutOfVolume = 17,   // GENERIC_ERROR: slab window access with an empty slab or one past its subvolume
  VoxelMemoryFull = 18,   // GENERIC_ERROR: VOL_DIM write past ID_VOXEL_MEMORY with the other subvolumes
  PolygonSize = 19,       // GENERIC_ERROR: polygon image access past POLY_WIDTH x POLY_HEIGHT or POLY_SLICES, or START with them not the frame's
  PolygonImage = 20,      // GENERIC_ERROR at START: a slab image whose lines do not hold the beam's pixels (ERROR_ADDR: the line's first word)
};

constexpr const char* error_name(ErrorCode e) {
  switch (e) {
    case ErrorCode::None: return "none";
    case ErrorCode::Unmapped: return "unmapped address";
    case ErrorCode::Alignment: return "unaligned address or length";
    case ErrorCode::Streaming: return "streaming not supported";
    case ErrorCode::ByteEnable: return "byte enables not supported";
    case ErrorCode::ReadOnly: return "read-only";
    case ErrorCode::WriteOnly: return "write-only";
    case ErrorCode::CtrlInBurst: return "CTRL written in a burst";
    case ErrorCode::FieldRange: return "value out of range for the field";
    case ErrorCode::Busy: return "busy";
    case ErrorCode::VolumeDimsUnset: return "volume dimensions not set";
    case ErrorCode::VoxelOutOfVolume: return "voxel outside the volume";
    case ErrorCode::ViewMismatch: return "view dimensions do not match the volume";
    case ErrorCode::BasePlaneTooLarge: return "base plane too large";
    case ErrorCode::CutFalloffNegative: return "cut-plane falloff negative";
    case ErrorCode::PixelOutOfImage: return "pixel outside the base plane";
    case ErrorCode::BackendFailure: return "backend failure";
    case ErrorCode::SlabOutOfVolume: return "slab outside its subvolume";
    case ErrorCode::VoxelMemoryFull: return "voxel memory full";
    case ErrorCode::PolygonSize: return "polygon images not the frame's size";
    case ErrorCode::PolygonImage: return "malformed slab image";
  }
  return "unknown";
}

// "MODE (0x140)", "CLASS[17].a (0x100088)": for error messages.
std::string describe_address(uint64_t a);

// The register-space tables of docs/registers.md, in Markdown.
std::string register_doc();

}  // namespace cube4::sysc::regmap
