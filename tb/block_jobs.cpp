#include "tb/block_jobs.hpp"

#include <zlib.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "golden/errors.hpp"
#include "golden/input_file.hpp"
#include "systemc/host/register_map.hpp"
#include "tb/report.hpp"
#include "tb/system_report.hpp"

namespace cube4::tb {

namespace {

constexpr char kMagic[8] = {'C', '4', 'P', 'A', 'R', 'T', '\r', '\n'};
constexpr uint32_t kVersion = 1;
constexpr size_t kRecordBytes = 20;
constexpr uint32_t kMaxHeaderBytes = 1 << 16;

// A 64-bit FNV-1a over everything fed to it.
struct Hash {
  uint64_t h = 1469598103934665603ull;
  void bytes(const void* p, size_t n) {
    const auto* b = static_cast<const unsigned char*>(p);
    for (size_t i = 0; i < n; ++i) h = (h ^ b[i]) * 1099511628211ull;
  }
  void u64(uint64_t v) {
    unsigned char b[8];
    for (int i = 0; i < 8; ++i) b[i] = static_cast<unsigned char>(v >> (8 * i));
    bytes(b, 8);
  }
};

void put_u32(std::string& out, uint32_t v) {
  for (int i = 0; i < 4; ++i) out.push_back(static_cast<char>(v >> (8 * i)));
}
uint32_t get_u32(const unsigned char* p) {
  return uint32_t{p[0]} | uint32_t{p[1]} << 8 | uint32_t{p[2]} << 16 | uint32_t{p[3]} << 24;
}

uint32_t crc(const std::string& data, size_t n) {
  return static_cast<uint32_t>(::crc32(0L, reinterpret_cast<const Bytef*>(data.data()), static_cast<uInt>(n)));
}

std::string read_file(const std::string& path, const std::string& what, size_t limit) {
  const golden::FdCloser fd{golden::open_regular_file(path, what)};
  std::string text;
  char buf[1 << 16];
  for (size_t n = sizeof buf; n == sizeof buf && text.size() <= limit;) {
    n = golden::read_fd(fd.fd, buf, sizeof buf, path, what);
    text.append(buf, n);
  }
  if (text.size() > limit)
    throw golden::InputError(path + ": " + what + " is larger than " + std::to_string(limit >> 20) + " MiB");
  return text;
}

}  // namespace

std::string plan_id(const golden::BlockPlan& plan, const golden::Volume& vol) {
  Hash h;
  // Every register the host writes (with the widths the hardware reports),
  // then the tables: what the volume's frame is, bit for bit.
  sysc::regmap::RegisterValues values;
  values.regs = plan.whole;
  values.vol_dims[0] = vol.dim;
  const sysc::HardwareParams hw{plan.whole.p, 1, 256};
  for (const sysc::regmap::Register& r : sysc::regmap::kRegisters)
    if (r.get && (r.set || r.block == sysc::regmap::Block::Precision)) h.u64(r.get(values, hw));
  for (const golden::ClassEntry& e : plan.whole.classification) {
    h.u64(e.r);
    h.u64(e.g);
    h.u64(e.b);
    h.u64(e.a);
  }
  h.bytes(plan.whole.gm_lut.data(), plan.whole.gm_lut.size() * sizeof(uint16_t));
  h.bytes(plan.whole.diffuse_map.data(), plan.whole.diffuse_map.size() * sizeof(uint32_t));
  h.bytes(plan.whole.specular_map.data(), plan.whole.specular_map.size() * sizeof(uint32_t));
  for (int c : plan.counts) h.u64(static_cast<uint64_t>(c));
  for (int d : vol.dim) h.u64(static_cast<uint64_t>(d));
  h.bytes(vol.data.data(), vol.data.size() * sizeof(uint16_t));
  return hex64(h.h);
}

nlohmann::json plan_json(const golden::BlockPlan& plan, const std::string& scene_path, const std::string& id) {
  nlohmann::json j = describe_blocks(plan);
  j["cube4_plan"] = 1;
  j["scene"] = scene_path;
  j["plan_id"] = id;
  return j;
}

PlanFile read_plan(const std::string& path) {
  const std::string text = read_file(path, "the plan", size_t{64} << 20);
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(text);
  } catch (const nlohmann::json::exception& e) {
    throw golden::InputError(path + ": not a plan (invalid JSON: " + e.what() + "); make one with cube4 plan");
  }
  PlanFile p;
  p.path = path;
  auto need = [&](const char* key) -> const nlohmann::json& {
    if (!j.is_object() || !j.contains(key))
      throw golden::InputError(path + ": not a plan (no \"" + key + "\"); make one with cube4 plan");
    return j[key];
  };
  try {
    if (need("cube4_plan").get<int>() != 1)
      throw golden::InputError(path + ": cube4_plan " + need("cube4_plan").dump() + " is not a version this cube4 reads (1)");
    p.scene = need("scene").get<std::string>();
    p.counts = need("counts").get<std::array<int, 3>>();
    p.id = need("plan_id").get<std::string>();
    p.blocks = need("machines").get<int>();
  } catch (const nlohmann::json::exception& e) {
    throw golden::InputError(path + ": a plan key has the wrong type (" + e.what() + ")");
  }
  return p;
}

