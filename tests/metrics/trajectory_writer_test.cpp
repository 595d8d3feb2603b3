// trajectories.csv's rows, exactly: one per fragment per snapshot (step 0 included), tagged with
// the strategy, with that step's candidate flag and force and nothing carried into the next step.

#include "metrics/trajectory_writer.hpp"

#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

namespace fragsim {
namespace {

TEST(TrajectoryWriter, WritesOneRowPerFragmentAndStepWithThatStepsFlagAndForce) {
  std::ostringstream out;
  TrajectoryWriter writer(out);
  std::vector<FragmentState> frags(2);
  frags[0].position_m = {1.0, 2.0, 3.0};
  frags[0].velocity_mps = {0.0, 0.0, -1.0};
  frags[1].position_m = {0.5, 0.0, -4.0};

  StepSnapshot snap;
  snap.fragments = frags;
  writer.begin({nullptr, "edge", 2, 2, 0.25}, snap);
  // Step 1: fragment 1 is a candidate and pushed up by 2 N.
  const std::vector<int> candidates{1};
  const std::vector<AppliedForce> forces{{1, {0.0, 2.0, 0.0}}};
  frags[0].position_m.z() = 2.75;
  snap.step = 1;
  snap.t_s = 0.25;
  snap.candidates = candidates;
  snap.forces = forces;
  writer.observe(snap);
  // Step 2: no candidates, no forces.
  snap = {};
  snap.fragments = frags;
  snap.step = 2;
  snap.t_s = 0.5;
  writer.observe(snap);
  writer.end();

  EXPECT_EQ(out.str(),
            "strategy,step,t_s,fragment,x_m,y_m,z_m,vx_mps,vy_mps,vz_mps,candidate,fx_N,fy_N,fz_N,"
            "qx,qy,qz,qw\n"
            "edge,0,0,0,1,2,3,0,0,-1,0,0,0,0,0,0,0,1\n"
            "edge,0,0,1,0.5,0,-4,0,0,0,0,0,0,0,0,0,0,1\n"
            "edge,1,0.25,0,1,2,2.75,0,0,-1,0,0,0,0,0,0,0,1\n"
            "edge,1,0.25,1,0.5,0,-4,0,0,0,1,0,2,0,0,0,0,1\n"
            "edge,2,0.5,0,1,2,2.75,0,0,-1,0,0,0,0,0,0,0,1\n"
            "edge,2,0.5,1,0.5,0,-4,0,0,0,0,0,0,0,0,0,0,1\n");
}

TEST(TrajectoryWriter, EachRunIsTaggedWithItsStrategyUnderOneHeader) {
  std::ostringstream out;
  TrajectoryWriter writer(out);
  std::vector<FragmentState> frags(1);
  frags[0].position_m = {0.0, 1.6, -10.0};
  StepSnapshot snap;
  snap.fragments = frags;
  for (const char* strategy : {"none", "wall"}) {
    writer.begin({nullptr, strategy, 1, 0, 1.0 / 60.0}, snap);
    writer.end();
  }
  EXPECT_EQ(out.str(), std::string(TrajectoryWriter::header()) +
                           "none,0,0,0,0,1.6,-10,0,0,0,0,0,0,0,0,0,0,1\n"
                           "wall,0,0,0,0,1.6,-10,0,0,0,0,0,0,0,0,0,0,1\n");
}

// The orientation, a unit quaternion x y z w with w >= 0: a half turn about x is (1, 0, 0, 0).
TEST(TrajectoryWriter, WritesEachFragmentsOrientationAsAUnitQuaternion) {
  std::ostringstream out;
  TrajectoryWriter writer(out);
  std::vector<FragmentState> frags(1);
  frags[0].rotation = Eigen::Vector3d(1, -1, -1).asDiagonal();
  StepSnapshot snap;
  snap.fragments = frags;
  writer.begin({nullptr, "none", 1, 0, 1.0 / 60.0}, snap);
  writer.end();
  EXPECT_EQ(out.str(),
            std::string(TrajectoryWriter::header()) + "none,0,0,0,0,0,0,0,0,0,0,0,0,0,1,0,0,0\n");
}

}  // namespace
}  // namespace fragsim
