#include <cmath>
#include <random>
#include <stdexcept>
#include <string>

#include "debris/convex_hull.hpp"
#include "debris/debris_def.hpp"
#include "debris/mesh_file.hpp"
#include "io/input_error.hpp"

#include <voro++.hh>

namespace fragsim {
namespace {

std::vector<Piece> grid_pieces(const DebrisDef& def) {
  // The cubes come from the same expressions in the same order as the pinned grid results were made
  // with, so a grid scene's results do not change by a bit.
  const int n = def.splits;
  const double cell_m = def.size_m / n;
  const double half_m = 0.5 * cell_m * (1.0 - def.gap);
  const double mass_kg = def.density_kgpm3 * std::pow(2.0 * half_m, 3);
  std::vector<Piece> out;
  out.reserve(static_cast<std::size_t>(n) * n * n);
  for (int iz = 0; iz < n; ++iz) {
    for (int iy = 0; iy < n; ++iy) {
      for (int ix = 0; ix < n; ++ix) {
        Piece p;
        p.centre_m = Eigen::Vector3d((ix + 0.5) * cell_m - 0.5 * def.size_m,
                                     (iy + 0.5) * cell_m - 0.5 * def.size_m,
                                     (iz + 0.5) * cell_m - 0.5 * def.size_m);
        p.half_extents_m = Eigen::Vector3d::Constant(half_m);
        p.mass_kg = mass_kg;
        out.push_back(p);
      }
    }
  }
  return out;
}

// Uniform numbers that are the same with every standard library, because std::mt19937_64 is
// specified bit for bit and std::uniform_real_distribution is not (the same rule as sim/random.hpp,
// which debris, below sim, cannot include).
class SeedPoints {
 public:
  // The seed is mixed (splitmix64) so the cells' stream is not the explosion's, which
  // simulation.seed also starts.
  explicit SeedPoints(std::uint64_t seed) : engine_(mix(seed)) {}
  double uniform() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }

 private:
  static std::uint64_t mix(std::uint64_t x) {
    x += 0x9e3779b97f4a7c15ull;
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
    return x ^ (x >> 31);
  }
  std::mt19937_64 engine_;
};

// `pieces` points strictly inside the cube of half edge h about the origin, drawn from a density
// that is uniform within r_core of the blast point b and falls off as (r / r_core)^(-3 cluster)
// beyond. Cells shrink toward the blast, but no cell is smaller than the core's, where a pure power
// law would put a cell of 1e-15 m^3 at b. r_core is half the mean spacing of uniform cells,
// size / (2 pieces^(1/3)). A point is drawn in the ball about b that holds the cube (radius R, in a
// uniform direction, at the distance whose share of the ball's mass is a uniform number) and kept
// if inside the cube. With x = r / r_core and a = 1 - cluster the mass within x is x^3 / 3 for
// x <= 1 and 1/3 + (x^(3a) - 1) / (3a) beyond, inverted in closed form; cluster = 0 is uniform.
std::vector<Eigen::Vector3d> seed_points(const DebrisDef& def) {
  SeedPoints rng(def.seed);
  const double h = 0.5 * def.size_m;
  const Eigen::Vector3d b = def.blast_offset_m;
  double r_max = 0.0;
  for (int c = 0; c < 8; ++c) {
    const Eigen::Vector3d corner(c & 1 ? h : -h, c & 2 ? h : -h, c & 4 ? h : -h);
    r_max = std::max(r_max, (corner - b).norm());
  }
  const double r_core = 0.5 * def.size_m / std::cbrt(static_cast<double>(def.pieces));
  const double a3 = 3.0 * (1.0 - def.cluster);
  const double x_max = r_max / r_core;  // > 1, because r_max is at least the half diagonal
  const double mass_max = 1.0 / 3.0 + (std::pow(x_max, a3) - 1.0) / a3;
  std::vector<Eigen::Vector3d> out;
  out.reserve(static_cast<std::size_t>(def.pieces));
  // A blast far outside the object could make acceptance too rare to wait for.
  const long long max_draws = 10000LL * def.pieces + 100000;
  for (long long draws = 0; static_cast<int>(out.size()) < def.pieces; ++draws) {
    if (draws > max_draws) {
      // Bad input (legal keys that together cannot be made), so InputError, one line, status 2.
      throw InputError(
          "voronoi: the blast point is too far from the object for its seed points to land in "
          "it (explosion.offset_m)");
    }
    Eigen::Vector3d dir;
    do {
      dir = Eigen::Vector3d(2 * rng.uniform() - 1, 2 * rng.uniform() - 1, 2 * rng.uniform() - 1);
    } while (dir.squaredNorm() > 1.0 || dir.squaredNorm() < 1e-12);
    const double m = rng.uniform() * mass_max;
    const double x =
        m <= 1.0 / 3.0 ? std::cbrt(3.0 * m) : std::pow(1.0 + a3 * (m - 1.0 / 3.0), 1.0 / a3);
    const Eigen::Vector3d p = b + x * r_core * dir.normalized();
    if ((p.array().abs() < h).all()) out.push_back(p);
  }
  return out;
}

std::vector<Piece> voronoi_pieces(const DebrisDef& def) {
  const std::vector<Eigen::Vector3d> seeds = seed_points(def);
  const double h = 0.5 * def.size_m;
  // About five points per block is voro++'s documented sweet spot.
  const int blocks = std::max(1, static_cast<int>(std::cbrt(def.pieces / 5.0)));
  voro::container con(-h, h, -h, h, -h, h, blocks, blocks, blocks, false, false, false, 8);
  for (std::size_t i = 0; i < seeds.size(); ++i) {
    con.put(static_cast<int>(i), seeds[i].x(), seeds[i].y(), seeds[i].z());
  }
  std::vector<Piece> out(seeds.size());
  std::vector<bool> done(seeds.size(), false);
  voro::c_loop_all loop(con);
  voro::voronoicell cell;
  if (loop.start()) {
    do {
      if (!con.compute_cell(cell, loop)) continue;
      const int id = loop.pid();
      double x = 0.0;
      double y = 0.0;
      double z = 0.0;
      loop.pos(x, y, z);
      std::vector<double> xyz;
      cell.vertices(x, y, z, xyz);
      std::vector<Eigen::Vector3d> points;
      for (std::size_t k = 0; k + 2 < xyz.size(); k += 3) {
        points.emplace_back(xyz[k], xyz[k + 1], xyz[k + 2]);
      }
      HullPiece hull;
      try {
        hull = convex_hull(points);
      } catch (const DegenerateHull& e) {
        throw InputError(
            "voronoi: cell " + std::to_string(id + 1) + ": " + e.what() +
            " (fewer object.pieces, a smaller object.cluster or a larger object.size_m)");
      }
      Piece& p = out[static_cast<std::size_t>(id)];
      p.centre_m = hull.centre_m;
      p.shape = def.gap > 0.0 ? scaled_shape(*hull.shape, 1.0 - def.gap) : hull.shape;
      p.half_extents_m = p.shape->half_extents_m;
      p.mass_kg = def.density_kgpm3 * p.shape->volume_m3;
      done[static_cast<std::size_t>(id)] = true;
    } while (loop.inc());
  }
  for (std::size_t i = 0; i < done.size(); ++i) {
    // voro++ works to absolute tolerances, so cells of a few micrometres can come out empty.
    if (!done[i]) {
      throw InputError("voronoi: voro++ made no cell " + std::to_string(i + 1) +
                       " (cells too small for it: a larger object.size_m or fewer object.pieces)");
    }
  }
  return out;
}

}  // namespace

double piece_volume_m3(const Piece& piece) {
  return piece.shape ? piece.shape->volume_m3 : 8.0 * piece.half_extents_m.prod();
}

std::vector<Piece> make_pieces(const DebrisDef& def) {
  if (!def.mesh_file.empty()) return read_pieces(def.mesh_file, def.density_kgpm3, def.mesh_frame);
  return def.pattern == DebrisPattern::kVoronoi ? voronoi_pieces(def) : grid_pieces(def);
}

}  // namespace fragsim
