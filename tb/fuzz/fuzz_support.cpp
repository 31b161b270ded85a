#include "tb/fuzz/fuzz_support.hpp"

#include <fcntl.h>
#include <unistd.h>
#include <zlib.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>

#include "golden/input_file.hpp"

namespace cube4::fuzz {

const std::string& scratch_file(const std::string& suffix, const uint8_t* data, size_t size) {
  static std::map<std::string, std::string> names;
  std::string& name = names[suffix];
  if (name.empty()) {
    std::string templ = (std::filesystem::temp_directory_path() / "cube4-fuzz-XXXXXX").string() + suffix;
    const int fd = mkstemps(templ.data(), static_cast<int>(suffix.size()));
    if (fd < 0) std::abort();
    ::close(fd);
    name = templ;
    static struct Remover {
      ~Remover() {
        for (const auto& [s, n] : names) std::remove(n.c_str());
      }
    } remover;
  }
  std::ofstream out(name, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  out.close();
  if (!out) std::abort();
  return name;
}

void write_seed(const std::string& dir, const std::string& name, const Bytes& b) {
  std::ofstream out(std::filesystem::path(dir) / name, std::ios::binary);
  out.write(reinterpret_cast<const char*>(b.data()), static_cast<std::streamsize>(b.size()));
  if (!out) std::abort();
}

Bytes gzip(const Bytes& in) {
  z_stream z{};
  deflateInit2(&z, 9, Z_DEFLATED, 16 + 15, 8, Z_DEFAULT_STRATEGY);  // 16 +: a gzip header
  Bytes out(deflateBound(&z, static_cast<uLong>(in.size())) + 32);
  z.next_in = const_cast<unsigned char*>(in.data());
  z.avail_in = static_cast<uInt>(in.size());
  z.next_out = out.data();
  z.avail_out = static_cast<uInt>(out.size());
  deflate(&z, Z_FINISH);
  out.resize(z.total_out);
  deflateEnd(&z);
  return out;
}

}  // namespace cube4::fuzz

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  if (const char* dir = std::getenv("CUBE4_FUZZ_SEEDS")) {
    std::filesystem::create_directories(dir);
    cube4::fuzz::write_seeds(dir);
    std::exit(0);
  }
  // Loaders run under a small memory limit, so that a header declaring a
  // huge volume is refused by the check rather than by the fuzzer's RSS limit.
  cube4::golden::set_memory_limit(uint64_t{64} << 20);
  return 0;
}
