// Progress lines (spec/outputs.md#progress): a stage that runs longer than the interval is
// reported by the heartbeat with its counts, a short one prints nothing.
#include <gtest/gtest.h>

#include "symmesh/mesh/progress.h"

#include <sstream>
#include <string>
#include <thread>

using namespace symmesh;

namespace {
std::size_t lines_with(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}
} // namespace

TEST(Progress, HeartbeatReportsALongStageAtLeastEveryInterval) {
  std::ostringstream os;
  {
    mesh::Progress p("symmesh test", os, 0.05);
    p.stage("meshing", 100, "triangles");
    p.set_done(42);
    std::this_thread::sleep_for(std::chrono::milliseconds(400));
    p.message("done");
  }
  const std::string text = os.str();
  // 400 ms at a 50 ms interval: several lines, each with the counts and the elapsed time.
  EXPECT_GE(lines_with(text, "symmesh test: meshing: 42/100 triangles ["), 3u) << text;
  EXPECT_EQ(lines_with(text, "symmesh test: done ["), 1u) << text;
}

TEST(Progress, ShortStagesAndStagesWithoutCountsStayQuietOrSayRunning) {
  std::ostringstream os;
  {
    mesh::Progress p("symmesh test", os, 5.0);
    p.stage("quick", 10, "items");
    p.message("quick: finished");
  }
  EXPECT_EQ(os.str().find("quick: 0"), std::string::npos) << os.str();
  std::ostringstream slow;
  {
    mesh::Progress p("symmesh test", slow, 0.05);
    p.stage("boundary patch partition", 0, "");
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
  }
  EXPECT_GE(lines_with(slow.str(), "boundary patch partition: running"), 1u) << slow.str();
}
