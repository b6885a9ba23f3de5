// Bullet's btMultiBody (Debian libbullet-dev 3.24, its float64 build) on a `urdf` scene, for
// `appell score` (tests/engine_score.sh):
//   bullet_reference states SCENE N SEED        the joints' q and q' at N random states (CSV)
//   bullet_reference values SCENE STATES        Featherstone's forward dynamics, called directly
//                                               (computeAccelerationsArticulatedBodyAlgorithmMultiDof
//                                               with dt = 0): every moving joint's acceleration and
//                                               every joint's btMultiBodyJointFeedback
//   bullet_reference world-values SCENE STATES  the joint feedback a user reads after one
//                                               btMultiBodyDynamicsWorld::stepSimulation (dt = 1e-9)
//   bullet_reference world-check SCENE STATES   whether that stepped feedback is the direct one plus the
//                                               direct one of the same state without gravity (the
//                                               double count of Bullet 3.24's constraint pass, #4451):
//                                               exit 0 when it is, to 1e-7, and differs from the
//                                               direct feedback by more than 1e-5; 1 otherwise
//   bullet_reference time SCENE REPS            microseconds per forward dynamics with feedback
// Debian ships no URDF importer for Bullet (it lives in Bullet's examples): the multibody is built
// here from urdfdom's reading of the URDF (Debian liburdfdom-dev, the parser ROS uses), the way
// Bullet's importer does: each link's frame at its centre of mass on principal axes (Bullet takes
// a diagonal inertia), the tensor diagonalized by Eigen's self-adjoint solver (to the rounding of
// double; Bullet's importer calls its own Jacobi sweep with a threshold of 1e-6, which would score
// the importer and not the dynamics), fixed joints as setupFixed links, no damping.
//
// The feedback (btMultiBodyJointFeedback, m_jointFeedbackInJointFrame): the force and the moment
// about the joint's pivot that the parent exerts on the link's subtree, on the link's principal
// axes; turned here onto the link's URDF axes, appell's convention (SCENES.md, `urdf`).
#include <BulletCollision/BroadphaseCollision/btDbvtBroadphase.h>
#include <BulletCollision/CollisionDispatch/btCollisionDispatcher.h>
#include <BulletCollision/CollisionDispatch/btDefaultCollisionConfiguration.h>
#include <BulletDynamics/Featherstone/btMultiBody.h>
#include <BulletDynamics/Featherstone/btMultiBodyConstraintSolver.h>
#include <BulletDynamics/Featherstone/btMultiBodyDynamicsWorld.h>
#include <BulletDynamics/Featherstone/btMultiBodyJointFeedback.h>
#include <BulletDynamics/Featherstone/btMultiBodyLink.h>
#include <urdf_parser/urdf_parser.h>

#include <Eigen/Dense>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "engine_common.hpp"
#include "engine_floating.hpp"
#include <algorithm>
#include <array>

#ifndef BT_USE_DOUBLE_PRECISION
#error "bullet_reference scores Bullet's float64 build: compile with BT_USE_DOUBLE_PRECISION"
#endif

