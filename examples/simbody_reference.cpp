// A real engine scored against appell's reference values: Simbody (Debian
// libsimbody-dev) computes, at the states of a dataset, what another project
// would test against appell, and writes them as the CSV `appell score` reads.
//
//   simbody_reference heavy_top SCENE.json STATES.csv > simbody.csv
//     the top on a Ball mobilizer at O: theta'', phi'', psi'' (from the
//     angular acceleration) and the pivot force (calcMobilizerReactionForces:
//     the force on the top at O, in Ground);
//   simbody_reference sphere_plane SCENE.json STATES.csv > simbody.csv
//     a sphere on a Free mobilizer, Constraint::SphereOnPlaneContact with
//     rolling: the centre's acceleration, the angular acceleration and the
//     contact force (findForceOnSphereInG).
//
// SCENE gives the parameters (appell's scene file: its state is ignored);
// STATES is the CSV given to `appell reference` (columns `state`, then the
// state's fields).  Simbody's headers are C++17: this unit is built as such.
#include <Simbody.h>

#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

namespace {

using namespace SimTK;

double number(const nlohmann::json& v) { return std::stod(v.is_string() ? v.get<std::string>() : v.dump()); }

struct table {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
  double get(std::size_t r, const std::string& column) const {
    for (std::size_t c = 0; c < header.size(); ++c)
      if (header[c] == column) return std::stod(rows[r][c]);
    throw std::runtime_error("the states file has no column " + column);
  }
};

table read_states(const std::string& path) {
  std::ifstream f(path);
  if (!f) throw std::runtime_error("cannot read " + path);
  table t;
  std::string line;
  while (std::getline(f, line)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty()) continue;
    std::vector<std::string> fields;
    std::stringstream ss(line);
    std::string field;
    while (std::getline(ss, field, ',')) fields.push_back(field);
    if (t.header.empty()) t.header = fields;
    else t.rows.push_back(fields);
  }
  if (t.header.empty() || t.header[0] != "state") throw std::runtime_error(path + ": expected a first column `state`");
  return t;
}

std::string g17(double x) {
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.17g", x);
  return buffer;
}

// R = Rz(psi) Rx(theta) Rz(phi): body components to Ground (appell's z-x-z Euler angles).
Rotation euler_zxz(double psi, double theta, double phi) {
  return Rotation(psi, ZAxis) * Rotation(theta, XAxis) * Rotation(phi, ZAxis);
}

void heavy_top(const nlohmann::json& scene, const table& states) {
  const nlohmann::json& top = scene.at("top");
  const double A = number(top.at("A")), C = number(top.at("C")), m = number(top.at("mass")), l = number(top.at("l"));
  const double g = number(scene.at("gravity"));
  MultibodySystem system;
  SimbodyMatterSubsystem matter(system);
  GeneralForceSubsystem forces(system);
  Force::UniformGravity gravity(forces, matter, Vec3(0, 0, -g));
  // Body frame at O; G at (0, 0, l); central inertia diag(A - m l^2, A - m l^2, C).
  const Vec3 com(0, 0, l);
  const Body::Rigid body(MassProperties(m, com, Inertia(A - m * l * l, A - m * l * l, C).shiftFromMassCenter(com, m)));
  MobilizedBody::Ball ball(matter.Ground(), Transform(), body, Transform());
  system.realizeTopology();
  State state = system.getDefaultState();
  std::cout << "state,theta_ddot,phi_ddot,psi_ddot,pivot_force[0],pivot_force[1],pivot_force[2]\n";
  for (std::size_t r = 0; r < states.rows.size(); ++r) {
    const double psi = states.get(r, "psi"), theta = states.get(r, "theta"), phi = states.get(r, "phi");
    const double psid = states.get(r, "psi_dot"), thd = states.get(r, "theta_dot"), phd = states.get(r, "phi_dot");
    ball.setQToFitRotation(state, euler_zxz(psi, theta, phi));
    const Vec3 n(std::cos(psi), std::sin(psi), 0), ez(std::sin(theta) * std::sin(psi), -std::sin(theta) * std::cos(psi),
                                                      std::cos(theta));
    const Vec3 w = Vec3(0, 0, psid) + thd * n + phd * ez;
    ball.setUToFitAngularVelocity(state, w);
    system.realize(state, Stage::Acceleration);
    // Euler angles' second derivatives from omega' = psi'' e3 + theta'' n + phi'' e_z + psi' theta' e3 x n + phi' omega x e_z.
    const Vec3 wdot = ball.getBodyAngularAcceleration(state);
    const Vec3 rest = wdot - (thd * psid) * cross(Vec3(0, 0, 1), n) - phd * cross(w, ez);
    const Mat33 K(0, n[0], ez[0],  //
                  0, n[1], ez[1],  //
                  1, n[2], ez[2]);
    const Vec3 x = K.invert() * rest;  // (psi'', theta'', phi'')
    Vector_<SpatialVec> reactions;
    matter.calcMobilizerReactionForces(state, reactions);
    const Vec3 F = reactions[ball.getMobilizedBodyIndex()][1];
    std::cout << states.rows[r][0] << "," << g17(x[1]) << "," << g17(x[2]) << "," << g17(x[0]) << "," << g17(F[0]) << ","
              << g17(F[1]) << "," << g17(F[2]) << "\n";
  }
}

