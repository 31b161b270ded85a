#include "tb/output_files.hpp"

#include <dirent.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstring>
#include <filesystem>

#include "golden/errors.hpp"

namespace cube4::tb {
namespace {

namespace fs = std::filesystem;
using golden::InputError;

// Temporaries the signal handler removes: fixed storage, because a handler
// may call only async-signal-safe functions (unlink, rmdir), not allocate.
constexpr int kMaxTemps = 64;
constexpr size_t kMaxName = 4096;
char g_temps[kMaxTemps][kMaxName];
volatile sig_atomic_t g_is_dir[kMaxTemps];
volatile sig_atomic_t g_count = 0;

void on_signal(int sig) {
  for (int i = g_count - 1; i >= 0; --i) {
    if (g_temps[i][0] == 0) continue;
    if (g_is_dir[i]) ::rmdir(g_temps[i]);
    else ::unlink(g_temps[i]);
  }
  std::signal(sig, SIG_DFL);
  std::raise(sig);
}

void remember(const std::string& name, bool is_dir) {
  if (g_count >= kMaxTemps || name.size() >= kMaxName)
    throw InputError("too many outputs, or an output path longer than " + std::to_string(kMaxName) + " bytes");
  const int i = g_count;
  std::memcpy(g_temps[i], name.c_str(), name.size() + 1);
  g_is_dir[i] = is_dir;
  g_count = i + 1;
}

void forget(const std::string& name) {
  for (int i = 0; i < g_count; ++i)
    if (name == g_temps[i]) g_temps[i][0] = 0;
}

// Holds SIGINT, SIGTERM and SIGHUP back while a temporary is created and
// registered: a signal between the two would leave it behind.
class SignalsHeld {
 public:
  SignalsHeld() {
    sigset_t s;
    sigemptyset(&s);
    for (int sig : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&s, sig);
    ::sigprocmask(SIG_BLOCK, &s, &old_);
  }
  ~SignalsHeld() { ::sigprocmask(SIG_SETMASK, &old_, nullptr); }
  SignalsHeld(const SignalsHeld&) = delete;
  SignalsHeld& operator=(const SignalsHeld&) = delete;

 private:
  sigset_t old_;
};

mode_t file_mode() {
  // mkstemp makes files 0600; outputs get what the user's umask gives.
  const mode_t mask = ::umask(0);
  ::umask(mask);
  return 0666 & ~mask;
}

std::string folder_of(const std::string& path) {
  const fs::path parent = fs::path(path).parent_path();
  return parent.empty() ? std::string(".") : parent.string();
}

// flush to the disk, so a full disk or an I/O error shows here, not later.
void sync_file(const std::string& temp, const std::string& dest, const std::string& what) {
  const int fd = ::open(temp.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) throw InputError(what + " '" + dest + "': cannot reopen the written file (" + std::strerror(errno) + ")");
  struct stat st {};
  const bool ok_stat = ::fstat(fd, &st) == 0;
  const bool synced = ::fsync(fd) == 0 || errno == EINVAL;  // EINVAL: the file system cannot sync (fine)
  const int e = errno;
  ::close(fd);
  if (!synced) throw InputError(what + " '" + dest + "': cannot write (" + std::strerror(e) + ")");
  if (!ok_stat || st.st_size == 0) throw InputError(what + " '" + dest + "': the written file is empty");
}

std::vector<std::string> folder_entries(const std::string& dir) {
  std::vector<std::string> out;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(dir, ec)) out.push_back(e.path().filename().string());
  return out;
}

}  // namespace

std::string trace_file_for(const std::string& file, const std::string& unit) {
  const auto dot = file.rfind(".fst");
  const std::string stem = dot == std::string::npos ? file : file.substr(0, dot);
  return stem + "." + unit + ".fst";
}

OutputSet::OutputSet() {
  for (int sig : {SIGINT, SIGTERM, SIGHUP}) std::signal(sig, on_signal);
}

OutputSet::~OutputSet() { discard(); }

void OutputSet::check_destination(const std::string& path, const std::string& what) {
  if (path.empty()) throw InputError(what + ": the file name is empty");
  const std::string dir = folder_of(path);
  std::error_code ec;
  const fs::file_status ds = fs::status(dir, ec);
  if (!fs::exists(ds)) throw InputError(what + " '" + path + "': the folder '" + dir + "' does not exist");
  if (!fs::is_directory(ds)) throw InputError(what + " '" + path + "': '" + dir + "' is not a folder");
  const fs::file_status st = fs::status(path, ec);
  if (fs::is_directory(st)) throw InputError(what + " '" + path + "' is a folder; name a file");
  if (fs::exists(st) && !fs::is_regular_file(st))
    throw InputError(what + " '" + path + "' exists and is not a regular file (a device or FIFO is not replaced)");
  const std::string canonical = fs::weakly_canonical(path, ec).string();
  for (size_t i = 0; i < dests_.size(); ++i)
    if (dests_[i] == canonical)
      throw InputError(what + " '" + path + "' is a file another output of this run also writes");
  dests_.push_back(canonical);
}

