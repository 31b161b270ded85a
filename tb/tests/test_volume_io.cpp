// Volume loaders, quantisation and synthetic volumes (docs/volumes.md).
// Expected values are computed here from the documented formula or from the
// file's bytes read independently, never from the loaders under test.
#include <gtest/gtest.h>
#include <unistd.h>
#include <zlib.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <random>
#include <string>
#include <vector>

// niftilib's header needs its own folder on the include path (it includes
// <znzlib.h>); without it the test writes NIfTI files by hand with the
// standard header struct.
#if __has_include(<nifti1_io.h>)
#include <nifti1_io.h>
#define CUBE4_TEST_NIFTILIB 1
#else
#include <nifti/nifti1.h>
#define CUBE4_TEST_NIFTILIB 0
#endif

#include "golden/errors.hpp"
#include "golden/quantise.hpp"
#include "golden/volume_io.hpp"

namespace fs = std::filesystem;
using namespace cube4::golden;

namespace {

// ---------------------------------------------------------------- helpers

class TempDir {
 public:
  TempDir() {
    static std::atomic<int> counter{0};
    std::random_device rd;
    path_ = fs::temp_directory_path() / ("cube4_volio_" + std::to_string(::getpid()) + "_" +
                                         std::to_string(counter++) + "_" + std::to_string(rd()));
    fs::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  std::string file(const std::string& name) const { return (path_ / name).string(); }
  std::string dir() const { return path_.string(); }

 private:
  fs::path path_;
};

using Bytes = std::vector<unsigned char>;

Bytes read_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return Bytes(std::istreambuf_iterator<char>(in), {});
}

void write_bytes(const std::string& path, const Bytes& b) {
  std::ofstream out(path, std::ios::binary);
  out.write(reinterpret_cast<const char*>(b.data()), static_cast<std::streamsize>(b.size()));
}

void write_gz(const std::string& path, const Bytes& b) {
  gzFile f = gzopen(path.c_str(), "wb");
  ASSERT_NE(f, nullptr);
  gzwrite(f, b.data(), static_cast<unsigned>(b.size()));
  gzclose(f);
}

void truncate_file(const std::string& path, size_t keep) {
  Bytes b = read_bytes(path);
  ASSERT_LT(keep, b.size());
  b.resize(keep);
  write_bytes(path, b);
}

// The message of the InputError f throws ("" and a test failure if none).
template <class F>
std::string input_error(F f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  } catch (const std::exception& e) {
    ADD_FAILURE() << "expected InputError, got another exception: " << e.what();
    return "";
  }
  ADD_FAILURE() << "expected InputError, nothing thrown";
  return "";
}

#define EXPECT_MSG_HAS(msg, text) \
  EXPECT_NE((msg).find(text), std::string::npos) << "message: " << (msg) << "\nlacks: " << (text)

// The documented mapping, written out independently of quantise.cpp.
uint16_t expected_q(double v, double lo, double hi, int bits) {
  const double maxv = std::pow(2.0, bits) - 1;
  if (hi == lo) return 0;
  const double x = std::floor((v - lo) * maxv / (hi - lo) + 0.5);
  return static_cast<uint16_t>(std::clamp(x, 0.0, maxv));
}

Quantisation full() { return {}; }
Quantisation minmax() {
  Quantisation q;
  q.mode = Quantisation::Mode::MinMax;
  return q;
}
Quantisation window(double lo, double hi) {
  Quantisation q;
  q.mode = Quantisation::Mode::Window;
  q.lo = lo;
  q.hi = hi;
  return q;
}

// A .den file as denfile.c's write_den makes it, in either byte order.
Bytes make_den(int nx, int ny, int nz, const Bytes& data, bool big_endian = false,
               int map_length = -1) {
  Bytes b;
  auto put16 = [&](int v) {
    const unsigned u = static_cast<uint16_t>(v);
    if (big_endian)
      b.insert(b.end(), {static_cast<unsigned char>(u >> 8), static_cast<unsigned char>(u)});
    else
      b.insert(b.end(), {static_cast<unsigned char>(u), static_cast<unsigned char>(u >> 8)});
  };
  put16(1);
  for (int block = 0; block < 3; ++block) {  // orig, extr, map: min, max, len
    put16(0), put16(0), put16(0);
    put16(nx - 1), put16(ny - 1), put16(nz - 1);
    put16(nx), put16(ny), put16(nz);
  }
  put16(0);  // warps
  const uint32_t len = static_cast<uint32_t>(map_length >= 0 ? map_length : nx * ny * nz);
  for (int i = 0; i < 4; ++i)
    b.push_back(static_cast<unsigned char>(len >> (big_endian ? 24 - 8 * i : 8 * i)));
  EXPECT_EQ(b.size(), 62u);
  b.insert(b.end(), data.begin(), data.end());
  return b;
}

template <class T>
Bytes encode(const std::vector<T>& values, bool big_endian, size_t header) {
  Bytes b(header, 0xab);
  for (T v : values) {
    unsigned char s[sizeof(T)];
    std::memcpy(s, &v, sizeof(T));
    if (big_endian) std::reverse(s, s + sizeof(T));  // the test host is little-endian
    b.insert(b.end(), s, s + sizeof(T));
  }
  return b;
}

