// Hostile input and hostile conditions (docs/reliability.md): every test
// makes its own bad file, full disk, FIFO or signal, and checks that cube4
// exits 2 naming the culprit, never crashes or hangs, and leaves every
// existing output as it was and no temporary behind.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <nifti1.h>
#include <signal.h>
#include <sys/mount.h>
#include <sys/stat.h>
#include <zlib.h>

#include <cctype>
#include <chrono>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <thread>
#include <vector>

#include "golden/errors.hpp"
#include "golden/input_file.hpp"
#include "golden/scene_io.hpp"
#include "tb/tests/cli_support.hpp"

namespace {

using cube4::test::Cli;
using cube4::test::CliResult;
namespace fs = std::filesystem;
using Bytes = std::vector<unsigned char>;

const char* kNoise = R"({"volume": {"synthetic": "noise", "size": [24, 24, 24]},
                         "transfer": {"opacity": [[0, 0.3], [1, 0.9]]}, "output": {"width": 256, "height": 256}})";

class Reliability : public Cli {
 protected:
  // The folder's files, each with its size and a hash of its contents:
  // short enough to print when two differ.
  std::string snapshot(const fs::path& d) const {
    std::map<std::string, std::string> m;
    for (const auto& e : fs::directory_iterator(d)) {
      if (e.path().filename() == "stderr.txt" || e.path().filename() == "stdout.txt") continue;
      std::string what = "folder";
      if (!e.is_directory()) {
        std::ifstream in(e.path(), std::ios::binary);
        const std::string bytes(std::istreambuf_iterator<char>(in), {});
        what = std::to_string(bytes.size()) + " bytes #" + std::to_string(std::hash<std::string>{}(bytes) % 100000);
      }
      m[e.path().filename().string()] = what;
    }
    std::string out;
    for (const auto& [name, what] : m) out += name + " (" + what + ") ";
    return out;
  }
  void write_bytes(const std::string& name, const Bytes& b) const {
    std::ofstream out(path(name), std::ios::binary);
    out.write(reinterpret_cast<const char*>(b.data()), static_cast<std::streamsize>(b.size()));
  }
  // One line on stderr, ours: nothing a library printed before it.
  static void expect_one_error_line(const CliResult& r, const std::string& must_contain) {
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_EQ(r.err.rfind("cube4: error: ", 0), 0u) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_NE(r.err.find(must_contain), std::string::npos) << "lacks " << must_contain << ": " << r.err;
  }
};

Bytes gzip(const Bytes& in, size_t repeat = 1) {
  z_stream z{};
  deflateInit2(&z, 1, Z_DEFLATED, 31, 8, Z_DEFAULT_STRATEGY);
  Bytes out;
  unsigned char buf[1 << 16];
  for (size_t r = 0; r < repeat; ++r) {
    z.next_in = const_cast<unsigned char*>(in.data());
    z.avail_in = static_cast<uInt>(in.size());
    const int flush = r + 1 == repeat ? Z_FINISH : Z_NO_FLUSH;
    do {
      z.next_out = buf;
      z.avail_out = sizeof buf;
      deflate(&z, flush);
      out.insert(out.end(), buf, buf + (sizeof buf - z.avail_out));
    } while (z.avail_out == 0);
  }
  deflateEnd(&z);
  return out;
}

// VolPack .den header (see golden/volume_den.cpp) for nx x ny x nz.
Bytes den_header(int nx, int ny, int nz) {
  Bytes b;
  auto put16 = [&](unsigned v) {
    b.push_back(static_cast<unsigned char>(v & 0xff));
    b.push_back(static_cast<unsigned char>(v >> 8));
  };
  put16(1);
  for (int block = 0; block < 3; ++block) {
    for (int i = 0; i < 3; ++i) put16(0);
    put16(nx - 1), put16(ny - 1), put16(nz - 1);
    put16(nx), put16(ny), put16(nz);
  }
  put16(0);
  const uint32_t n = static_cast<uint32_t>(nx) * ny * nz;
  put16(n & 0xffff), put16(n >> 16);
  return b;
}

