// Pieces of files in other units and axes (object.mesh_unit_m, mesh_up, mesh_handedness): the
// same object written Z up in centimetres and Y up in metres reads as the same pieces to the bit
// (whole metres: tinyobjloader reads a decimal fraction as mantissa * 5^-e * 2^-e, which rounds
// 0.578125 and 57.8125 differently, so 1/64 m multiples agree only to 1e-16), a left-handed file as
// the mirrored object with outward faces, and an object 200 m across at unit 1 is warned about.

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "debris/mesh_file.hpp"

namespace fragsim {
namespace {

namespace fs = std::filesystem;

class MeshFileFrame : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("fragsim_frame_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  // Two pieces (an irregular hexahedron and a tetrahedron) in fragsim's frame, metres: every
  // coordinate a multiple of q (1/64 m unless set). `to_file` writes a point in the file's units
  // and axes.
  template <class ToFile>
  std::string write(const std::string& name, ToFile to_file, double q = 1.0 / 64) {
    const std::vector<std::vector<Eigen::Vector3d>> pieces = {{{0, 0, 0},
                                                               {37 * q, 0, 0},
                                                               {0, 29 * q, 0},
                                                               {35 * q, 31 * q, 0},
                                                               {0, 0, 41 * q},
                                                               {33 * q, 0, 43 * q},
                                                               {0, 27 * q, 45 * q},
                                                               {39 * q, 25 * q, 47 * q}},
                                                              {{-64 * q, 5 * q, 3 * q},
                                                               {-17 * q, 7 * q, 1 * q},
                                                               {-60 * q, 70 * q, 2 * q},
                                                               {-50 * q, 11 * q, 90 * q}}};
    std::string text;
    int base = 1;
    char line[160];
    for (std::size_t p = 0; p < pieces.size(); ++p) {
      text += "o piece" + std::to_string(p) + "\n";
      for (const auto& v : pieces[p]) {
        const Eigen::Vector3d f = to_file(v);
        std::snprintf(line, sizeof line, "v %.17g %.17g %.17g\n", f.x(), f.y(), f.z());
        text += line;
      }
      // Every point in one face: the hull is made from the points, whatever the winding.
      text += "f";
      for (std::size_t k = 0; k < pieces[p].size(); ++k) text += " " + std::to_string(base + k);
      text += "\n";
      base += static_cast<int>(pieces[p].size());
    }
    const std::string path = (dir_ / name).string();
    std::ofstream(path, std::ios::binary) << text;
    return path;
  }
  fs::path dir_;
};

void expect_same_bits(const std::vector<Piece>& a, const std::vector<Piece>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].centre_m, b[i].centre_m);
    EXPECT_EQ(a[i].mass_kg, b[i].mass_kg);
    EXPECT_EQ(a[i].shape->vertices_m, b[i].shape->vertices_m);
    EXPECT_EQ(a[i].shape->faces, b[i].shape->faces);
    EXPECT_EQ(a[i].shape->inertia_per_kg_m2, b[i].shape->inertia_per_kg_m2);
  }
}

TEST_F(MeshFileFrame, ZUpCentimetresReadAsYUpMetresToTheBit) {
  const auto metres = read_pieces(write(
                                      "m.obj", [](const Eigen::Vector3d& v) { return v; }, 1.0),
                                  600);
  // Blender-style Z up (y away from the viewer), in centimetres.
  const std::string cm = write(
      "cm.obj",
      [](const Eigen::Vector3d& v) {
        return Eigen::Vector3d(100 * v.x(), -100 * v.z(), 100 * v.y());
      },
      1.0);
  expect_same_bits(metres, read_pieces(cm, 600, {0.01, UpAxis::kZ, Handedness::kRight}));
  // Unreal-style: centimetres, Z up, left-handed (fragsim's z is its y).
  const std::string unreal = write(
      "ue.obj",
      [](const Eigen::Vector3d& v) {
        return Eigen::Vector3d(100 * v.x(), 100 * v.z(), 100 * v.y());
      },
      1.0);
  expect_same_bits(metres, read_pieces(unreal, 600, {0.01, UpAxis::kZ, Handedness::kLeft}));
  // At 1/64 m the two files agree to tinyobjloader's rounding of decimals.
  const auto fine = read_pieces(write("f.obj", [](const Eigen::Vector3d& v) { return v; }), 600);
  const auto fine_cm =
      read_pieces(write("fcm.obj",
                        [](const Eigen::Vector3d& v) {
                          return Eigen::Vector3d(100 * v.x(), -100 * v.z(), 100 * v.y());
                        }),
                  600, {0.01, UpAxis::kZ, Handedness::kRight});
  ASSERT_EQ(fine.size(), fine_cm.size());
  for (std::size_t i = 0; i < fine.size(); ++i) {
    EXPECT_NEAR(fine_cm[i].mass_kg / fine[i].mass_kg, 1.0, 1e-9);
    EXPECT_LE((fine_cm[i].centre_m - fine[i].centre_m).norm(), 1e-9 * fine[i].centre_m.norm());
  }
  // Read without the settings, the centimetre file is another, 100 times larger, object.
  EXPECT_NEAR(read_pieces(cm, 600)[0].mass_kg / metres[0].mass_kg, 1e6, 1e-6);
}

TEST_F(MeshFileFrame, ALeftHandedFileIsTheMirroredObjectWithOutwardFaces) {
  const std::string path = write("left.obj", [](const Eigen::Vector3d& v) { return v; });
  const auto right = read_pieces(path, 600);
  const auto left = read_pieces(path, 600, {1.0, UpAxis::kY, Handedness::kLeft});
  ASSERT_EQ(left.size(), right.size());
  const Eigen::Vector3d mirror(1, 1, -1);
  for (std::size_t i = 0; i < left.size(); ++i) {
    // The same hull from points in another order: equal to rounding.
    EXPECT_LT((left[i].centre_m - right[i].centre_m.cwiseProduct(mirror)).norm(), 1e-14);
    EXPECT_NEAR(left[i].mass_kg / right[i].mass_kg, 1.0, 1e-14);
    const ConvexShape& s = *left[i].shape;
    ASSERT_EQ(s.vertices_m.size(), right[i].shape->vertices_m.size());
    for (const auto& v : right[i].shape->vertices_m) {
      const Eigen::Vector3d m = v.cwiseProduct(mirror);
      double best = INFINITY;
      for (const auto& w : s.vertices_m) best = std::min(best, (w - m).norm());
      EXPECT_LT(best, 1e-14);
    }
    // Outward: every vertex on the inner side of every face, the centre strictly inside.
    for (std::size_t f = 0; f < s.faces.size(); ++f) {
      EXPECT_GT(s.offsets_m[f], 0.0);
      for (const auto& w : s.vertices_m) EXPECT_LE(s.normals[f].dot(w), s.offsets_m[f] + 1e-12);
    }
  }
}

TEST_F(MeshFileFrame, AnObjectHundredsOfMetresAcrossIsWarnedAbout) {
  const std::string cm = write("crate.obj", [](const Eigen::Vector3d& v) { return 100 * v; });
  std::vector<std::string> warnings;
  read_pieces(cm, 600, {}, &warnings);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0], cm + ": the object is 161 m across; if the file is in centimetres set "
                              "object.mesh_unit_m = 0.01");
  warnings.clear();
  read_pieces(cm, 600, {0.01}, &warnings);
  EXPECT_TRUE(warnings.empty());
}

}  // namespace
}  // namespace fragsim