VolumeSource raw_source(const std::string& type, const std::string& endian, std::array<int, 3> dim,
                        uint64_t header = 0) {
  VolumeSource s;
  s.kind = "raw";
  s.type = type;
  s.endian = endian;
  s.dim = dim;
  s.header_bytes = header;
  return s;
}

// ---------------------------------------------------------------- NIfTI writer

struct NiftiSpec {
  std::vector<int> dims;  // nx, ny, nz[, nt]
  int datatype = DT_INT16;
  int bitpix = 16;
  Bytes data;
  std::array<float, 3> pixdim{1, 1, 1};
  float slope = 0, inter = 0;
};

template <class T>
void swap_field(T& v) {
  unsigned char b[sizeof(T)];
  std::memcpy(b, &v, sizeof(T));
  std::reverse(b, b + sizeof(T));
  std::memcpy(&v, b, sizeof(T));
}

// The NIfTI-1 layout written field by field: lets a test make files niftilib
// would not write, such as big-endian ones.
void write_nifti_by_hand(const std::string& path, const NiftiSpec& s, bool big_endian) {
  nifti_1_header h{};
  h.sizeof_hdr = 348;
  h.dim[0] = static_cast<short>(s.dims.size());
  for (int i = 1; i < 8; ++i) h.dim[i] = 1;
  for (size_t i = 0; i < s.dims.size(); ++i) h.dim[i + 1] = static_cast<short>(s.dims[i]);
  h.datatype = static_cast<short>(s.datatype);
  h.bitpix = static_cast<short>(s.bitpix);
  h.pixdim[0] = 1;
  for (int i = 0; i < 3; ++i) h.pixdim[i + 1] = s.pixdim[i];
  h.vox_offset = 352;
  h.scl_slope = s.slope;
  h.scl_inter = s.inter;
  std::memcpy(h.magic, "n+1", 4);
  Bytes data = s.data;
  if (big_endian) {  // the test host is little-endian
    swap_field(h.sizeof_hdr);
    for (auto& d : h.dim) swap_field(d);
    swap_field(h.datatype);
    swap_field(h.bitpix);
    for (auto& p : h.pixdim) swap_field(p);
    swap_field(h.vox_offset);
    swap_field(h.scl_slope);
    swap_field(h.scl_inter);
    const size_t w = static_cast<size_t>(s.bitpix) / 8;
    for (size_t i = 0; w > 1 && i + w <= data.size(); i += w)
      std::reverse(data.begin() + i, data.begin() + i + w);
  }
  Bytes b(sizeof h + 4, 0);  // header, then an empty extension flag
  std::memcpy(b.data(), &h, sizeof h);
  b.insert(b.end(), data.begin(), data.end());
  const bool gz = path.size() > 3 && path.compare(path.size() - 3, 3, ".gz") == 0;
  if (gz)
    write_gz(path, b);
  else
    write_bytes(path, b);
}

#if CUBE4_TEST_NIFTILIB
void write_nifti(const std::string& path, const NiftiSpec& s) {
  int dims[8] = {static_cast<int>(s.dims.size()), 1, 1, 1, 1, 1, 1, 1};
  for (size_t i = 0; i < s.dims.size(); ++i) dims[i + 1] = s.dims[i];
  std::unique_ptr<nifti_image, void (*)(nifti_image*)> nim(nifti_make_new_nim(dims, s.datatype, 1),
                                                           nifti_image_free);
  ASSERT_TRUE(nim);
  ASSERT_EQ(nim->nvox * nim->nbyper, s.data.size());
  std::memcpy(nim->data, s.data.data(), s.data.size());
  nim->pixdim[1] = nim->dx = s.pixdim[0];
  nim->pixdim[2] = nim->dy = s.pixdim[1];
  nim->pixdim[3] = nim->dz = s.pixdim[2];
  nim->scl_slope = s.slope;
  nim->scl_inter = s.inter;
  ASSERT_EQ(nifti_set_filenames(nim.get(), path.c_str(), 0, 1), 0);
  nifti_image_write(nim.get());
}
#else
void write_nifti(const std::string& path, const NiftiSpec& s) {
  write_nifti_by_hand(path, s, false);
}
#endif

NiftiSpec int16_spec() {
  NiftiSpec s;
  s.dims = {4, 3, 2};
  std::vector<int16_t> v;
  for (int i = 0; i < 24; ++i) v.push_back(static_cast<int16_t>(i * 1000 - 12000));
  s.data = encode(v, false, 0);
  s.pixdim = {0.5f, -2.0f, 0.0f};  // sign dropped, 0 read as 1
  return s;
}

// ---------------------------------------------------------------- brainsmall