nifti_1_header nifti_header(short nx, short ny, short nz) {
  nifti_1_header h{};
  h.sizeof_hdr = 348;
  h.dim[0] = 3;
  for (int i = 1; i < 8; ++i) h.dim[i] = 1;
  h.dim[1] = nx, h.dim[2] = ny, h.dim[3] = nz;
  h.datatype = DT_UINT8;
  h.bitpix = 8;
  h.pixdim[1] = h.pixdim[2] = h.pixdim[3] = 1;
  h.vox_offset = 352;
  std::memcpy(h.magic, "n+1", 4);
  return h;
}

Bytes nifti_file(const nifti_1_header& h, size_t data_bytes) {
  Bytes b(sizeof h + 4, 0);
  std::memcpy(b.data(), &h, sizeof h);
  for (size_t i = 0; i < data_bytes; ++i) b.push_back(static_cast<unsigned char>(i * 7));
  return b;
}

// ---- outputs --------------------------------------------------------------

// The disk fills while the outputs are written: with a small tmpfs where
// mounting is allowed (as root), and always with a file-size limit
// (RLIMIT_FSIZE, SIGXFSZ ignored so write() fails with EFBIG as on a full disk).
TEST_F(Reliability, FullDiskLeavesEveryExistingOutputAsItWas) {
  const std::string scene = write("s.json", kNoise);
  struct Disk {
    std::string name, folder, shell;
  };
  std::vector<Disk> disks;
  const fs::path mnt = dir / "small";
  fs::create_directories(mnt);
  const bool mounted = ::mount("tmpfs", mnt.c_str(), "tmpfs", 0, "size=64k") == 0;
  if (mounted) disks.push_back({"tmpfs of 64 KiB", mnt.string(), ""});
  disks.push_back({"RLIMIT_FSIZE 64 KiB", (dir / "limited").string(), "trap \"\" XFSZ; ulimit -f 64"});
  fs::create_directories(dir / "limited");
  for (const Disk& d : disks) {
    SCOPED_TRACE(d.name);
    for (const char* f : {"out.exr", "bp.png", "r.json"}) std::ofstream(fs::path(d.folder) / f) << "old " << f;
    const auto before = snapshot(d.folder);
    // The EXR is about a megabyte: larger than either disk.
    const std::string o = d.folder + "/out.exr", bp = d.folder + "/bp.png", rep = d.folder + "/r.json";
    const CliResult r = run("render " + scene + " -q -o " + o + " --baseplane " + bp + " --report " + rep, d.shell);
    EXPECT_EQ(r.code, 2) << r.err;
    EXPECT_NE(r.err.find("cannot write"), std::string::npos) << r.err;
    EXPECT_EQ(snapshot(d.folder), before) << "an output was touched or a temporary left behind";
    // The same run with room succeeds: the failure was the disk's.
    if (&d == &disks.back()) {
      const CliResult ok = run("render " + scene + " -q -o " + o + " --baseplane " + bp + " --report " + rep);
      EXPECT_EQ(ok.code, 0) << ok.err;
      EXPECT_NE(snapshot(d.folder), before);
    }
  }
  if (mounted) ::umount(mnt.c_str());
  if (!mounted) std::fprintf(stderr, "note: tmpfs could not be mounted here; the file-size limit stood in\n");
}

// SIGTERM and SIGINT while rendering: the run dies, the outputs keep their
// old contents and its temporaries are gone.
TEST_F(Reliability, KilledRunLeavesNoTemporaryAndNoChangedOutput) {
  const std::string scene = write("s.json", R"({"volume": {"synthetic": "noise", "size": [96, 96, 96]},
      "output": {"width": 512, "height": 512}})");
  for (int sig : {SIGTERM, SIGINT}) {
    SCOPED_TRACE(sig);
    std::ofstream(path("out.png")) << "old image";
    std::ofstream(path("r.json")) << "old report";
    const auto before = snapshot(dir);
    const std::string cmd = std::string(CUBE4_BINARY) + " render " + scene + " -q --model reference --reference-step 0.05 -o " +
                            path("out.png") + " --report " + path("r.json");
    const pid_t pid = ::fork();
    ASSERT_GE(pid, 0);
    if (pid == 0) {
      ::execl("/bin/sh", "sh", "-c", ("exec " + cmd + " 2>/dev/null").c_str(), static_cast<char*>(nullptr));
      ::_exit(127);
    }
    // Wait until the temporaries exist: the run is past its checks.
    bool started = false;
    for (int i = 0; i < 400 && !started; ++i) {
      std::this_thread::sleep_for(std::chrono::milliseconds(25));
      for (const auto& e : fs::directory_iterator(dir))
        if (e.path().filename().string().find(".tmp-") != std::string::npos) started = true;
    }
    EXPECT_TRUE(started) << "no temporary appeared";
    ::kill(pid, sig);
    int status = 0;
    ::waitpid(pid, &status, 0);
    EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == sig) << "the run ended before the signal (status " << status << ")";
    EXPECT_EQ(snapshot(dir), before);
  }
}

