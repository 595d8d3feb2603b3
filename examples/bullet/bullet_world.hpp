// Bullet's side of the example: a btDiscreteDynamicsWorld (floats, as Debian's libbullet-dev
// builds it) with a ground plane at y = 0, gravity -9.81 y, and one small box per fragment.
#pragma once

#include <btBulletDynamicsCommon.h>

#include <memory>
#include <vector>

#include "blast.hpp"

constexpr double kGravity_mps2 = 9.81;  // along -y

class BulletWorld {
 public:
  // Fragments collide with the ground only (fragsim's default scenes), or with each other too.
  BulletWorld(const std::vector<FragmentStart>& blast, bool fragment_collisions);
  ~BulletWorld();
  BulletWorld(const BulletWorld&) = delete;
  BulletWorld& operator=(const BulletWorld&) = delete;

  btDiscreteDynamicsWorld& world() { return *world_; }
  int fragment_count() const { return static_cast<int>(fragments_.size()); }
  btRigidBody& fragment(int i) { return *fragments_[i]; }
  double bounding_radius_m(int i) const { return bounding_radius_m_[i]; }
  double mass_kg(int i) const { return mass_kg_[i]; }

 private:
  // Declared in the order they depend on each other: the world, destroyed first, still reaches
  // the broadphase and the bodies while it takes them out.
  std::unique_ptr<btDefaultCollisionConfiguration> configuration_;
  std::unique_ptr<btCollisionDispatcher> dispatcher_;
  std::unique_ptr<btDbvtBroadphase> broadphase_;
  std::unique_ptr<btSequentialImpulseConstraintSolver> solver_;
  std::vector<std::unique_ptr<btCollisionShape>> shapes_;
  std::unique_ptr<btRigidBody> ground_;
  std::vector<std::unique_ptr<btRigidBody>> fragments_;
  std::unique_ptr<btDiscreteDynamicsWorld> world_;
  std::vector<double> bounding_radius_m_;
  std::vector<double> mass_kg_;
};