TEST(Den, BrainsmallLoadsAs12BitWithDocumentedMapping) {
  const Bytes file = read_bytes(CUBE4_BRAINSMALL);
  ASSERT_EQ(file.size(), 62u + 128 * 128 * 84);
  const Volume v = load_den(CUBE4_BRAINSMALL, full(), 12);
  EXPECT_EQ(v.dim, (std::array<int, 3>{128, 128, 84}));
  EXPECT_EQ(v.bits, 12);
  EXPECT_EQ(v.spacing, (std::array<double, 3>{1, 1, 1}));
  ASSERT_EQ(v.data.size(), 128u * 128 * 84);
  // A few hand-picked voxels, then all of them.
  for (auto [x, y, z] : {std::array<int, 3>{0, 0, 0}, {64, 64, 42}, {127, 127, 83}, {70, 50, 30}}) {
    const unsigned b = file[62 + v.index(x, y, z)];
    EXPECT_EQ(v.at(x, y, z), (2 * b * 4095 + 255) / 510) << x << "," << y << "," << z;
  }
  unsigned max_byte = 0;
  for (size_t i = 0; i < v.data.size(); ++i) {
    const unsigned b = file[62 + i];
    max_byte = std::max(max_byte, b);
    ASSERT_EQ(v.data[i], expected_q(b, 0, 255, 12)) << "voxel " << i;
  }
  const uint16_t vmax = *std::max_element(v.data.begin(), v.data.end());
  EXPECT_EQ(vmax == 4095, max_byte == 255);
  EXPECT_EQ(vmax, expected_q(max_byte, 0, 255, 12));
}

// How fast it loads is bench_golden's `volume_load_ms` (docs/volumes.md),
// not a test's: wall-clock limits fail on a loaded machine.
TEST(Den, BrainsmallLoadsTheSameVoxelsEveryTime) {
  const Volume a = load_den(CUBE4_BRAINSMALL, full(), 12);
  const Volume b = load_den(CUBE4_BRAINSMALL, full(), 12);
  EXPECT_EQ(a.dim, (std::array<int, 3>{128, 128, 84}));
  EXPECT_EQ(a.data, b.data);
}

TEST(Den, DefaultPathAndLoadVolumeResolveRelativePaths) {
  EXPECT_EQ(default_brainsmall_path(), std::string(CUBE4_BRAINSMALL));
  VolumeSource s;
  s.kind = "den";
  s.path = fs::path(CUBE4_BRAINSMALL).filename().string();
  s.spacing = Vec3{1, 1, 1.5};
  const Volume v = load_volume(s, 10, fs::path(CUBE4_BRAINSMALL).parent_path().string());
  EXPECT_EQ(v.dim, (std::array<int, 3>{128, 128, 84}));
  EXPECT_EQ(v.bits, 10);
  EXPECT_EQ(v.spacing, (std::array<double, 3>{1, 1, 1.5}));
  EXPECT_LE(*std::max_element(v.data.begin(), v.data.end()), 1023);
}

TEST(Den, TruncatedDataNamesFileAndTruncated) {
  TempDir t;
  const std::string p = t.file("brain_cut.den");
  Bytes b = read_bytes(CUBE4_BRAINSMALL);
  b.resize(62 + 1000);
  write_bytes(p, b);
  const std::string m = input_error([&] { load_den(p, full(), 12); });
  EXPECT_MSG_HAS(m, "brain_cut.den");
  EXPECT_MSG_HAS(m, "truncated");
  EXPECT_MSG_HAS(m, "1376256");
  EXPECT_MSG_HAS(m, "1000");
}

TEST(Den, TruncatedHeader) {
  TempDir t;
  const std::string p = t.file("short.den");
  Bytes b = read_bytes(CUBE4_BRAINSMALL);
  b.resize(30);
  write_bytes(p, b);
  const std::string m = input_error([&] { load_den(p, full(), 12); });
  EXPECT_MSG_HAS(m, "short.den");
  EXPECT_MSG_HAS(m, "truncated header");
}

TEST(Den, BadMagicShowsValue) {
  TempDir t;
  const std::string p = t.file("magic.den");
  Bytes b = make_den(2, 2, 2, Bytes(8, 7));
  b[0] = 0x34, b[1] = 0x12;
  write_bytes(p, b);
  const std::string m = input_error([&] { load_den(p, full(), 12); });
  EXPECT_MSG_HAS(m, "magic.den");
  EXPECT_MSG_HAS(m, "not a VolPack density file");
  EXPECT_MSG_HAS(m, "0x1234");
}

TEST(Den, InconsistentHeaderAndNonpositiveDims) {
  TempDir t;
  const std::string p = t.file("bad.den");
  write_bytes(p, make_den(2, 2, 2, Bytes(8, 7), false, 9));
  std::string m = input_error([&] { load_den(p, full(), 12); });
  EXPECT_MSG_HAS(m, "bad.den");
  EXPECT_MSG_HAS(m, "inconsistent header");
  write_bytes(p, make_den(0, 2, 2, {}, false, 0));
  m = input_error([&] { load_den(p, full(), 12); });
  EXPECT_MSG_HAS(m, "nonpositive dimensions 0x2x2");
}

TEST(Den, MissingFile) {
  TempDir t;
  const std::string m = input_error([&] { load_den(t.file("nothing.den"), full(), 12); });
  EXPECT_MSG_HAS(m, "nothing.den");
  EXPECT_MSG_HAS(m, "cannot open");
}