TEST_F(Reliability, OutputPathsAreCheckedBeforeAnyWork) {
  const std::string scene = write("s.json", kNoise);
  fs::create_directories(dir / "d.png");
  std::ofstream(path("keep.png")) << "old";
  struct Case {
    std::string args, must_contain;
  };
  const std::vector<Case> cases = {
      {"-o " + path("d.png"), "is a folder"},
      {"-o " + path("keep.png") + " --baseplane " + path("keep.png"), "also writes"},
      {"-o " + path("keep.png") + " --baseplane " + dir.string() + "/./keep.png", "also writes"},
      {"-o " + path("nowhere/x.png"), "does not exist"},
      {"-o " + path("keep.png") + " --report " + path("nowhere/r.json"), "does not exist"},
      {"-o " + path("keep.png") + " --model rtl --trace " + path("nowhere/t.fst"), "does not exist"},
      {"-o /dev/null.png --baseplane /dev/full", "/dev/full"},
      {"-o " + path("keep.png") + " --trace-window -1 5", "--trace-window"},
      {"-o " + path("keep.png") + " --model fixed --trace " + path("t.fst"), "no RTL unit"},
  };
  const auto before = snapshot(dir);
  for (const Case& c : cases) {
    // A missing scene would fail too; the outputs must be refused first.
    const CliResult r = run("render " + path("no-such-scene.json") + " -q " + c.args);
    EXPECT_EQ(r.code, 2) << c.args << "\n" << r.err;
    EXPECT_NE(r.err.find(c.must_contain), std::string::npos) << c.args << "\n" << r.err;
    EXPECT_EQ(snapshot(dir), before) << c.args;
  }
  EXPECT_FALSE(fs::exists("/dev/null.png"));
}

// An output naming an input of the run would replace what it reads.
TEST_F(Reliability, OutputsNamingAnInputAreRefused) {
  std::ofstream(path("v.raw"), std::ios::binary) << std::string(8, '\x10');
  const std::string scene = write("s.json", R"({"volume": {"file": "v.raw", "dim": [2, 2, 2]}})");
  const auto before = snapshot(dir);
  const CliResult r = run("render " + scene + " -q -o " + path("o.png") + " --report " + scene);
  expect_one_error_line(r, "the scene");
  const CliResult v = run("render " + scene + " -q -o " + path("o.png") + " --report " + path("./v.raw"));
  expect_one_error_line(v, "the volume");
  EXPECT_EQ(snapshot(dir), before);
}

TEST_F(Reliability, BadSceneAfterGoodOutputsTouchesNothing) {
  std::ofstream(path("out.png")) << "old";
  write("bad.json", R"({"volume": {"synthetic": "sphere"}, "blend": "sum"})");
  const auto with_scene = snapshot(dir);
  const CliResult r = run("render " + path("bad.json") + " -q -o " + path("out.png") + " --report " + path("r.json"));
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_EQ(snapshot(dir), with_scene);
}

TEST_F(Reliability, OutputsGetTheUmaskModeNotTheTemporaryOne) {
  const std::string scene = write("s.json", kNoise);
  const CliResult r = run("render " + scene + " -q -o " + path("o.png") + " --report " + path("r.json"), "umask 022");
  ASSERT_EQ(r.code, 0) << r.err;
  for (const char* f : {"o.png", "r.json"})
    EXPECT_EQ(fs::status(path(f)).permissions() & fs::perms::all,
              fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read | fs::perms::others_read)
        << f;
}

// ---- inputs that would exhaust the machine ---------------------------------