void OutputSet::check_not_output(const std::string& path, const std::string& what) const {
  std::error_code ec;
  const std::string canonical = fs::weakly_canonical(path, ec).string();
  for (const std::string& d : dests_)
    if (d == canonical) throw InputError(what + " '" + path + "' is also an output of this run; it would be replaced");
}

std::string OutputSet::add(const std::string& path, const std::string& what) {
  check_destination(path, what);
  // A symbolic link is followed: the file it names is replaced, as writing
  // in place would have done, and the temporary goes in that file's folder.
  std::error_code ec;
  const std::string dest = fs::is_symlink(path, ec) ? fs::weakly_canonical(path, ec).string() : path;
  const std::string ext = fs::path(dest).extension().string();
  std::string temp = (fs::path(folder_of(dest)) / ("." + fs::path(dest).stem().string() + ".tmp-XXXXXX" + ext)).string();
  const SignalsHeld held;
  const int fd = ::mkstemps(temp.data(), static_cast<int>(ext.size()));
  if (fd < 0)
    throw InputError(what + " '" + path + "': cannot create a file in '" + folder_of(dest) + "' (" +
                     std::strerror(errno) + ")");
  ::fchmod(fd, file_mode());
  ::close(fd);
  remember(temp, false);
  entries_.push_back({dest, temp, what, false});
  return temp;
}

std::string OutputSet::add_trace(const std::string& path, const std::vector<std::string>& suffixes) {
  check_destination(path, "--trace");
  for (const std::string& s : suffixes) check_destination(trace_file_for(path, s), "--trace");
  const std::string dir = folder_of(path);
  std::string temp = (fs::path(dir) / ("." + fs::path(path).stem().string() + ".tmp-XXXXXX")).string();
  const SignalsHeld held;
  if (!::mkdtemp(temp.data()))
    throw InputError("--trace '" + path + "': cannot create a folder in '" + dir + "' (" + std::strerror(errno) + ")");
  // The signal handler removes the files before the folder (it walks back).
  remember(temp, true);
  const std::string inside = (fs::path(temp) / fs::path(path).filename()).string();
  for (const std::string& s : suffixes) remember(trace_file_for(inside, s), false);
  entries_.push_back({path, temp, "--trace", true});
  return inside;
}

void OutputSet::commit() {
  for (const Entry& e : entries_) {
    if (!e.trace) {
      sync_file(e.temp, e.dest, e.what);
      continue;
    }
    const auto files = folder_entries(e.temp);
    if (files.empty()) throw InputError("--trace '" + e.dest + "': no trace was written");
    for (const std::string& f : files) sync_file((fs::path(e.temp) / f).string(), e.dest, e.what);
  }
  // Renames in one folder do not fail for want of space; what could fail
  // (a folder that vanished) is reported, and the rest stay temporaries.
  for (Entry& e : entries_) {
    if (!e.trace) {
      if (::rename(e.temp.c_str(), e.dest.c_str()) != 0)
        throw InputError(e.what + " '" + e.dest + "': cannot replace the file (" + std::strerror(errno) + ")");
      forget(e.temp);
      e.temp.clear();
      continue;
    }
    const std::string dir = folder_of(e.dest);
    for (const std::string& f : folder_entries(e.temp)) {
      const std::string from = (fs::path(e.temp) / f).string(), to = (fs::path(dir) / f).string();
      if (::rename(from.c_str(), to.c_str()) != 0)
        throw InputError("--trace '" + to + "': cannot replace the file (" + std::strerror(errno) + ")");
      forget(from);
    }
    ::rmdir(e.temp.c_str());
    forget(e.temp);
    e.temp.clear();
  }
  entries_.clear();
}

void OutputSet::discard() {
  for (const Entry& e : entries_) {
    if (e.temp.empty()) continue;
    if (e.trace) {
      for (const std::string& f : folder_entries(e.temp)) {
        const std::string name = (fs::path(e.temp) / f).string();
        ::unlink(name.c_str());
        forget(name);
      }
      ::rmdir(e.temp.c_str());
    } else {
      ::unlink(e.temp.c_str());
    }
    forget(e.temp);
  }
  entries_.clear();
}

}  // namespace cube4::tb