TEST(Den, ByteSwappedAndGzippedFiles) {
  TempDir t;
  const Bytes data{0, 1, 2, 3, 250, 251, 254, 255, 9, 10, 11, 12};
  for (bool big : {false, true}) {
    const std::string p = t.file(big ? "big.den" : "little.den");
    write_bytes(p, make_den(3, 2, 2, data, big));
    const Volume v = load_den(p, full(), 8);
    EXPECT_EQ(v.dim, (std::array<int, 3>{3, 2, 2}));
    EXPECT_EQ(v.data, std::vector<uint16_t>(data.begin(), data.end())) << p;
  }
  const std::string gz = t.file("small.den.gz");
  write_gz(gz, make_den(3, 2, 2, data));
  EXPECT_EQ(load_den(gz, full(), 8).data, std::vector<uint16_t>(data.begin(), data.end()));

  // A cut gzip stream must be an InputError, not a short volume.
  const std::string cut = t.file("brain_cut.den.gz");
  write_gz(cut, read_bytes(CUBE4_BRAINSMALL));
  truncate_file(cut, fs::file_size(cut) / 2);
  const std::string m = input_error([&] { load_den(cut, full(), 12); });
  EXPECT_MSG_HAS(m, "brain_cut.den.gz");
  EXPECT_MSG_HAS(m, "truncated");
}

// ---------------------------------------------------------------- raw

template <class T>
void raw_round_trip(const std::string& type, const std::vector<T>& values, double lo, double hi,
                    const Quantisation& q = {}) {
  TempDir t;
  for (const std::string endian : {"little", "big"}) {
    for (uint64_t header : {0, 13}) {
      const std::string p = t.file(type + "_" + endian + ".raw");
      write_bytes(p, encode(values, endian == "big", header));
      VolumeSource s = raw_source(type, endian, {3, 2, 2}, header);
      s.quantisation = q;
      const Volume v = load_raw(s, p, 12);
      ASSERT_EQ(v.dim, (std::array<int, 3>{3, 2, 2}));
      ASSERT_EQ(v.data.size(), values.size());
      for (size_t i = 0; i < values.size(); ++i)
        EXPECT_EQ(v.data[i], expected_q(static_cast<double>(values[i]), lo, hi, 12))
            << type << " " << endian << " header " << header << " voxel " << i;
    }
  }
}

TEST(Raw, RoundTripEveryTypeAndEndianness) {
  raw_round_trip<uint8_t>("uint8", {0, 1, 2, 50, 100, 127, 128, 200, 253, 254, 255, 7}, 0, 255);
  raw_round_trip<uint16_t>("uint12", {0, 1, 4095, 2048, 100, 4000, 17, 3, 4094, 5, 6, 2047}, 0,
                           4095);
  raw_round_trip<uint16_t>("uint16", {0, 65535, 256, 1, 30000, 40000, 2, 3, 4, 5, 6, 65534}, 0,
                           65535);
  raw_round_trip<int16_t>("int16", {-32768, 32767, 0, -1, 1, 1000, -1000, 2, 3, 4, 5, 6}, -32768,
                          32767);
  raw_round_trip<uint32_t>("uint32", {0, 4294967295u, 1u << 31, 1, 2, 3, 4, 5, 6, 7, 8, 9}, 0,
                           4294967295.0);
  raw_round_trip<int32_t>("int32", {INT32_MIN, INT32_MAX, 0, -1, 1, 2, 3, 4, 5, 6, 7, 8},
                          -2147483648.0, 2147483647.0);
  // Floats have no type range: Full means MinMax.
  raw_round_trip<float>("float32", {-1.5f, 0, 0.25f, 2.5f, 1, 1, 1, 1, 1, 1, 1, 1}, -1.5, 2.5);
  raw_round_trip<double>("float64", {10, 20, 30, 40, 15, 25, 35, 12, 11, 13, 14, 16}, 10, 40);
  raw_round_trip<int16_t>("int16", {-200, 0, 100, 200, 300, 5, 6, 7, 8, 9, 10, 11}, 0, 255,
                          window(0, 255));
}

TEST(Raw, SizeMismatchNamesExpectedAndActual) {
  TempDir t;
  const std::string p = t.file("vol.raw");
  const VolumeSource s = raw_source("uint16", "little", {4, 4, 4}, 10);  // 10 + 128 bytes
  write_bytes(p, Bytes(137, 0));
  std::string m = input_error([&] { load_raw(s, p, 12); });
  EXPECT_MSG_HAS(m, "vol.raw");
  EXPECT_MSG_HAS(m, "137");
  EXPECT_MSG_HAS(m, "138");
  write_bytes(p, Bytes(139, 0));  // too large is wrong too
  m = input_error([&] { load_raw(s, p, 12); });
  EXPECT_MSG_HAS(m, "139");
  EXPECT_MSG_HAS(m, "138");
  write_bytes(p, Bytes(138, 0));
  EXPECT_NO_THROW(load_raw(s, p, 12));
}

TEST(Raw, Uint12OutOfRangeNamesFirstVoxel) {
  TempDir t;
  const std::string p = t.file("ct.raw");
  std::vector<uint16_t> v(12, 100);
  v[7] = 5000;
  v[9] = 4096;
  write_bytes(p, encode(v, false, 0));
  const std::string m = input_error([&] {
    load_raw(raw_source("uint12", "little", {3, 2, 2}), p, 12);
  });
  EXPECT_MSG_HAS(m, "ct.raw");
  EXPECT_MSG_HAS(m, "voxel 7");
  EXPECT_MSG_HAS(m, "5000");
}

