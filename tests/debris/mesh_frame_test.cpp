// A mesh file's units and axes to fragsim's frame (metres, Y up, right-handed): each engine
// family's convention on a point whose meaning is known (1 m right, 2 m up, 3 m toward the
// viewer in fragsim's frame).

#include "debris/mesh_frame.hpp"

#include <gtest/gtest.h>

#include <Eigen/LU>

namespace fragsim {
namespace {

TEST(MeshFrame, EachConventionLandsTheSamePoint) {
  const Eigen::Vector3d want(1, 2, 3);
  // fragsim and glTF: as is, to the bit.
  EXPECT_EQ(to_fragsim_frame(MeshFrame{}, want), want);
  EXPECT_TRUE(MeshFrame{}.is_identity());
  // Unity: metres, Y up, left-handed, z away from the viewer.
  EXPECT_EQ(to_fragsim_frame({1.0, MeshUp::kY, MeshHandedness::kLeft}, {1, 2, -3}), want);
  // Blender: metres, Z up, right-handed, y away from the viewer (its glTF exporter's turn).
  EXPECT_EQ(to_fragsim_frame({1.0, MeshUp::kZ, MeshHandedness::kRight}, {1, -3, 2}), want);
  // Unreal: centimetres, Z up, left-handed: x forward, y right, z up. fragsim's x stays x and
  // its z (x cross y) is then Unreal's y.
  EXPECT_EQ(to_fragsim_frame({0.01, MeshUp::kZ, MeshHandedness::kLeft}, {100, 300, 200}), want);
}

TEST(MeshFrame, ALeftHandedFrameIsAMirror) {
  // The three file axes' images: a right-handed frame has determinant +1, a left one -1 (so a
  // left-handed file's hulls are recomputed, not their faces reused).
  for (MeshUp up : {MeshUp::kY, MeshUp::kZ}) {
    for (MeshHandedness h : {MeshHandedness::kRight, MeshHandedness::kLeft}) {
      Eigen::Matrix3d m;
      for (int k = 0; k < 3; ++k)
        m.col(k) = to_fragsim_frame({1.0, up, h}, Eigen::Vector3d::Unit(k));
      EXPECT_EQ(m.determinant(), h == MeshHandedness::kRight ? 1.0 : -1.0);
    }
  }
}

}  // namespace
}  // namespace fragsim
