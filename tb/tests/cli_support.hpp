// The cube4 command run from a test: a scratch folder per test and the
// command's exit code, stderr and stdout.
#pragma once
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace cube4::test {

namespace fs = std::filesystem;

struct CliResult {
  int code = -1;
  std::string err, out;
};

class Cli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir = fs::temp_directory_path() / ("cube4_cli_" + std::to_string(::getpid()) + "_" +
                                       ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir);
  }
  void TearDown() override { fs::remove_all(dir); }

  std::string path(const std::string& name) const { return (dir / name).string(); }

  std::string write(const std::string& name, const std::string& text) const {
    std::ofstream(path(name)) << text;
    return path(name);
  }

  // `shell` runs before the command in the same bash (a ulimit, a trap);
  // `wrapper` runs it ("timeout 20").
  CliResult run(const std::string& args, const std::string& shell = "", const std::string& wrapper = "") const {
    return run_line(shell + (shell.empty() ? "" : "; ") + "exec " + wrapper + (wrapper.empty() ? "" : " ") +
                    CUBE4_BINARY + " " + args);
  }
  // Any command line, run by bash (a script of the repository, say).
  CliResult run_line(const std::string& line) const {
    const std::string err_file = path("stderr.txt"), out_file = path("stdout.txt");
    const std::string cmd = "bash -c '" + line + "' >" + out_file + " 2>" + err_file;
    const int status = std::system(cmd.c_str());
    CliResult r;
    r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    std::ifstream in(err_file), out(out_file);
    r.err.assign(std::istreambuf_iterator<char>(in), {});
    r.out.assign(std::istreambuf_iterator<char>(out), {});
    return r;
  }

  fs::path dir;
};

}  // namespace cube4::test