TEST(Raw, NonFiniteFloatNamesVoxel) {
  TempDir t;
  const std::string p = t.file("f.raw");
  std::vector<float> v(12, 1.0f);
  v[3] = std::nanf("");
  write_bytes(p, encode(v, false, 0));
  std::string m = input_error([&] { load_raw(raw_source("float32", "little", {3, 2, 2}), p, 12); });
  EXPECT_MSG_HAS(m, "f.raw");
  EXPECT_MSG_HAS(m, "voxel 3");
  EXPECT_MSG_HAS(m, "NaN");
  std::vector<double> d(12, 1.0);
  d[11] = -INFINITY;
  write_bytes(p, encode(d, true, 0));
  m = input_error([&] { load_raw(raw_source("float64", "big", {3, 2, 2}), p, 12); });
  EXPECT_MSG_HAS(m, "voxel 11");
  EXPECT_MSG_HAS(m, "infinite");
}

TEST(Raw, BadTypeEndianAndDims) {
  TempDir t;
  const std::string p = t.file("x.raw");
  write_bytes(p, Bytes(8, 0));
  std::string m = input_error([&] { load_raw(raw_source("int8x", "little", {2, 2, 2}), p, 12); });
  EXPECT_MSG_HAS(m, "volume.type");
  EXPECT_MSG_HAS(m, "int8x");
  m = input_error([&] { load_raw(raw_source("uint8", "middle", {2, 2, 2}), p, 12); });
  EXPECT_MSG_HAS(m, "volume.endian");
  EXPECT_MSG_HAS(m, "middle");
  m = input_error([&] { load_raw(raw_source("uint8", "little", {2, 0, 2}), p, 12); });
  EXPECT_MSG_HAS(m, "volume.dim");
  m = input_error([&] {
    load_raw(raw_source("uint8", "little", {2, 2, 2}), t.file("none.raw"), 12);
  });
  EXPECT_MSG_HAS(m, "none.raw");
  EXPECT_MSG_HAS(m, "cannot open");
}

TEST(Raw, LoadVolumeResolvesAgainstSceneDir) {
  TempDir t;
  write_bytes(t.file("v.raw"), Bytes{0, 255, 128, 64, 1, 2, 3, 4});
  VolumeSource s = raw_source("uint8", "little", {2, 2, 2});
  s.path = "v.raw";
  const Volume v = load_volume(s, 8, t.dir());
  EXPECT_EQ(v.data, (std::vector<uint16_t>{0, 255, 128, 64, 1, 2, 3, 4}));
  EXPECT_EQ(v.source, t.file("v.raw"));
  s.path = "";
  EXPECT_MSG_HAS(input_error([&] { load_volume(s, 8, t.dir()); }), "volume.file");
}

// ---------------------------------------------------------------- NIfTI

TEST(Nifti, NiiAndNiiGzRoundTripWithSpacing) {
  TempDir t;
  const NiftiSpec spec = int16_spec();
  for (const std::string name : {"head.nii", "head.nii.gz"}) {
    const std::string p = t.file(name);
    write_nifti(p, spec);
    ASSERT_TRUE(fs::exists(p)) << p;
    const Volume v = load_nifti(p, full(), 12);
    EXPECT_EQ(v.dim, (std::array<int, 3>{4, 3, 2}));
    EXPECT_EQ(v.spacing, (std::array<double, 3>{0.5, 2.0, 1.0}));
    ASSERT_EQ(v.data.size(), 24u);
    for (int i = 0; i < 24; ++i)
      EXPECT_EQ(v.data[i], expected_q(i * 1000 - 12000, -32768, 32767, 12)) << name << " " << i;
    const Volume mm = load_nifti(p, minmax(), 12);
    EXPECT_EQ(mm.data.front(), 0);
    EXPECT_EQ(mm.data.back(), 4095);
  }
}

TEST(Nifti, BigEndianFilesAreSwapped) {
  TempDir t;
  const NiftiSpec spec = int16_spec();
  for (const std::string name : {"be.nii", "be.nii.gz"}) {
    const std::string p = t.file(name);
    write_nifti_by_hand(p, spec, true);
    const Volume v = load_nifti(p, full(), 12);
    EXPECT_EQ(v.dim, (std::array<int, 3>{4, 3, 2}));
    EXPECT_EQ(v.spacing, (std::array<double, 3>{0.5, 2.0, 1.0}));
    ASSERT_EQ(v.data.size(), 24u);
    for (int i = 0; i < 24; ++i)
      EXPECT_EQ(v.data[i], expected_q(i * 1000 - 12000, -32768, 32767, 12)) << name << " " << i;
  }
}

TEST(Nifti, SlopeAndInterceptApplyBeforeQuantising) {
  TempDir t;
  NiftiSpec s;
  s.dims = {2, 2, 1};
  s.datatype = DT_UINT8;
  s.bitpix = 8;
  s.data = {0, 100, 200, 255};
  s.slope = 2;
  s.inter = 10;  // stored v means 2v + 10
  const std::string p = t.file("scaled.nii");
  write_nifti(p, s);
  Volume v = load_nifti(p, window(0, 1000), 12);
  EXPECT_EQ(v.data,
            (std::vector<uint16_t>{expected_q(10, 0, 1000, 12), expected_q(210, 0, 1000, 12),
                                   expected_q(410, 0, 1000, 12), expected_q(520, 0, 1000, 12)}));
  EXPECT_EQ(v.data[1], 860);  // 210 * 4095 / 1000 = 859.95
  // Full is the scaled type range 10..520, so the mapping matches unscaled uint8.
  v = load_nifti(p, full(), 12);
  EXPECT_EQ(v.data, (std::vector<uint16_t>{0, expected_q(100, 0, 255, 12),
                                           expected_q(200, 0, 255, 12), 4095}));
}