void sphere_plane(const nlohmann::json& scene, const table& states) {
  const double m = number(scene.at("sphere").at("mass")), a = number(scene.at("sphere").at("radius"));
  Vec3 gvec, force, torque;
  for (int i = 0; i < 3; ++i) {
    gvec[i] = number(scene.at("gravity").at(i));
    force[i] = scene.contains("force") ? number(scene.at("force").at(i)) : 0.0;
    torque[i] = scene.contains("torque") ? number(scene.at("torque").at(i)) : 0.0;
  }
  MultibodySystem system;
  SimbodyMatterSubsystem matter(system);
  GeneralForceSubsystem forces(system);
  Force::UniformGravity gravity(forces, matter, gvec);
  const Body::Rigid body(MassProperties(m, Vec3(0), UnitInertia::sphere(a)));
  MobilizedBody::Free ball(matter.Ground(), Transform(), body, Transform());
  Force::ConstantForce applied(forces, ball, Vec3(0), force);
  Force::ConstantTorque couple(forces, ball, torque);
  // The plane z = 0 of Ground (its frame P is Ground's), the sphere centred at the body origin.
  Constraint::SphereOnPlaneContact contact(matter.updGround(), Transform(), ball, Vec3(0), a, true);
  system.realizeTopology();
  State state = system.getDefaultState();
  std::cout << "state,center_ddot[0],center_ddot[1],center_ddot[2],omega_dot[0],omega_dot[1],omega_dot[2],"
               "contact_force[0],contact_force[1],contact_force[2]\n";
  for (std::size_t r = 0; r < states.rows.size(); ++r) {
    const Vec3 c(states.get(r, "center[0]"), states.get(r, "center[1]"), states.get(r, "center[2]"));
    const Vec3 w(states.get(r, "omega[0]"), states.get(r, "omega[1]"), states.get(r, "omega[2]"));
    ball.setQToFitTransform(state, Transform(Rotation(), c));
    ball.setUToFitAngularVelocity(state, w);
    ball.setUToFitLinearVelocity(state, cross(w, Vec3(0, 0, a)));  // rolling: the contact point at rest
    system.realize(state, Stage::Acceleration);
    const Vec3 acc = ball.getBodyOriginAcceleration(state), wdot = ball.getBodyAngularAcceleration(state);
    const Vec3 F = contact.findForceOnSphereInG(state);
    std::cout << states.rows[r][0];
    for (const Vec3* v : {&acc, &wdot, &F})
      for (int i = 0; i < 3; ++i) std::cout << "," << g17((*v)[i]);
    std::cout << "\n";
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 4) {
    std::cerr << "usage: simbody_reference heavy_top|sphere_plane SCENE.json STATES.csv\n";
    return 2;
  }
  try {
    std::ifstream f(argv[2]);
    if (!f) throw std::runtime_error(std::string("cannot read ") + argv[2]);
    const nlohmann::json scene = nlohmann::json::parse(f);
    const table states = read_states(argv[3]);
    const std::string what = argv[1];
    if (what == "heavy_top") heavy_top(scene, states);
    else if (what == "sphere_plane") sphere_plane(scene, states);
    else throw std::runtime_error("unknown scene kind " + what);
  } catch (const std::exception& e) {
    std::cerr << "simbody_reference: " << e.what() << "\n";
    return 2;
  }
  return 0;
}
