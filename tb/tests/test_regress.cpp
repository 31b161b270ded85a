// cube4 regress: a scene set at several levels in parallel, its JUnit XML
// valid against the schema CI servers read (tb/junit.xsd, checked with
// xmllint), bad scenes reported as errors naming the fault, bad input refused.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace {

namespace fs = std::filesystem;

std::string read(const fs::path& p) {
  std::ifstream f(p);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

int exit_code(const std::string& cmd) {
  const int status = std::system(cmd.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

size_t count(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t i = text.find(what); i != std::string::npos; i = text.find(what, i + 1)) ++n;
  return n;
}

fs::path scratch(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("cube4_test_regress_" + name + "_" + std::to_string(getpid()));
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

void expect_valid_junit(const fs::path& xml) {
  if (exit_code("command -v xmllint >/dev/null") != 0) GTEST_SKIP() << "xmllint not installed (libxml2-utils)";
  EXPECT_EQ(exit_code("xmllint --noout --schema " CUBE4_SOURCE_DIR "/tb/junit.xsd " + xml.string() + " 2>/dev/null"), 0)
      << read(xml);
}

#ifdef CUBE4_HAVE_RTL
constexpr const char* kLevels = "fixed tlm rtl";
constexpr size_t kLevelCount = 3;
#else
constexpr const char* kLevels = "fixed tlm";  // a build without the RTL
constexpr size_t kLevelCount = 2;
#endif

TEST(Regress, SceneSetAtEveryLevelPassesWithValidJUnit) {
  const fs::path d = scratch("set");
  const std::string cmd = std::string(CUBE4_BINARY) + " regress " CUBE4_SOURCE_DIR "/scenes/regress -q -j 2 " +
                          "--levels " + kLevels + " --junit " + (d / "r.xml").string() + " --summary " +
                          (d / "r.md").string();
  ASSERT_EQ(exit_code(cmd), 0);
  const std::string xml = read(d / "r.xml");
  const size_t scenes = static_cast<size_t>(std::distance(fs::directory_iterator(CUBE4_SOURCE_DIR "/scenes/regress"),
                                                          fs::directory_iterator{}));
  EXPECT_EQ(count(xml, "<testcase "), kLevelCount * scenes);
  EXPECT_EQ(count(xml, "<failure"), 0u);
  EXPECT_EQ(count(xml, "<error"), 0u);
  EXPECT_NE(read(d / "r.md").find("0 failed, 0 errors"), std::string::npos);
  expect_valid_junit(d / "r.xml");
  fs::remove_all(d);
}

TEST(Regress, ABadSceneIsAnErrorCaseNamingTheKey) {
  const fs::path d = scratch("bad");
  std::ofstream(d / "bad.json") << R"({"volume": {"synthetic": "sphere", "size": [8, 8, 8]}, "colour": 1})";
  std::ofstream(d / "list.txt") << "# one good, one bad\n" CUBE4_SOURCE_DIR "/scenes/regress/noise_mip.json\nbad.json\n";
  const std::string cmd = std::string(CUBE4_BINARY) + " regress " + (d / "list.txt").string() +
                          " -q --levels fixed tlm --junit " + (d / "r.xml").string();
  EXPECT_EQ(exit_code(cmd), 2);
  const std::string xml = read(d / "r.xml");
  EXPECT_EQ(count(xml, "<testcase "), 4u);
  EXPECT_EQ(count(xml, "<error"), 2u) << xml;
  EXPECT_NE(xml.find("unknown key &quot;colour&quot;"), std::string::npos) << xml;
  expect_valid_junit(d / "r.xml");
  fs::remove_all(d);
}

TEST(Regress, BadInputIsRefused) {
  const fs::path d = scratch("input");
  const std::string bin = std::string(CUBE4_BINARY) + " regress ";
  EXPECT_EQ(exit_code(bin + (d / "missing").string() + " -q --junit " + (d / "r.xml").string() + " 2>/dev/null"), 2);
  EXPECT_EQ(exit_code(bin + d.string() + " -q --junit " + (d / "r.xml").string() + " 2>/dev/null"), 2)
      << "a folder without scenes";
  EXPECT_EQ(exit_code(bin + CUBE4_SOURCE_DIR "/scenes/regress --levels gpu -q --junit " + (d / "r.xml").string() +
                      " 2>/dev/null"),
            2);
  EXPECT_FALSE(fs::exists(d / "r.xml")) << "nothing written for refused input";
  fs::remove_all(d);
}

}  // namespace