TEST_F(Reliability, NonRegularFilesAreRefusedWithoutBlocking) {
  ASSERT_EQ(::mkfifo(path("fifo").c_str(), 0600), 0);
  for (const char* name : {"f.den", "f.nii", "f.raw", "f.json"}) fs::create_symlink(path("fifo"), path(name));
  struct Case {
    std::string args, must_contain;
  };
  const std::vector<Case> cases = {
      {"info " + path("f.json"), "FIFO"},
      {"info " + write("den.json", R"({"volume": {"file": "f.den"}})"), "FIFO"},
      {"info " + write("nii.json", R"({"volume": {"file": "f.nii"}})"), "FIFO"},
      {"info " + write("raw.json", R"({"volume": {"file": "f.raw", "dim": [2, 2, 2]}})"), "FIFO"},
      {"info " + write("zero.json", R"({"volume": {"file": "/dev/zero", "format": "den"}})"), "device"},
      {"info " + write("zeronii.json", R"({"volume": {"file": "/dev/zero", "format": "nifti"}})"), "device"},
      {"info /dev/zero", "device"},
      {"info " + dir.string(), "directory"},
  };
  for (const Case& c : cases) {
    // timeout: a hang fails the test (exit 124) instead of stalling the suite.
    expect_one_error_line(run(c.args, "", "timeout 20"), c.must_contain);
  }
}

TEST_F(Reliability, GzipBombReadsOnlyWhatTheHeaderDeclares) {
  // 8x8x8 declared, 64 MiB of zeros behind it, and the gzip trailer's CRC
  // spoiled: a loader that inflated the whole file would meet it and fail;
  // one that reads what the header declares never gets there. (Exact, where
  // a time limit would only be loose.)
  Bytes plain = den_header(8, 8, 8);
  plain.resize(plain.size() + (1 << 20), 0);
  Bytes bomb = gzip(plain, 64);
  bomb[bomb.size() - 8] ^= 0xff;
  write_bytes("bomb.den.gz", bomb);
  // The spoiled trailer is there to be met: zlib reading to the end fails.
  gzFile f = gzopen(path("bomb.den.gz").c_str(), "rb");
  ASSERT_NE(f, nullptr);
  std::vector<char> buf(1 << 20);
  int got = 0;
  while ((got = gzread(f, buf.data(), static_cast<unsigned>(buf.size()))) > 0) {
  }
  EXPECT_LT(got, 0) << "a read to the end did not meet the spoiled CRC";
  gzclose(f);
  const CliResult r = run("info " + write("s.json", R"({"volume": {"file": "bomb.den.gz"}})"));
  EXPECT_EQ(r.code, 0) << r.err;
}

TEST_F(Reliability, VolumesBeyondTheMemoryLimitAreRefusedNamingFileSizeAndLimit) {
  // A .nii.gz of a few hundred bytes declaring 2048x2048x1024 voxels.
  write_bytes("big.nii.gz", gzip(nifti_file(nifti_header(2048, 2048, 1024), 4096)));
  const CliResult n = run("info " + write("n.json", R"({"volume": {"file": "big.nii.gz"}})"));
  expect_one_error_line(n, "big.nii.gz");
  EXPECT_NE(n.err.find("2048x2048x1024"), std::string::npos) << n.err;
  EXPECT_NE(n.err.find("memory limit of 4096 MiB"), std::string::npos) << n.err;
  // A .den.gz bomb whose header declares 1024^3 (3 GiB to hold): under the
  // default it is read (that is what it declares), under --max-memory refused.
  Bytes plain = den_header(1024, 1024, 1024);
  write_bytes("big.den.gz", gzip(plain));
  const CliResult d = run("info --max-memory 256 " + write("d.json", R"({"volume": {"file": "big.den.gz"}})"));
  expect_one_error_line(d, "big.den.gz");
  EXPECT_NE(d.err.find("memory limit of 256 MiB"), std::string::npos) << d.err;
  // Raw: refused before the file is even looked at for size.
  const CliResult w = run("info --max-memory 16 " +
                          write("w.json", R"({"volume": {"file": "w.raw", "dim": [512, 512, 64], "type": "uint16"}})"));
  expect_one_error_line(w, "memory limit of 16 MiB");
  // The render's own needs: an 8192x8192 image.
  const CliResult i = run("render --max-memory 512 -q -o " + path("i.png") + " " +
                          write("i.json", R"({"volume": {"synthetic": "sphere", "size": [8, 8, 8]},
                                              "output": {"width": 8192, "height": 8192}})"));
  expect_one_error_line(i, "8192x8192 image");
  EXPECT_FALSE(fs::exists(path("i.png")));
}

