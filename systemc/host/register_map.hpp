// The host interface's address map (docs/registers.md): one byte-addressed
// 64-bit address space of 32-bit registers and table windows. 64-bit values
// are two words, low word first, 8-byte aligned, so one 8-byte transaction
// moves a whole value. Signed values are two's complement in 32 (or 64) bits.
#pragma once
#include <cstdint>
#include <string>

#include "golden/registers.hpp"

namespace cube4::sysc::regmap {

// ---- Control and status (0x000-0x03F) --------------------------------------
constexpr uint64_t kCtrl = 0x000;            // W: kCtrl* bits; reads 0
constexpr uint64_t kStatus = 0x004;          // R: kStatus* bits
constexpr uint64_t kLastError = 0x008;       // R: ErrorCode of the latest error
constexpr uint64_t kErrorAddrLo = 0x010;     // R: address of the word at fault
constexpr uint64_t kErrorAddrHi = 0x014;
constexpr uint64_t kFrameCountLo = 0x018;    // R: frames completed by the backend
constexpr uint64_t kFrameCountHi = 0x01C;
constexpr uint64_t kCyclesLo = 0x020;        // R: clock cycles of the last frame
constexpr uint64_t kCyclesHi = 0x024;
constexpr uint64_t kBaseWidth = 0x028;       // R: base plane of the last frame
constexpr uint64_t kBaseHeight = 0x02C;

constexpr uint32_t kCtrlStart = 1u << 0;
constexpr uint32_t kCtrlReset = 1u << 1;       // register file, error state and DONE
constexpr uint32_t kCtrlClearError = 1u << 2;
constexpr uint32_t kCtrlMask = 0x7;

constexpr uint32_t kStatusBusy = 1u << 0;
constexpr uint32_t kStatusDone = 1u << 1;      // the frame started last has completed
constexpr uint32_t kStatusError = 1u << 2;     // sticky until CLEAR_ERROR or RESET

// ---- Identification (0x040-0x07F), read-only ------------------------------
constexpr uint64_t kIdMagic = 0x040;
constexpr uint64_t kIdVersion = 0x044;
constexpr uint64_t kIdPipelines = 0x048;
constexpr uint64_t kIdMaxDim = 0x04C;
constexpr uint64_t kIdVoxelBits = 0x050;
constexpr uint64_t kIdClassEntries = 0x054;
constexpr uint64_t kIdGmLutEntries = 0x058;
constexpr uint64_t kIdMapEntries = 0x05C;     // per map: 6 faces * res^2
constexpr uint64_t kIdBaseMax = 0x060;        // largest base-plane width and height

constexpr uint32_t kMagic = 0x43554234;       // "CUB4"
constexpr uint32_t kVersion = 0x00010000;     // 1.0

// ---- Precision (0x080-0x0C7), read-only: one word per golden::Precision
// field, in the struct's order (voxel_bits first, acc_guard_bits last).
constexpr uint64_t kPrecision = 0x080;
constexpr int kPrecisionFields = 18;

// ---- View and DDA (0x100-0x137) -------------------------------------------
constexpr uint64_t kDimX = 0x100;             // permuted dims, 1..max_dim
constexpr uint64_t kDimY = 0x104;
constexpr uint64_t kDimZ = 0x108;
constexpr uint64_t kPerm = 0x10C;             // perm[i] in bits 2i+1:2i
constexpr uint64_t kFlip = 0x110;             // flip[i] in bit i
constexpr uint64_t kSupersampling = 0x114;    // 1..8
constexpr uint64_t kXStartLo = 0x118;         // int64, dda_frac_bits fraction
constexpr uint64_t kXStartHi = 0x11C;
constexpr uint64_t kXStepLo = 0x120;
constexpr uint64_t kXStepHi = 0x124;
constexpr uint64_t kYStartLo = 0x128;
constexpr uint64_t kYStartHi = 0x12C;
constexpr uint64_t kYStepLo = 0x130;
constexpr uint64_t kYStepHi = 0x134;

// ---- Mode (0x140) ------------------------------------------------------------
constexpr uint64_t kMode = 0x140;
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
constexpr uint32_t kModeMask = 0x7F | kModeBlendMask | kModeCrop | kModeCut;

// ---- Cropping (0x180-0x19B) --------------------------------------------------
constexpr uint64_t kCropSlab = 0x180;         // int32 x lo, x hi, y lo, y hi, z lo, z hi
constexpr uint64_t kCropMask = 0x198;         // 8 bits

// ---- Cut plane (0x1C0-0x1EF) -------------------------------------------------
constexpr uint64_t kCutA = 0x1C0;             // int32
constexpr uint64_t kCutB = 0x1C4;
constexpr uint64_t kCutC = 0x1C8;
constexpr uint64_t kCutFlags = 0x1CC;         // bit 0: keep_inside
constexpr uint64_t kCutDminLo = 0x1D0;        // int64
constexpr uint64_t kCutDminHi = 0x1D4;
constexpr uint64_t kCutDmaxLo = 0x1D8;        // int64
constexpr uint64_t kCutDmaxHi = 0x1DC;
constexpr uint64_t kCutFalloffLo = 0x1E0;     // int64, >= 0 at START
constexpr uint64_t kCutFalloffHi = 0x1E4;
constexpr uint64_t kCutInvFalloffLo = 0x1E8;  // uint64
constexpr uint64_t kCutInvFalloffHi = 0x1EC;
constexpr uint32_t kCutKeepInside = 1u << 0;

// ---- Shading (0x200-0x223) ---------------------------------------------------
constexpr uint64_t kKe = 0x200;               // coef_bits
constexpr uint64_t kKd = 0x204;
constexpr uint64_t kKs = 0x208;
constexpr uint64_t kSpecularColor = 0x20C;    // r, g, b: alpha_bits each
constexpr uint64_t kEye = 0x218;              // x, y, z: int32, |e| <= 2^(eye_bits-1)-1

// ---- Volume (0x240-0x24B) ----------------------------------------------------
constexpr uint64_t kVolDim = 0x240;           // object-order nx, ny, nz, 1..max_dim

constexpr uint64_t kRegisterSpace = 0x1000;   // everything above is a window

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
constexpr uint64_t kBaseBase = 0x0800'0000;    // 8 bytes per pixel: {r|g<<16, b|a<<16}, row-major
constexpr uint64_t kBaseSize = 0x0800'0000;
constexpr uint64_t kVolumeBase = 0x1'0000'0000;  // two voxels per word, x fastest
constexpr uint64_t kVolumeSize = 0x1'0000'0000;

constexpr int kMaxDimLimit = 1024;   // volume window: 2 bytes * 1024^3 = 2 GiB
constexpr int kMaxPipelines = 256;
constexpr int kMaxSupersampling = 8;

enum class Region { None, Registers, Class, GmLut, Diffuse, Specular, Base, Volume };

constexpr Region region_of(uint64_t a) {
  if (a < kRegisterSpace) return Region::Registers;
  if (a >= kClassBase && a - kClassBase < kClassSize) return Region::Class;
  if (a >= kGmLutBase && a - kGmLutBase < kGmLutSize) return Region::GmLut;
  if (a >= kDiffuseBase && a - kDiffuseBase < kMapSize) return Region::Diffuse;
  if (a >= kSpecularBase && a - kSpecularBase < kMapSize) return Region::Specular;
  if (a >= kBaseBase && a - kBaseBase < kBaseSize) return Region::Base;
  if (a >= kVolumeBase && a - kVolumeBase < kVolumeSize) return Region::Volume;
  return Region::None;
}

// LAST_ERROR codes. Every error response sets STATUS.ERROR and records one.
enum class ErrorCode : uint32_t {
  None = 0,
  Unmapped = 1,           // ADDRESS_ERROR: no register or window entry there
  Alignment = 2,          // BURST_ERROR: address or length not a multiple of 4, or no data
  Streaming = 3,          // BURST_ERROR: streaming width below the data length
  ByteEnable = 4,         // BYTE_ENABLE_ERROR: byte enables are not supported
  ReadOnly = 5,           // COMMAND_ERROR: write to a read-only register or window
  WriteOnly = 6,          // COMMAND_ERROR: read of the volume window
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
  }
  return "unknown";
}

// "MODE (0x140)", "CLASS[17].a (0x100088)": for error messages.
std::string describe_address(uint64_t a);

// The MODE register's word for the registers' mode bits (the one encoder:
// the host writes it, the register file reads it back).
uint32_t mode_word(const golden::Registers& r);

}  // namespace cube4::sysc::regmap