namespace {

using engine::appell_name;
using engine::g17;
using Eigen::Matrix3d;
using Eigen::Vector3d;

Vector3d vec(const urdf::Vector3& v) { return {v.x, v.y, v.z}; }
Matrix3d rot(const urdf::Rotation& r) { return Eigen::Quaterniond(r.w, r.x, r.y, r.z).normalized().toRotationMatrix(); }
btVector3 bt(const Vector3d& v) { return btVector3(v.x(), v.y(), v.z()); }
Vector3d ei(const btVector3& v) { return {v.x(), v.y(), v.z()}; }
btQuaternion btq(const Matrix3d& m) {
  const Eigen::Quaterniond q(m);
  return btQuaternion(q.x(), q.y(), q.z(), q.w());
}

using engine::read_scene;
using engine::read_state;
using engine::scene;

Vector3d gravity_of(const scene& s) { return {s.gravity[0], s.gravity[1], s.gravity[2]}; }

/// One link of the multibody: its URDF joint, and its principal frame on the URDF link's axes.
struct mb_link {
  std::string joint;  ///< the URDF joint's name
  bool moves = false;
  double mass = 0;
  Vector3d principal;  ///< principal moments
  Matrix3d R;          ///< principal axes on the link's axes
  Vector3d c;          ///< centre of mass on the link's axes
};

/// The principal frame of a URDF link's inertial (identity at the origin when it has none).
void principal_frame(const urdf::LinkConstSharedPtr& l, double& mass, Vector3d& moments, Matrix3d& R, Vector3d& c) {
  mass = 0, moments.setZero(), R.setIdentity(), c.setZero();
  if (!l->inertial) return;
  const auto& in = *l->inertial;
  mass = in.mass;
  Matrix3d I;
  I << in.ixx, in.ixy, in.ixz, in.ixy, in.iyy, in.iyz, in.ixz, in.iyz, in.izz;
  const Matrix3d Ri = rot(in.origin.rotation);
  c = vec(in.origin.position);
  if (I(0, 1) == 0 && I(0, 2) == 0 && I(1, 2) == 0) {  // already principal: no rounding added
    moments = I.diagonal();
    R = Ri;
    return;
  }
  Eigen::SelfAdjointEigenSolver<Matrix3d> eig(I);
  Matrix3d V = eig.eigenvectors();
  if (V.determinant() < 0) V.col(2) = -V.col(2);
  moments = eig.eigenvalues();
  R = Ri * V;
}

struct robot {
  std::unique_ptr<btMultiBody> body;
  bool floating = false;
  double base_mass = 0;
  Matrix3d base_R;   ///< the base's principal axes on the root link's
  Vector3d base_c;   ///< its centre of mass on the root link's axes
  std::vector<mb_link> links;                       ///< in Bullet's link order (parents first)
  std::vector<btMultiBodyJointFeedback> feedback;
  std::map<std::string, int> index;              ///< URDF joint name -> Bullet link index
};

robot build(const scene& s) {
  const std::string bare = engine::without_geometry(s.urdf, "bullet_reference");
  const urdf::ModelInterfaceSharedPtr model = urdf::parseURDFFile(bare);
  std::filesystem::remove(bare);
  if (!model) throw std::runtime_error("urdfdom could not read " + s.urdf);
  // the links below the root, parents first
  std::vector<urdf::LinkConstSharedPtr> order;
  for (std::vector<urdf::LinkConstSharedPtr> todo{model->getRoot()}; !todo.empty();) {
    const auto l = todo.front();
    todo.erase(todo.begin());
    if (l != model->getRoot()) order.push_back(l);
    for (const auto& c : l->child_links) todo.push_back(c);
  }
  robot r;
  double root_mass;
  Vector3d root_moments, root_c;
  Matrix3d root_R;
  principal_frame(model->getRoot(), root_mass, root_moments, root_R, root_c);
  if (s.floating && !(root_mass > 0))
    throw std::runtime_error("a floating base whose root link has no mass: Bullet's base needs one");
  r.floating = s.floating, r.base_mass = root_mass, r.base_R = root_R, r.base_c = root_c;
  r.body = std::make_unique<btMultiBody>(static_cast<int>(order.size()), root_mass > 0 ? root_mass : 1.0,
                                         bt(root_mass > 0 ? root_moments : Vector3d(1, 1, 1)), !s.floating, false);
  r.body->setBaseWorldTransform(btTransform(btq(root_R), bt(root_c)));
  r.body->setLinearDamping(0);
  r.body->setAngularDamping(0);
  r.body->setMaxCoordinateVelocity(1e300);
  r.body->setMaxAppliedImpulse(1e300);
  r.body->setHasSelfCollision(false);
  r.links.resize(order.size());
  r.feedback.resize(order.size());
  std::map<std::string, int> of_link;  // URDF link name -> Bullet index (-1: the base)
  of_link[model->getRoot()->name] = -1;
  for (std::size_t k = 0; k < order.size(); ++k) {
    const auto& l = order[k];
    const auto& j = *l->parent_joint;
    mb_link& L = r.links[k];
    L.joint = j.name;
    principal_frame(l, L.mass, L.principal, L.R, L.c);
    const int parent = of_link.at(j.parent_link_name);
    of_link[l->name] = static_cast<int>(k);
    r.index[j.name] = static_cast<int>(k);
    Matrix3d Rp;
    Vector3d cp;
    if (parent < 0) Rp = root_R, cp = root_c;
    else Rp = r.links[parent].R, cp = r.links[parent].c;
    const Matrix3d RJ = rot(j.parent_to_joint_origin_transform.rotation);
    const Vector3d pJ = vec(j.parent_to_joint_origin_transform.position);
    const Matrix3d Rrel = Rp.transpose() * RJ * L.R;         // the link's principal axes on the parent's
    const btQuaternion parent_to_this = btq(Rrel.transpose());  // rotates parent vectors into this frame
    const btVector3 pivot_from_parent = bt(Vector3d(Rp.transpose() * (pJ - cp)));
    const btVector3 com_from_pivot = bt(Vector3d(L.R.transpose() * L.c));
    const btVector3 axis = bt(Vector3d(L.R.transpose() * vec(j.axis)));
    const btVector3 moments = bt(L.principal);
    switch (j.type) {
      case urdf::Joint::REVOLUTE:
      case urdf::Joint::CONTINUOUS:
        L.moves = true;
        r.body->setupRevolute(static_cast<int>(k), L.mass, moments, parent, parent_to_this, axis, pivot_from_parent,
                              com_from_pivot, true);
        break;
      case urdf::Joint::PRISMATIC:
        L.moves = true;
        r.body->setupPrismatic(static_cast<int>(k), L.mass, moments, parent, parent_to_this, axis, pivot_from_parent,
                               com_from_pivot, true);
        break;
      case urdf::Joint::FIXED:
        r.body->setupFixed(static_cast<int>(k), L.mass, moments, parent, parent_to_this, pivot_from_parent, com_from_pivot);
        break;
      default:
        throw std::runtime_error("joint " + j.name + ": a type this program does not build");
    }
    r.body->getLink(static_cast<int>(k)).m_jointFeedback = &r.feedback[k];
  }
  r.body->finalizeMultiDof();
  return r;
}

/// The state and the applied forces: q, q', the scene's torques, gravity on every link.
void load_state(robot& r, const scene& s, const std::map<std::string, double>& q, const std::map<std::string, double>& qd,
                bool gravity) {
  if (r.floating) {
    // Bullet's base: its centre of mass and principal axes in the world, the centre's velocity
    // and the angular velocity on the world's axes.
    const engine::floating_base b(q, qd);
    const Vector3d c = b.R * r.base_c;
    r.body->setBaseWorldTransform(btTransform(btq(b.R * r.base_R), bt(Vector3d(b.p + c))));
    r.body->setBaseVel(bt(Vector3d(b.p_dot + b.omega.cross(c))));
    r.body->setBaseOmega(bt(b.omega));
  }
  for (const auto& [name, k] : r.index)
    if (r.links[k].moves) {
      r.body->setJointPos(k, q.at(name));
      r.body->setJointVel(k, qd.at(name));
    }
  r.body->clearForcesAndTorques();
  for (const auto& [name, tau] : s.torques) r.body->addJointTorque(r.index.at(name), tau);
  if (gravity) {
    for (std::size_t k = 0; k < r.links.size(); ++k) r.body->addLinkForce(static_cast<int>(k), bt(Vector3d(r.links[k].mass * gravity_of(s))));
    if (r.floating) r.body->addBaseForce(bt(Vector3d(r.base_mass * gravity_of(s))));
  }
}

/// A floating base's coordinates' second derivatives from Bullet's base accelerations (the
/// first six outputs: the angular acceleration, then the centre of mass's acceleration, both on
/// the world's axes).
std::array<double, 6> base_second_derivatives(const robot& r, const std::map<std::string, double>& q,
                                              const std::map<std::string, double>& qd,
                                              const btAlignedObjectArray<btScalar>& sr) {
  const engine::floating_base b(q, qd);
  const int dofs = r.body->getNumDofs();
  const Vector3d alpha(sr[dofs + 0], sr[dofs + 1], sr[dofs + 2]), a_c(sr[dofs + 3], sr[dofs + 4], sr[dofs + 5]);
  const Vector3d c = b.R * r.base_c;
  return b.second_derivatives(a_c - alpha.cross(c) - b.omega.cross(b.omega.cross(c)), alpha);
}

/// Featherstone's forward dynamics as btMultiBodyDynamicsWorld calls it, with dt = 0 (no step):
/// the joint accelerations, in Bullet's link order; the feedback filled.
std::vector<double> forward(robot& r, btAlignedObjectArray<btScalar>& sr, btAlignedObjectArray<btVector3>& sv,
                            btAlignedObjectArray<btMatrix3x3>& sm) {
  r.body->computeAccelerationsArticulatedBodyAlgorithmMultiDof(0, sr, sv, sm, false, false, true);
  const int dofs = r.body->getNumDofs();
  std::vector<double> qdd(r.links.size(), 0.0);
  for (std::size_t k = 0; k < r.links.size(); ++k)
    if (r.links[k].moves) qdd[k] = sr[dofs + 6 + r.body->getLink(static_cast<int>(k)).m_dofOffset];
  return qdd;
}

/// Joint k's feedback on the link's URDF axes: force then moment about the joint's origin.
void print_feedback(const robot& r, std::size_t k) {
  const Matrix3d& R = r.links[k].R;
  const Vector3d f = R * ei(r.feedback[k].m_reactionForces.getLinear());
  const Vector3d m = R * ei(r.feedback[k].m_reactionForces.getAngular());
  for (int i = 0; i < 3; ++i) std::cout << "," << g17(f[i]);
  for (int i = 0; i < 3; ++i) std::cout << "," << g17(m[i]);
}

}  // namespace