// ---- scenes ------------------------------------------------------------------

TEST_F(Reliability, DeepNestingIsRefusedWithoutCrashing) {
  const std::string deep = std::string(100000, '[') + std::string(100000, ']');
  const CliResult a = run("info " + write("a.json", R"({"volume": {"synthetic": "sphere"}, "view": )" + deep + "}"));
  expect_one_error_line(a, "nested more than 64 levels");
  const CliResult b = run("info " + write("b.json", R"({"volume": {"synthetic": "sphere"}, "unknown": )" +
                                                        std::string(75000, '[') + std::string(75000, ']') + "}"));
  expect_one_error_line(b, "nested more than 64 levels");
  // Long values are shown cut short.
  std::string wide = "[";
  for (int i = 0; i < 200000; ++i) wide += "1,";
  wide += "1]";
  const CliResult c = run("info " + write("c.json", R"({"volume": {"synthetic": "sphere"}, "view": {"rotate": )" + wide + "}}"));
  expect_one_error_line(c, "...");
  EXPECT_LT(c.err.size(), 400u) << c.err;
}

TEST_F(Reliability, NumbersBeyondADoubleNameTheirKey) {
  const CliResult r = run("info " + write("s.json", R"({"volume": {"synthetic": "sphere"}, "cut_plane": {"dmin": 1e309}})"));
  expect_one_error_line(r, "\"cut_plane.dmin\" = 1e309");
  const CliResult a = run("info " + write("a.json", R"({"volume": {"synthetic": "sphere"}, "view": {"rotate": [0, -2e400, 0]}})"));
  expect_one_error_line(a, "\"view.rotate[1]\" = -2e400");
}

TEST_F(Reliability, CutPlaneDistancesBeyondTheirRegistersAreRefused) {
  for (const char* v : {"1e15", "-1e15"}) {
    const std::string scene = std::string(R"({"volume": {"synthetic": "sphere", "size": [16, 16, 16]}, "cut_plane": {"normal": [1, 0, 0], "dmin": )") +
                              v + R"(, "dmax": 1e15}})";
    const CliResult r = run("render -q -o " + path("c.png") + " " + write("c.json", scene));
    expect_one_error_line(r, std::string("\"cut_plane.dmin\" = ") + (v[0] == '-' ? "-1e+15" : "1e+15"));
    EXPECT_NE(r.err.find("CUT_DMIN"), std::string::npos) << r.err;
  }
  const CliResult f = run("info " + write("f.json", R"({"volume": {"synthetic": "sphere"}, "cut_plane": {"falloff": 1e16}})"));
  expect_one_error_line(f, "\"cut_plane.falloff\" = 1e+16");
  // Tiny and huge normals have a direction like any other.
  for (const char* n : {"[1e-200, 0, 0]", "[1e200, 1e200, 0]"}) {
    const CliResult r = run("info " + write("n.json", std::string(R"({"volume": {"synthetic": "sphere"}, "cut_plane": {"normal": )") + n + "}}"));
    EXPECT_EQ(r.code, 0) << n << r.err;
  }
  // A coefficient wider than the precision given for it.
  const CliResult k = run("info " + write("k.json", R"({"volume": {"synthetic": "sphere"}, "material": {"kd": 3.5},
      "precision": {"coef_bits": 8, "coef_frac_bits": 7}})"));
  expect_one_error_line(k, "\"material.kd\" = 3.5");
}