TEST(Nifti, Int8AndFloatSamples) {
  TempDir t;
  NiftiSpec s;
  s.dims = {2, 2, 1};
  s.datatype = DT_INT8;
  s.bitpix = 8;
  s.data = {0x80, 0x00, 0x01, 0x7f};  // -128, 0, 1, 127
  const std::string p = t.file("i8.nii");
  write_nifti(p, s);
  EXPECT_EQ(
      load_nifti(p, full(), 12).data,
      (std::vector<uint16_t>{0, expected_q(0, -128, 127, 12), expected_q(1, -128, 127, 12), 4095}));

  s.datatype = DT_FLOAT32;
  s.bitpix = 32;
  s.data = encode(std::vector<float>{0.5f, 1.5f, 2.5f, 4.5f}, false, 0);
  write_nifti(t.file("f.nii.gz"), s);
  EXPECT_EQ(load_nifti(t.file("f.nii.gz"), full(), 12).data,
            (std::vector<uint16_t>{0, 1024, 2048, 4095}));  // 1023.75, 2047.5 round up
  s.data = encode(std::vector<float>{0.5f, 1.5f, NAN, 4.5f}, false, 0);
  write_nifti(t.file("nan.nii"), s);
  const std::string m = input_error([&] { load_nifti(t.file("nan.nii"), full(), 12); });
  EXPECT_MSG_HAS(m, "nan.nii");
  EXPECT_MSG_HAS(m, "voxel 2");
}

TEST(Nifti, TruncatedFilesAreInputErrors) {
  TempDir t;
  NiftiSpec s = int16_spec();
  s.dims = {32, 32, 16};
  std::vector<int16_t> vals(32 * 32 * 16);
  std::mt19937 gen(3);
  for (auto& x : vals) x = static_cast<int16_t>(gen());  // incompressible
  s.data = encode(vals, false, 0);
  for (const std::string name : {"cut.nii.gz", "cut.nii"}) {
    const std::string p = t.file(name);
    write_nifti(p, s);
    truncate_file(p, fs::file_size(p) / 2);
    const std::string m = input_error([&] { load_nifti(p, full(), 12); });
    EXPECT_MSG_HAS(m, name);
  }
  const std::string p = t.file("header_only.nii.gz");
  write_nifti(p, s);
  truncate_file(p, 40);
  EXPECT_MSG_HAS(input_error([&] { load_nifti(p, full(), 12); }), "header_only.nii.gz");
  EXPECT_MSG_HAS(input_error([&] { load_nifti(t.file("missing.nii"), full(), 12); }),
                 "cannot open");
}

TEST(Nifti, FourDAndUnsupportedTypesRejected) {
  TempDir t;
  NiftiSpec s;
  s.dims = {2, 2, 2, 3};
  s.datatype = DT_UINT8;
  s.bitpix = 8;
  s.data = Bytes(24, 1);
  const std::string p = t.file("series.nii");
  write_nifti(p, s);
  std::string m = input_error([&] { load_nifti(p, full(), 12); });
  EXPECT_MSG_HAS(m, "series.nii");
  EXPECT_MSG_HAS(m, "3-D");

  s.dims = {2, 2, 2};
  s.datatype = DT_COMPLEX64;
  s.bitpix = 64;
  s.data = Bytes(64, 0);
  const std::string c = t.file("complex.nii");
  write_nifti(c, s);
  m = input_error([&] { load_nifti(c, full(), 12); });
  EXPECT_MSG_HAS(m, "complex.nii");
  EXPECT_MSG_HAS(m, "datatype");
  EXPECT_MSG_HAS(m, "COMPLEX64");
}

TEST(Nifti, LoadVolumeDispatch) {
  TempDir t;
  write_nifti(t.file("a.nii.gz"), int16_spec());
  VolumeSource s;
  s.kind = "nifti";
  s.path = "a.nii.gz";
  const Volume v = load_volume(s, 12, t.dir());
  EXPECT_EQ(v.spacing, (std::array<double, 3>{0.5, 2.0, 1.0}));
  s.spacing = Vec3{3, 3, 3};
  EXPECT_EQ(load_volume(s, 12, t.dir()).spacing, (std::array<double, 3>{3, 3, 3}));
}

// ---------------------------------------------------------------- quantisation

TEST(Quantise, EightBitIntoTwelve) {
  EXPECT_EQ(quantise_value(255, {0, 255}, 12), 4095);
  EXPECT_EQ(quantise_value(0, {0, 255}, 12), 0);
  EXPECT_EQ(quantise_value(128, {0, 255}, 12), 2056);  // 2055.53 rounds up
  EXPECT_EQ(quantise_value(1, {0, 255}, 12), 16);      // 16.06
  EXPECT_EQ(quantise_value(-5, {0, 255}, 12), 0);      // clamped
  EXPECT_EQ(quantise_value(300, {0, 255}, 12), 4095);  // clamped
}

