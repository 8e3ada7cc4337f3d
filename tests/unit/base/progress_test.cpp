#include "kernels/base/progress.h"

#include <gtest/gtest.h>

#include <vector>

using namespace selfsim;

namespace {

struct Recorder : Progress {
  std::vector<double> seen;
  bool stop = false;
  void fraction(double done) override { seen.push_back(done); }
  bool cancelled() override { return stop; }
};

}  // namespace

TEST(ProgressStage, MapsItsRangeIntoTheParents) {
  Recorder parent;
  ProgressStage stage(parent, 0.25, 0.75);
  stage.fraction(0);
  stage.fraction(0.5);
  stage.fraction(1);
  EXPECT_EQ(parent.seen, (std::vector<double>{0.25, 0.5, 0.75}));
}

TEST(ProgressStage, CancelsWhenTheParentDoes) {
  Recorder parent;
  ProgressStage stage(parent, 0, 0.1);
  EXPECT_NO_THROW(stage.step(0.5));
  parent.stop = true;
  EXPECT_TRUE(stage.cancelled());
  EXPECT_THROW(stage.step(0.6), Cancelled);
}