TEST_F(Reliability, DocumentedRawKeysAreAccepted) {
  std::ofstream(path("ct.raw"), std::ios::binary) << std::string(4 * 4 * 2 * 2, '\x01');
  // docs/scene.md's raw example, at a size a test can write.
  const CliResult r = run("info " + write("ct.json", R"({
  "volume": {"file": "ct.raw", "dim": [4, 4, 2], "type": "int16", "endian": "little",
             "spacing": [0.7, 0.7, 1.25], "map": [-200, 1200]},
  "view": {"direction": [0, -1, -0.3], "up": [0, 0, 1]},
  "output": {"width": 512, "height": 512}
})"));
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("1.25"), std::string::npos) << r.out;
  const CliResult u = run("info " + write("u.json", R"({"volume": {"file": "ct.raw", "dim": [4, 4, 2], "type": "int16", "spacng": [1, 1, 1]}})"));
  expect_one_error_line(u, "volume.spacng");
}

TEST_F(Reliability, MessagesSayWhatIsWrong) {
  // An I/O error reading the scene is not a JSON syntax error.
  const CliResult io = run("info /proc/self/mem");
  expect_one_error_line(io, "cannot read the scene (Input/output error)");
  const CliResult empty = run("info " + write("e.json", R"({"volume": {"synthetic": "sphere"}, "transfer": {"opacity": []}})"));
  expect_one_error_line(empty, "has 0 entries; at least 1 is needed");
  EXPECT_EQ(empty.err.find("18446744073709551615"), std::string::npos) << empty.err;
}

// ---- NIfTI-1 rules -------------------------------------------------------------

TEST_F(Reliability, NiftiHeadersBreakingTheStandardAreRefused) {
  struct Case {
    std::string name, must_contain;
    void (*edit)(nifti_1_header&);
  };
  const std::vector<Case> cases = {
      {"dim0_zero", "dim[0] = 0", [](nifti_1_header& h) { h.dim[0] = 0; }},
      {"dim0_eight", "dim[0] = 8", [](nifti_1_header& h) { h.dim[0] = 8; }},
      {"dim_neg", "dim[2] = -4", [](nifti_1_header& h) { h.dim[2] = -4; }},
      {"sizeof0", "sizeof_hdr is 0", [](nifti_1_header& h) { h.sizeof_hdr = 0; }},
      {"off_nan", "vox_offset = nan", [](nifti_1_header& h) { h.vox_offset = NAN; }},
      {"off_neg", "vox_offset = -352", [](nifti_1_header& h) { h.vox_offset = -352; }},
      {"off_small", "vox_offset = 100", [](nifti_1_header& h) { h.vox_offset = 100; }},
      {"off_frac", "vox_offset = 352.5", [](nifti_1_header& h) { h.vox_offset = 352.5f; }},
      {"magic", "magic", [](nifti_1_header& h) { std::memcpy(h.magic, "xyz", 4); }},
      {"bitpix", "bitpix = 16", [](nifti_1_header& h) { h.bitpix = 16; }},
  };
  for (const Case& c : cases) {
    nifti_1_header h = nifti_header(4, 4, 4);
    c.edit(h);
    write_bytes(c.name + ".nii", nifti_file(h, 64));
    const CliResult r = run("info " + write(c.name + ".json", R"({"volume": {"file": ")" + c.name + R"(.nii"}})"));
    SCOPED_TRACE(c.name);
    expect_one_error_line(r, c.must_contain);
    EXPECT_NE(r.err.find(c.name + ".nii"), std::string::npos) << r.err;
  }
  // The well-formed one loads as 4x4x4.
  write_bytes("ok.nii", nifti_file(nifti_header(4, 4, 4), 64));
  const CliResult ok = run("info " + write("ok.json", R"({"volume": {"file": "ok.nii"}})"));
  EXPECT_EQ(ok.code, 0) << ok.err;
  EXPECT_NE(ok.out.find("\"dim\": [\n      4,\n      4,\n      4"), std::string::npos) << ok.out;
}

