// Slow system tests (ctest label `slow`, `scripts/test.sh --slow`): the
// larger rows of Cube-4's Table 1 that have an RTL build (p = 8) simulated
// at RTL, so docs/performance.md's cycle counts are checked against the RTL
// at full size, and brainsmall from further views. Results of the last run
// are recorded in docs/performance.md.
#include "tb/tests/system_support.hpp"

namespace {

using namespace cube4::test;

TEST(SystemSlow, Table1Row128P8) {
  Case c;
  c.volume = R"({"synthetic": "sphere", "size": [128, 128, 128]})";
  c.direction = "[0, 0, 1]";
  run(c, 8, kRtl);
}

TEST(SystemSlow, Table1Row256P8) {
  Case c;
  c.volume = R"({"synthetic": "sphere", "size": [256, 256, 256]})";
  c.direction = "[0, 0, 1]";
  run(c, 8, kRtl);
}

// The VolumePro configuration's p at full size: 256³ with 4 pipelines.
TEST(SystemSlow, VolumePro256P4) {
  Case c;
  c.volume = R"({"synthetic": "sphere", "size": [256, 256, 256]})";
  c.direction = "[0.2, 0.1, 1]";
  run(c, 4, kRtl);
}

class BrainViews : public ::testing::TestWithParam<const char*> {};
TEST_P(BrainViews, AllRtlP5) {
  Case c;
  c.volume = std::string(R"({"file": ")") + CUBE4_BRAINSMALL + R"("})";
  c.direction = GetParam();
  run(c, 5, kRtl);
}
INSTANTIATE_TEST_SUITE_P(SystemSlow, BrainViews,
                         ::testing::Values("[1, 0.3, 0.2]", "[-0.2, 1, 0.4]", "[0.3, 0.2, -1]"));

}  // namespace