TEST(Quantise, EightBitsLeaveUint8Unchanged) {
  std::vector<uint8_t> in(256);
  for (int i = 0; i < 256; ++i) in[i] = static_cast<uint8_t>(i);
  const auto out = quantise(in.data(), SampleType::UInt8, {256, 1, 1}, full(), 8, "test");
  for (int i = 0; i < 256; ++i) EXPECT_EQ(out[i], i);
}

TEST(Quantise, FullRanges) {
  const std::vector<int16_t> s16{-32768, 0, 32767};
  EXPECT_EQ(quantise(s16.data(), SampleType::Int16, {3, 1, 1}, full(), 12, "t"),
            (std::vector<uint16_t>{0, 2048, 4095}));  // 0 -> 2047.53 -> 2048
  const std::vector<uint16_t> u12{0, 1, 4095};
  EXPECT_EQ(quantise(u12.data(), SampleType::UInt12, {3, 1, 1}, full(), 12, "t"),
            (std::vector<uint16_t>{0, 1, 4095}));
  const std::vector<uint16_t> u16{0, 16, 65535};
  EXPECT_EQ(quantise(u16.data(), SampleType::UInt16, {3, 1, 1}, full(), 12, "t"),
            (std::vector<uint16_t>{0, 1, 4095}));  // 16 * 4095 / 65535 = 0.9998
  const std::vector<float> f{1, 2, 3};             // floats: Full means MinMax
  EXPECT_EQ(quantise(f.data(), SampleType::Float32, {3, 1, 1}, full(), 12, "t"),
            (std::vector<uint16_t>{0, 2048, 4095}));
}

TEST(Quantise, MinMaxAndConstantData) {
  const std::vector<uint16_t> v{100, 200, 300};
  EXPECT_EQ(quantise(v.data(), SampleType::UInt16, {3, 1, 1}, minmax(), 12, "t"),
            (std::vector<uint16_t>{0, 2048, 4095}));  // 2047.5 rounds up
  const std::vector<uint16_t> c{7, 7, 7, 7};
  EXPECT_EQ(quantise(c.data(), SampleType::UInt16, {2, 2, 1}, minmax(), 12, "t"),
            (std::vector<uint16_t>{0, 0, 0, 0}));
}

TEST(Quantise, WindowClampsAndRejectsEmptyWindow) {
  const std::vector<int16_t> v{-100, 0, 50, 100, 200};
  EXPECT_EQ(quantise(v.data(), SampleType::Int16, {5, 1, 1}, window(0, 100), 8, "t"),
            (std::vector<uint16_t>{0, 0, 128, 255, 255}));  // 127.5 rounds up
  EXPECT_MSG_HAS(input_error([&] {
                   quantise(v.data(), SampleType::Int16, {5, 1, 1}, window(5, 5), 8, "t");
                 }),
                 "window");
  EXPECT_MSG_HAS(input_error([&] {
                   quantise(v.data(), SampleType::Int16, {5, 1, 1}, window(9, 1), 8, "t");
                 }),
                 "window");
}

TEST(Quantise, VoxelBitsLimits) {
  EXPECT_MSG_HAS(input_error([] { check_voxel_bits(7); }), "voxel_bits");
  EXPECT_MSG_HAS(input_error([] { check_voxel_bits(17); }), "17");
  EXPECT_NO_THROW(check_voxel_bits(8));
  EXPECT_NO_THROW(check_voxel_bits(16));
  EXPECT_EQ(quantise_value(1.0, {0, 1}, 16), 65535);
  VolumeSource s;
  s.kind = "constant";
  EXPECT_MSG_HAS(input_error([&] { load_volume(s, 17, ""); }), "voxel_bits");
}

// ---------------------------------------------------------------- synthetic

VolumeSource synth(const std::string& kind, std::array<int, 3> size) {
  VolumeSource s;
  s.kind = kind;
  s.size = size;
  return s;
}

TEST(Synthetic, SphereSymmetricCentreMaxCornerZero) {
  const Volume v = make_synthetic(synth("sphere", {32, 32, 32}), 12);
  EXPECT_EQ(v.dim, (std::array<int, 3>{32, 32, 32}));
  EXPECT_EQ(v.source, "sphere 32x32x32 r=12");
  for (int z = 0; z < 32; ++z)
    for (int y = 0; y < 32; ++y)
      for (int x = 0; x < 32; ++x) {
        const uint16_t a = v.at(x, y, z);
        ASSERT_EQ(a, v.at(31 - x, y, z));
        ASSERT_EQ(a, v.at(x, 31 - y, z));
        ASSERT_EQ(a, v.at(x, y, 31 - z));
      }
  EXPECT_EQ(v.at(15, 16, 15), 4095);
  EXPECT_EQ(*std::max_element(v.data.begin(), v.data.end()), 4095);
  EXPECT_EQ(v.at(0, 0, 0), 0);
  EXPECT_EQ(v.at(31, 31, 31), 0);
}