// A corrupt deflate stream (found by fuzz_nifti: znzread hands on gzread's
// -1 as a size_t) is exit 2 for both compressed formats, wherever the
// damage lies.
TEST_F(Reliability, CorruptGzipStreamsAreExitTwo) {
  const Bytes nii = gzip(nifti_file(nifti_header(16, 16, 16), 4096));
  Bytes den = den_header(16, 16, 16);
  den.resize(den.size() + 4096, 7);
  const Bytes dgz = gzip(den);
  // Just after the gzip header, in the deflate data, in the CRC trailer.
  for (double where : {0.0, 0.33, 0.5, 1.0}) {
    auto damaged = [where](Bytes b) {
      const size_t at = 10 + static_cast<size_t>(where * static_cast<double>(b.size() - 10 - 4));
      for (size_t i = 0; i < 4; ++i) b[at + i] ^= 0x5a;
      return b;
    };
    write_bytes("bad.nii.gz", damaged(nii));
    write_bytes("bad.den.gz", damaged(dgz));
    SCOPED_TRACE(where);
    const CliResult n = run("info " + write("n.json", R"({"volume": {"file": "bad.nii.gz"}})"));
    expect_one_error_line(n, "bad.nii.gz");
    const CliResult d = run("info " + write("d.json", R"({"volume": {"file": "bad.den.gz"}})"));
    expect_one_error_line(d, "bad.den.gz");
  }
}

}  // namespace

// ---- limits: refused from the scene and the header, before any voxel -------

namespace {

// A raw volume whose file does not exist: a run that gets past its limits
// fails on opening it, so a refusal naming a limit was made before any
// voxel was loaded.
std::string missing_raw_scene(int nx, int ny, int nz, const std::string& extra = "", int image = 32) {
  return R"({"volume": {"file": "missing.raw", "dim": [)" + std::to_string(nx) + ", " + std::to_string(ny) + ", " +
         std::to_string(nz) + R"(], "type": "uint8"}, "view": {"direction": [0, 0, 1]},
            "output": {"width": )" + std::to_string(image) + R"(, "height": )" + std::to_string(image) + "}" + extra + "}";
}

}  // namespace

TEST_F(Reliability, LimitsAreCheckedBeforeAnyVoxelIsLoaded) {
  const std::string wide = write("wide.json", missing_raw_scene(300, 20, 8));
  const std::string out = " -q -o " + path("o.png");
  // Golden and TLM levels have no ring storage: they get as far as the file.
  for (const char* model : {"fixed", "tlm"}) {
    const CliResult r = run("render " + wide + " --model " + std::string(model) + out);
    expect_one_error_line(r, "missing.raw: cannot open raw volume");
  }
#if CUBE4_TEST_RTL
  // The rings hold 256 voxels per permuted x and y: named, with the value,
  // the limit and what to do.
  for (const char* model : {"rtl", "mixed:interp", "mixed:composite", "mixed:gradient"}) {
    const CliResult r = run("render " + wide + " --model " + std::string(model) + out);
    expect_one_error_line(r, "300 voxels");
    EXPECT_NE(r.err.find("MaxDim 256"), std::string::npos) << model << ": " << r.err;
    EXPECT_NE(r.err.find("at TLM"), std::string::npos) << model << ": " << r.err;
    EXPECT_NE(r.err.find("--blocks"), std::string::npos) << model << ": " << r.err;
    EXPECT_NE(r.err.find("CUBE4_SYSTEM_MAX_DIM"), std::string::npos) << model << ": " << r.err;
  }
  // The shading unit and address generation have no ring storage: not
  // refused for the rings.
  for (const char* model : {"mixed:shade", "mixed:addr"}) {
    const CliResult r = run("render " + wide + " --model " + std::string(model) + out);
    expect_one_error_line(r, "missing.raw: cannot open raw volume");
  }
  // The address generator's 10-bit dimensions, at RTL: 1024 (which the
  // host interface's window takes) is refused for it, named.
  const CliResult a = run("render " + write("a.json", missing_raw_scene(1024, 4, 4)) + " --model mixed:addr" + out);
  expect_one_error_line(a, "1024 voxels");
  EXPECT_NE(a.err.find("10-bit"), std::string::npos) << a.err;
  EXPECT_NE(a.err.find("at TLM"), std::string::npos) << a.err;
  expect_one_error_line(run("render " + write("a2.json", missing_raw_scene(1023, 4, 4)) + " --model mixed:addr" + out),
                        "missing.raw: cannot open raw volume");
  // An unshaded scene runs no gradient unit, so its ring limit does not apply.
  const std::string mip = write("mip.json", missing_raw_scene(300, 20, 8, R"(, "shading": false, "blend": "mip")"));
  expect_one_error_line(run("render " + mip + " --model mixed:gradient" + out), "missing.raw: cannot open raw volume");
  // Pipeline counts with no verilated variant name the CMake option.
  const std::string small = write("small.json", missing_raw_scene(16, 16, 8));
  const CliResult p = run("render " + small + " --model rtl --pipes 3" + out);
  expect_one_error_line(p, "pipelines: 3 has no RTL build");
  EXPECT_NE(p.err.find("CUBE4_SYSTEM_PIPES"), std::string::npos) << p.err;
  // Widths the RTL was not verilated with.
  const CliResult w = run("render " + write("w.json", missing_raw_scene(16, 16, 8, R"(, "precision": {"alpha_bits": 12, "acc_guard_bits": 0})")) +
                          " --model mixed:shade" + out);
  expect_one_error_line(w, "precision: alpha_bits = 12");
  // The message says how to build the RTL at those widths, not to use blocks.
  EXPECT_NE(w.err.find("CUBE4_SYSTEM_WIDTHS"), std::string::npos) << w.err;
  EXPECT_NE(w.err.find("scripts/build_widths.sh AlphaBits=12"), std::string::npos) << w.err;
  EXPECT_EQ(w.err.find("--blocks"), std::string::npos) << w.err;
  // More pipelines than a cycle-level run has lanes.
  expect_one_error_line(run("render " + small + " --model rtl --pipes 32" + out), "at most 16");
#else
  expect_one_error_line(run("render " + wide + " --model rtl" + out), "this build has no RTL");
#endif
  // The host interface's volume window (1024 per axis), for every system level.
  const std::string huge = write("huge.json", missing_raw_scene(2000, 4, 4));
  const CliResult h = run("render " + huge + " --model tlm" + out);
  expect_one_error_line(h, "2000x4x4");
  EXPECT_NE(h.err.find("host interface's 1024"), std::string::npos) << h.err;
  EXPECT_NE(h.err.find("--model fixed"), std::string::npos) << h.err;
  // Memory, for the volume and for the render, from the header.
  const std::string deep = write("deep.json", missing_raw_scene(512, 512, 16));
  expect_one_error_line(run("render --max-memory 4 " + deep + out), "memory limit of 4 MiB");
  const std::string image = write("image.json", missing_raw_scene(64, 64, 8, "", 8192));
  const CliResult m = run("render --max-memory 512 " + image + out);
  expect_one_error_line(m, "8192x8192 image");
  EXPECT_NE(m.err.find("--max-memory"), std::string::npos) << m.err;
}

