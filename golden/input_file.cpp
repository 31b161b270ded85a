#include "golden/input_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>

#include "golden/errors.hpp"

namespace cube4::golden {

namespace {
uint64_t g_limit = kDefaultMemoryLimit;

std::string mib(double bytes) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.0f MiB", bytes / (1024.0 * 1024.0));
  return buf;
}

const char* kind_of(mode_t m) {
  if (S_ISDIR(m)) return "it is a directory";
  if (S_ISFIFO(m)) return "it is a FIFO, not a regular file";
  if (S_ISCHR(m) || S_ISBLK(m)) return "it is a device, not a regular file";
  if (S_ISSOCK(m)) return "it is a socket, not a regular file";
  return "not a regular file";
}
}  // namespace

uint64_t memory_limit() { return g_limit; }
void set_memory_limit(uint64_t bytes) { g_limit = bytes; }

void check_memory(const std::string& path, const std::string& what, double bytes, const std::string& detail) {
  if (bytes <= static_cast<double>(g_limit)) return;
  throw InputError(path + ": " + what + " needs about " + mib(bytes) + " (" + detail +
                   "), more than the memory limit of " + mib(static_cast<double>(g_limit)) +
                   " (raise it with --max-memory MiB)");
}

double volume_load_bytes(double voxels, double sample_bytes) { return voxels * (sample_bytes + 2.0); }

int open_regular_file(const std::string& path, const std::string& what) {
  // O_NONBLOCK: opening a FIFO for reading would otherwise wait for a writer.
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) throw InputError(path + ": cannot open " + what + " (" + std::strerror(errno) + ")");
  struct stat st {};
  if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
    const int e = errno;
    const bool stat_failed = !S_ISREG(st.st_mode) && st.st_mode == 0;
    ::close(fd);
    throw InputError(path + ": cannot open " + what + " (" + (stat_failed ? std::strerror(e) : kind_of(st.st_mode)) +
                     ")");
  }
  const int flags = ::fcntl(fd, F_GETFL);
  if (flags >= 0) ::fcntl(fd, F_SETFL, flags & ~O_NONBLOCK);
  return fd;
}

void require_regular_file(const std::string& path, const std::string& what) {
  ::close(open_regular_file(path, what));
}

size_t read_fd(int fd, void* buf, size_t n, const std::string& path, const std::string& what) {
  auto* p = static_cast<unsigned char*>(buf);
  size_t got = 0;
  while (got < n) {
    const ssize_t r = ::read(fd, p + got, std::min<size_t>(n - got, size_t{1} << 30));
    if (r < 0 && errno == EINTR) continue;
    if (r < 0) throw InputError(path + ": cannot read " + what + " (" + std::strerror(errno) + ")");
    if (r == 0) break;
    got += static_cast<size_t>(r);
  }
  return got;
}

FdCloser::~FdCloser() { ::close(fd); }

std::string dims_text(int x, int y, int z) {
  return std::to_string(x) + "x" + std::to_string(y) + "x" + std::to_string(z);
}

}  // namespace cube4::golden
