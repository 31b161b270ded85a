// cube4_pkg: what the units share, declared once.
//
// Default widths: each equals the golden default of the same name
// (golden::Precision{}, docs/fixed-point.md); every unit's parameter of
// that name defaults to the value here, and the RTL tests check the two
// against each other (RtlPackage.DefaultsAreGoldens, tb/rtl/test_pkg.cpp),
// so a width changes in two places that a test ties together, never in
// fifteen. The /*verilator public*/ marks make the values visible to C++
// (V<model>_cube4_pkg::<Name>).
//
// Shared arithmetic is modules, not package functions: yosys 0.23 has no
// parameterised functions, so a package function would be of one fixed
// width; cube4_lerp and cube4_mul_frac take their widths as parameters and
// are instantiated wherever the operation occurs.
//
// Every unit that uses the package includes it (guarded, so a file list
// that also names it reads it once): a unit file then lints and
// synthesises alone, with rtl/ on the include path.
//
// Frame registers stay one port per field: a packed struct port would reach
// C++ as one flat vector (Verilator 5.006 exports no field layout), so the
// C++ binding would have to restate the struct's layout, the second copy
// this package exists to avoid.
`ifndef CUBE4_PKG_SV
`define CUBE4_PKG_SV

package cube4_pkg;

  // Waiver: each unit uses only some of these constants, and Verilator
  // reports the rest as unused in every model that reads the package.
  /* verilator lint_off UNUSEDPARAM */

  // golden::Precision defaults.
  localparam int unsigned VoxelBits      /*verilator public*/ = 12;
  localparam int unsigned WeightBits     /*verilator public*/ = 8;
  localparam int unsigned GradientBits   /*verilator public*/ = 8;
  localparam int unsigned GradientShift  /*verilator public*/ = 5;
  localparam int unsigned MagnitudeBits  /*verilator public*/ = 8;
  localparam int unsigned NrIterations   /*verilator public*/ = 3;
  localparam int unsigned ColorBits      /*verilator public*/ = 8;
  localparam int unsigned AlphaBits      /*verilator public*/ = 16;
  localparam int unsigned GmlutBits      /*verilator public*/ = 8;
  localparam int unsigned MapFaceRes     /*verilator public*/ = 8;
  localparam int unsigned MapBits        /*verilator public*/ = 16;
  localparam int unsigned MapFracBits    /*verilator public*/ = 8;
  localparam int unsigned CoefBits       /*verilator public*/ = 10;
  localparam int unsigned CoefFracBits   /*verilator public*/ = 8;
  localparam int unsigned EyeBits        /*verilator public*/ = 8;
  localparam int unsigned CutBits        /*verilator public*/ = 32;
  localparam int unsigned AccGuardBits   /*verilator public*/ = 8;
  localparam int unsigned VoxelTagBits   /*verilator public*/ = 0;    // bela's voxel tags: none
  localparam int unsigned FracBits       /*verilator public*/ = 20;   // dda_frac_bits: the weight generator's fraction

  // Hardware choices without a golden counterpart (docs/registers.md gives
  // the register widths they set).
  localparam int unsigned NumPipes          /*verilator public*/ = 4;    // p, as VolumePro
  localparam int unsigned MaxDim            /*verilator public*/ = 256;  // ring storage per axis
  localparam int unsigned DimBits           /*verilator public*/ = 10;   // address generator's dims
  localparam int unsigned SupersamplingBits /*verilator public*/ = 4;    // S up to 15
  localparam int unsigned PosBits           /*verilator public*/ = 16;   // sample positions (crop, cut)
  localparam int unsigned CutCoefBits       /*verilator public*/ = 12;   // cut-plane a, b, c
  localparam int unsigned CutInvShift       /*verilator public*/ = 24;   // cut-plane 1/falloff fraction
  localparam int unsigned DivBitsPerStage   /*verilator public*/ = 2;    // quotient bits per divider stage

  // Polygons (Cube-5; golden/units/composite_polygon.hpp, rle_decode.hpp):
  // fixed by golden's formats, not by Precision.
  localparam int unsigned ZBits             /*verilator public*/ = 24;   // kZBits: a ray's depth
  localparam int unsigned ZFracBits         /*verilator public*/ = 8;    // kZFracBits: its fraction
  localparam int unsigned SliceBits         /*verilator public*/ = 16;   // sample slice k: k << ZFracBits fits ZBits
  localparam int unsigned RleWordBits       /*verilator public*/ = 16;   // a slab line's word (and run length)

  // Blend modes: golden BlendMode and the BLEND register's values.
  typedef enum logic [1:0] {
    BlendComposite = 2'd0,
    BlendMip       = 2'd1,
    BlendMinIp     = 2'd2
  } blend_e;

  /* verilator lint_on UNUSEDPARAM */

endpackage

`endif  // CUBE4_PKG_SV
