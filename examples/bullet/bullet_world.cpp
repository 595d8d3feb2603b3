#include "bullet_world.hpp"

#include <cmath>

namespace {

// Collision filter bits of our own, clear of Bullet's predefined btBroadphaseProxy groups.
constexpr int kGroundGroup = 1 << 6;
constexpr int kFragmentGroup = 1 << 7;

btVector3 to_bullet(Vec3 v) {
  return {static_cast<btScalar>(v.x), static_cast<btScalar>(v.y), static_cast<btScalar>(v.z)};
}

}  // namespace

BulletWorld::BulletWorld(const std::vector<FragmentStart>& blast, bool fragment_collisions)
    : configuration_(std::make_unique<btDefaultCollisionConfiguration>()),
      dispatcher_(std::make_unique<btCollisionDispatcher>(configuration_.get())),
      broadphase_(std::make_unique<btDbvtBroadphase>()),
      solver_(std::make_unique<btSequentialImpulseConstraintSolver>()) {
  world_ = std::make_unique<btDiscreteDynamicsWorld>(dispatcher_.get(), broadphase_.get(),
                                                     solver_.get(), configuration_.get());
  world_->setGravity(btVector3(0, static_cast<btScalar>(-kGravity_mps2), 0));

  shapes_.push_back(std::make_unique<btStaticPlaneShape>(btVector3(0, 1, 0), 0));
  ground_ = std::make_unique<btRigidBody>(0, nullptr, shapes_.back().get());
  ground_->setFriction(0.6f);
  ground_->setRestitution(0.2f);
  world_->addRigidBody(ground_.get(), kGroundGroup, kFragmentGroup);

  const int fragment_mask = fragment_collisions ? (kGroundGroup | kFragmentGroup) : kGroundGroup;
  for (const FragmentStart& start : blast) {
    const double half_m = 0.5 * start.size_m;
    shapes_.push_back(std::make_unique<btBoxShape>(btVector3(half_m, half_m, half_m)));
    btCollisionShape* shape = shapes_.back().get();
    const double mass_kg = kFragmentDensity_kgpm3 * start.size_m * start.size_m * start.size_m;
    btVector3 inertia(0, 0, 0);
    shape->calculateLocalInertia(static_cast<btScalar>(mass_kg), inertia);
    // No motion state: the example reads the physics' own transform, not a rendered one.
    btRigidBody::btRigidBodyConstructionInfo info(static_cast<btScalar>(mass_kg), nullptr, shape,
                                                  inertia);
    info.m_startWorldTransform.setOrigin(to_bullet(start.position_m));
    info.m_friction = 0.6f;
    info.m_restitution = 0.2f;
    auto body = std::make_unique<btRigidBody>(info);
    body->setLinearVelocity(to_bullet(start.velocity_mps));
    body->setAngularVelocity(to_bullet(start.spin_radps));
    world_->addRigidBody(body.get(), kFragmentGroup, fragment_mask);
    fragments_.push_back(std::move(body));
    bounding_radius_m_.push_back(half_m * std::sqrt(3.0));  // the cube's corner
    // The mass Bullet divides an impulse by, so the controller's force is the one applied.
    mass_kg_.push_back(1.0 / static_cast<double>(fragments_.back()->getInvMass()));
  }
}

BulletWorld::~BulletWorld() {
  for (auto& body : fragments_) world_->removeRigidBody(body.get());
  world_->removeRigidBody(ground_.get());
}