void write_partial(const std::string& path, const golden::BasePlane& partial, const golden::Precision& p,
                   const std::string& id, int block, int blocks, const std::string& model) {
  const nlohmann::json header = {{"plan_id", id},
                                 {"block", block},
                                 {"blocks", blocks},
                                 {"width", partial.width},
                                 {"height", partial.height},
                                 {"alpha_bits", p.alpha_bits},
                                 {"acc_guard_bits", p.acc_guard_bits},
                                 {"voxel_bits", p.voxel_bits},
                                 {"model", model}};
  const std::string text = header.dump();
  std::string out(kMagic, sizeof kMagic);
  put_u32(out, kVersion);
  put_u32(out, static_cast<uint32_t>(text.size()));
  out += text;
  out.reserve(out.size() + partial.acc.size() * kRecordBytes + 4);
  for (const golden::RayAcc& a : partial.acc) {
    put_u32(out, a.r);
    put_u32(out, a.g);
    put_u32(out, a.b);
    put_u32(out, a.a);
    out.push_back(static_cast<char>(a.value & 0xFF));
    out.push_back(static_cast<char>(a.value >> 8));
    out.push_back(static_cast<char>(a.valid ? 1 : 0));
    out.push_back(0);
  }
  put_u32(out, crc(out, out.size()));
  std::ofstream f(path, std::ios::binary);
  f.write(out.data(), static_cast<std::streamsize>(out.size()));
  f.close();
  if (!f) throw golden::InputError(path + ": could not write the partial image");
}

Partial read_partial(const std::string& path) {
  const std::string data = read_file(path, "the partial image", size_t{4} << 30);
  auto fail = [&](const std::string& why) {
    throw golden::InputError(path + ": " + why + "; render the block again (cube4 render --plan P --block I)");
  };
  const auto* u = reinterpret_cast<const unsigned char*>(data.data());
  if (data.size() < 16 || std::memcmp(data.data(), kMagic, sizeof kMagic) != 0)
    fail("not a cube4 partial image (no C4PART signature)");
  if (get_u32(u + 8) != kVersion)
    fail("partial image format " + std::to_string(get_u32(u + 8)) + ", this cube4 reads " + std::to_string(kVersion));
  const uint32_t hlen = get_u32(u + 12);
  if (hlen > kMaxHeaderBytes || data.size() < 16 + size_t{hlen} + 4) fail("truncated (its header is cut short)");
  nlohmann::json h;
  Partial p;
  p.path = path;
  try {
    h = nlohmann::json::parse(data.substr(16, hlen));
    p.plan_id = h.at("plan_id").get<std::string>();
    p.block = h.at("block").get<int>();
    p.blocks = h.at("blocks").get<int>();
    p.model = h.at("model").get<std::string>();
    p.plane.width = h.at("width").get<int>();
    p.plane.height = h.at("height").get<int>();
    p.plane.bits = h.at("alpha_bits").get<int>();
  } catch (const nlohmann::json::exception& e) {
    fail(std::string("its header is not a partial image's (") + e.what() + ")");
  }
  if (p.plane.width < 0 || p.plane.height < 0 || p.plane.width > (1 << 16) || p.plane.height > (1 << 16))
    fail("its header gives a " + std::to_string(p.plane.width) + "x" + std::to_string(p.plane.height) + " image");
  const size_t pixels = static_cast<size_t>(p.plane.width) * p.plane.height;
  const size_t expected = 16 + size_t{hlen} + pixels * kRecordBytes + 4;
  if (data.size() != expected)
    fail((data.size() < expected ? "truncated: " : "longer than its header says: ") + std::to_string(data.size()) +
         " bytes for a " + std::to_string(p.plane.width) + "x" + std::to_string(p.plane.height) + " image (" +
         std::to_string(expected) + ")");
  if (crc(data, data.size() - 4) != get_u32(u + data.size() - 4)) fail("corrupt (CRC-32 mismatch)");
  p.plane.acc.resize(pixels);
  const unsigned char* q = u + 16 + hlen;
  for (golden::RayAcc& a : p.plane.acc) {
    a.r = get_u32(q);
    a.g = get_u32(q + 4);
    a.b = get_u32(q + 8);
    a.a = get_u32(q + 12);
    a.value = static_cast<uint16_t>(q[16] | q[17] << 8);
    a.valid = q[18] != 0;
    q += kRecordBytes;
  }
  return p;
}

std::vector<Partial> order_partials(const golden::BlockPlan& plan, const std::string& id,
                                    const std::vector<std::string>& files) {
  const int n = static_cast<int>(plan.blocks.size());
  std::vector<Partial> by_block(static_cast<size_t>(n));
  for (const std::string& f : files) {
    Partial p = read_partial(f);
    if (p.plan_id != id)
      throw golden::InputError(f + ": a partial image of another plan (plan_id " + p.plan_id + ", this plan's " + id +
                               "): another scene, view, volume or cut");
    if (p.block < 0 || p.block >= n || p.blocks != n)
      throw golden::InputError(f + ": block " + std::to_string(p.block) + " of " + std::to_string(p.blocks) +
                               ", but the plan has " + std::to_string(n) + " blocks");
    Partial& slot = by_block[static_cast<size_t>(p.block)];
    if (!slot.path.empty())
      throw golden::InputError(f + ": block " + std::to_string(p.block) + " again (also " + slot.path + ")");
    const golden::Block& b = plan.blocks[static_cast<size_t>(p.block)];
    if (p.plane.width != b.base_width() || p.plane.height != b.base_height())
      throw golden::InputError(f + ": block " + std::to_string(p.block) + " is " + std::to_string(p.plane.width) + "x" +
                               std::to_string(p.plane.height) + ", the plan's " + std::to_string(b.base_width()) +
                               "x" + std::to_string(b.base_height()));
    slot = std::move(p);
  }
  std::string missing;
  for (int i = 0; i < n; ++i)
    if (by_block[static_cast<size_t>(i)].path.empty()) missing += (missing.empty() ? "" : ", ") + std::to_string(i);
  if (!missing.empty())
    throw golden::InputError("partial images: block" + std::string(missing.find(',') == std::string::npos ? " " : "s ") +
                             missing + " of " + std::to_string(n) + " missing");
  return by_block;
}

}  // namespace cube4::tb
