// What every loader does before it reads a byte: refuse what is not a
// regular file (a FIFO or a device would block or never end), and refuse a
// volume whose declared size would exhaust memory, against a stated limit
// (docs/reliability.md), before anything is allocated.
#pragma once
#include <cstddef>
#include <cstdint>
#include <string>

namespace cube4::golden {

// Default 4 GiB; cube4 --max-memory raises or lowers it.
constexpr uint64_t kDefaultMemoryLimit = uint64_t{4} << 30;
uint64_t memory_limit();
void set_memory_limit(uint64_t bytes);

// Throws InputError "<path>: <what> needs about N MiB (<detail>), more than
// the memory limit of L MiB (--max-memory)" when bytes exceed the limit.
void check_memory(const std::string& path, const std::string& what, double bytes, const std::string& detail);

// Bytes a loader holds for a volume: the file's samples plus the quantised copy.
double volume_load_bytes(double voxels, double sample_bytes);

// Opens `path` for reading without blocking on a FIFO, and returns the
// descriptor only if it names a regular file; otherwise throws InputError
// "<path>: cannot open <what> (reason)". The caller closes it.
int open_regular_file(const std::string& path, const std::string& what);
// The same check for loaders that open by name (niftilib).
void require_regular_file(const std::string& path, const std::string& what);

// Reads until n bytes or the end of the file; returns how many were read.
// A read error throws InputError "<path>: cannot read <what> (reason)".
size_t read_fd(int fd, void* buf, size_t n, const std::string& path, const std::string& what);

// Closes a descriptor when it goes out of scope.
struct FdCloser {
  int fd;
  ~FdCloser();
};

// "2048x2048x1024"
std::string dims_text(int x, int y, int z);

}  // namespace cube4::golden