int main(int argc, char** argv) try {
  const std::string mode = argc > 1 ? argv[1] : "";
  if (!((mode == "states" && argc == 5) || ((mode == "values" || mode == "world-values" || mode == "world-check" || mode == "time") && argc == 4))) {
    std::cerr << "usage: bullet_reference states SCENE N SEED | values SCENE STATES | world-values SCENE STATES | world-check SCENE STATES | time SCENE REPS\n";
    return 2;
  }
  const scene s = read_scene(argv[2]);
  if (mode == "states") {
    engine::print_states(s.joints, std::stoi(argv[3]), std::stoull(argv[4]), false);
    return 0;
  }
  robot r = build(s);
  auto is_base = [&](const std::string& j) {
    return s.floating && std::count(engine::base_coordinates.begin(), engine::base_coordinates.end(), j);
  };
  for (const auto& j : s.joints)
    if (!is_base(j) && (!r.index.count(j) || !r.links[r.index.at(j)].moves))
      throw std::runtime_error("no moving joint " + j + " in the multibody");
  if (s.floating && mode != "values") throw std::runtime_error(mode + ": a fixed base only");
  btAlignedObjectArray<btScalar> sr;
  btAlignedObjectArray<btVector3> sv;
  btAlignedObjectArray<btMatrix3x3> sm;
  if (mode == "time") {  // the scene's own state
    std::ifstream sin(argv[2]);
    const nlohmann::json j = nlohmann::json::parse(sin);
    std::map<std::string, double> q, qd;
    for (auto it = j.at("state").begin(); it != j.at("state").end(); ++it) {
      q[it.key()] = std::stod(it.value().at("q").get<std::string>());
      qd[it.key()] = std::stod(it.value().at("q_dot").get<std::string>());
    }
    load_state(r, s, q, qd, true);
    const int reps = std::stoi(argv[3]);
    double sink = 0;
    const auto t0 = std::chrono::steady_clock::now();
    for (int k = 0; k < reps; ++k) sink += forward(r, sr, sv, sm)[0] + r.feedback[0].m_reactionForces.getLinear().x();
    const double us = std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - t0).count() / reps;
    std::cout << "bullet " << us << " us per forward dynamics and joint feedback (" << (sink != 0) << ")\n";
    return 0;
  }
  // the world a user steps (world-values): gravity applied by the world, feedback on joint frames
  btDefaultCollisionConfiguration config;
  btCollisionDispatcher dispatcher(&config);
  btDbvtBroadphase broadphase;
  btMultiBodyConstraintSolver solver;
  btMultiBodyDynamicsWorld world(&dispatcher, &broadphase, &solver, &config);
  if (mode == "world-values" || mode == "world-check") {
    world.setGravity(bt(gravity_of(s)));
    world.getSolverInfo().m_jointFeedbackInWorldSpace = false;
    world.getSolverInfo().m_jointFeedbackInJointFrame = true;
    if (mode == "world-values") world.addMultiBody(r.body.get());
  }
  std::ifstream in(argv[3]);
  std::string line;
  std::getline(in, line);
  const std::vector<std::string> header = engine::fields(line);
  if (mode == "world-check") {
    // per state, the largest difference over every joint's six components, relative to the
    // largest component of the direct wrenches
    double explained = 0, differs = 1e300;
    int states = 0;
    for (; std::getline(in, line); ++states) {
      if (line.empty()) continue;
      std::map<std::string, double> q, qd;
      read_state(header, engine::fields(line), q, qd);
      std::vector<Eigen::Matrix<double, 6, 1>> direct, no_gravity, stepped;
      const auto take = [&](std::vector<Eigen::Matrix<double, 6, 1>>& to) {
        for (const auto& fb : r.feedback) {
          Eigen::Matrix<double, 6, 1> w;
          w << ei(fb.m_reactionForces.getLinear()), ei(fb.m_reactionForces.getAngular());
          to.push_back(w);
        }
      };
      load_state(r, s, q, qd, true);
      forward(r, sr, sv, sm);
      take(direct);
      load_state(r, s, q, qd, false);
      forward(r, sr, sv, sm);
      take(no_gravity);
      world.addMultiBody(r.body.get());
      load_state(r, s, q, qd, false);
      world.stepSimulation(1e-9, 0, 1e-9);
      world.removeMultiBody(r.body.get());
      take(stepped);
      double scale = 0, e_sum = 0, e_direct = 0;
      for (std::size_t k = 0; k < direct.size(); ++k) scale = std::max(scale, direct[k].cwiseAbs().maxCoeff());
      for (std::size_t k = 0; k < direct.size(); ++k) {
        e_sum = std::max(e_sum, (stepped[k] - direct[k] - no_gravity[k]).cwiseAbs().maxCoeff() / scale);
        e_direct = std::max(e_direct, (stepped[k] - direct[k]).cwiseAbs().maxCoeff() / scale);
      }
      explained = std::max(explained, e_sum);
      differs = std::min(differs, e_direct);
    }
    std::cout << states << " states: the stepped feedback minus (direct + direct without gravity), at most " << explained
              << " of the largest direct component; minus the direct feedback, at least " << differs << "\n";
    return explained <= 1e-7 && differs > 1e-5 ? 0 : 1;
  }
  std::cout << "state";
  if (mode == "values")
    for (const auto& j : s.joints) std::cout << "," << appell_name(j) << "_ddot";
  for (const mb_link& L : r.links) engine::print_wrench_columns(L.joint);
  std::cout << "\n";
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    const std::vector<std::string> f = engine::fields(line);
    std::map<std::string, double> q, qd;
    read_state(header, f, q, qd);
    std::cout << f[0];
    if (mode == "values") {
      load_state(r, s, q, qd, true);
      const std::vector<double> qdd = forward(r, sr, sv, sm);
      if (s.floating)
        for (const double x : base_second_derivatives(r, q, qd, sr)) std::cout << "," << g17(x);
      for (const auto& j : s.joints)
        if (!is_base(j)) std::cout << "," << g17(qdd[r.index.at(j)]);
    } else {
      load_state(r, s, q, qd, false);  // the world adds gravity
      world.stepSimulation(1e-9, 0, 1e-9);
    }
    for (std::size_t k = 0; k < r.links.size(); ++k) print_feedback(r, k);
    std::cout << "\n";
  }
  if (mode == "world-values") world.removeMultiBody(r.body.get());
  return 0;
} catch (const std::exception& e) {
  std::cerr << "bullet_reference: " << e.what() << "\n";
  return 4;
}