TEST(Synthetic, SphereRampIsTwoVoxelsWide) {
  VolumeSource s = synth("sphere", {33, 33, 33});
  s.radius = 10;  // centre 16: voxel 26 sits on the surface
  const Volume v = make_synthetic(s, 12);
  EXPECT_EQ(v.at(26, 16, 16), 2048);  // 0.5 -> 2047.5 -> 2048
  EXPECT_EQ(v.at(25, 16, 16), 4095);
  EXPECT_EQ(v.at(27, 16, 16), 0);
  s.center = Vec3{0, 0, 0};
  s.radius = 2;
  const Volume c = make_synthetic(s, 12);
  EXPECT_EQ(c.at(0, 0, 0), 4095);
  EXPECT_EQ(c.at(2, 0, 0), 2048);
}

TEST(Synthetic, SingleVoxelAndConstant) {
  VolumeSource s = synth("single_voxel", {5, 6, 7});
  s.at = {1, 2, 3};
  s.value = 0.5;
  const Volume v = make_synthetic(s, 12);
  for (size_t i = 0; i < v.data.size(); ++i)
    EXPECT_EQ(v.data[i], i == v.index(1, 2, 3) ? 2048 : 0) << i;
  s = synth("constant", {4, 4, 4});
  s.value = 0.25;
  const Volume c = make_synthetic(s, 12);
  EXPECT_EQ(c.data, std::vector<uint16_t>(64, 1024));  // 1023.75 + 0.5
}

TEST(Synthetic, NoiseIsDeterministicPerSeed) {
  VolumeSource s = synth("noise", {8, 8, 8});
  s.seed = 7;
  const Volume a = make_synthetic(s, 12), b = make_synthetic(s, 12);
  EXPECT_EQ(a.data, b.data);
  std::mt19937 gen(7);
  EXPECT_EQ(a.data[0], gen() >> 20);
  EXPECT_EQ(a.data[1], gen() >> 20);
  s.seed = 8;
  EXPECT_NE(make_synthetic(s, 12).data, a.data);
  EXPECT_LE(*std::max_element(a.data.begin(), a.data.end()), 4095);
}

TEST(Synthetic, Fields) {
  VolumeSource s = synth("field", {41, 41, 41});
  const Volume ml = make_synthetic(s, 12);
  const auto [lo, hi] = std::minmax_element(ml.data.begin(), ml.data.end());
  EXPECT_LE(*hi, 4095);
  EXPECT_GT(*hi - *lo, 3000);  // the signal spans most of [0,1]
  // Centre of [-1,1]^3: r=0, z=0 -> (1 + 0.25 * (1 + cos(12 pi))) / 2.5 = 0.6
  EXPECT_EQ(ml.at(20, 20, 20), expected_q(0.6, 0, 1, 12));

  s.field = "gaussian";
  const Volume g = make_synthetic(s, 12);
  EXPECT_EQ(g.at(20, 20, 20), 4095);
  EXPECT_EQ(*std::max_element(g.data.begin(), g.data.end()), 4095);
  EXPECT_LT(g.at(0, 0, 0), 10);

  s.field = "ramp_y";
  const Volume r = make_synthetic(s, 12);
  EXPECT_EQ(r.at(3, 0, 9), 0);
  EXPECT_EQ(r.at(7, 40, 2), 4095);
  EXPECT_EQ(r.at(7, 20, 2), 2048);
  EXPECT_EQ(r.at(0, 20, 40), 2048);
}

TEST(Synthetic, BadParametersRejected) {
  EXPECT_MSG_HAS(input_error([] {
                   make_synthetic(synth("sphere", {0, 8, 8}), 12);
                 }),
                 "volume.size");
  EXPECT_MSG_HAS(input_error([] {
                   make_synthetic(synth("noise", {8, 1025, 8}), 12);
                 }),
                 "volume.size");
  VolumeSource s = synth("constant", {4, 4, 4});
  s.value = 1.5;
  EXPECT_MSG_HAS(input_error([&] { make_synthetic(s, 12); }), "volume.value");
  s.value = -0.1;
  EXPECT_MSG_HAS(input_error([&] { make_synthetic(s, 12); }), "volume.value");
  s = synth("single_voxel", {4, 4, 4});
  s.at = {1, 4, 1};
  EXPECT_MSG_HAS(input_error([&] { make_synthetic(s, 12); }), "volume.at");
  s = synth("field", {4, 4, 4});
  s.field = "wobble";
  EXPECT_MSG_HAS(input_error([&] { make_synthetic(s, 12); }), "wobble");
  s = synth("sphere", {4, 4, 4});
  s.radius = -1;
  EXPECT_MSG_HAS(input_error([&] { make_synthetic(s, 12); }), "volume.radius");
}

TEST(LoadVolume, UnknownKindAndBadSpacing) {
  VolumeSource s = synth("teapot", {4, 4, 4});
  EXPECT_MSG_HAS(input_error([&] { load_volume(s, 12, ""); }), "unknown volume kind 'teapot'");
  s = synth("constant", {4, 4, 4});
  s.spacing = Vec3{1, 0, 1};
  EXPECT_MSG_HAS(input_error([&] { load_volume(s, 12, ""); }), "volume.spacing");
  s.spacing = Vec3{0.5, 1, 2};
  const Volume v = load_volume(s, 14, "");
  EXPECT_EQ(v.spacing, (std::array<double, 3>{0.5, 1, 2}));
  EXPECT_EQ(v.bits, 14);
  EXPECT_EQ(v.data.front(), 16383);
}

}  // namespace