// scripts/build_widths.sh refuses what the RTL cannot be verilated with in
// the configure step's first second, naming the width and its limit, and
// leaves no half-made build behind to be taken for one.
TEST_F(Reliability, BuildWidthsRefusesWidthsTheRtlCannotTake) {
  const std::string script = "CUBE4_WIDTH_BUILDS=" + path("builds") + " bash " CUBE4_SOURCE_DIR "/scripts/build_widths.sh ";
  struct Bad {
    std::string args, says;
  };
  for (const Bad& b : {Bad{"AlphaBits=99", "AlphaBits=99 is outside precision.alpha_bits's range 8 to 16"},
                       Bad{"Nonsense=3", "Nonsense is not a width of the RTL"},
                       Bad{"WeightBits=10", "WeightBits at most 9 at RTL"},
                       Bad{"AlphaBits", "\"AlphaBits\" is not Name=value"},
                       Bad{"--pipes 0 AlphaBits=12", "\"0\" is not a pipeline count"}}) {
    SCOPED_TRACE(b.args);
    const CliResult r = run_line(script + b.args);
    EXPECT_NE(r.code, 0);
    EXPECT_EQ(r.out, "") << "no program path for a build that failed";
    // CMake wraps its messages: the words, whatever the line breaks.
    std::string words;
    for (const char c : r.err)
      if (!std::isspace(static_cast<unsigned char>(c)) || (!words.empty() && words.back() != ' '))
        words += std::isspace(static_cast<unsigned char>(c)) ? ' ' : c;
    EXPECT_NE(words.find(b.says), std::string::npos) << r.err;
    if (fs::exists(path("builds"))) {
      for (const auto& e : fs::directory_iterator(path("builds"))) {
        EXPECT_FALSE(e.is_directory()) << "a half-made build: " << e.path();
      }
    }
  }
}
