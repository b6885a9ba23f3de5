// tests/engines/engine_floating.hpp -- a floating base's coordinates (appell's x, y, z, yaw,
// pitch, roll: SCENES.md, "urdf") turned into the pose and twist the engines take, and the
// engines' accelerations back into the coordinates' second derivatives.  Eigen, double.
#pragma once

#include <Eigen/Geometry>
#include <array>
#include <map>
#include <string>

namespace engine {

/// A floating base's pose and twist from its coordinates and their rates (R = Rz(yaw) Ry(pitch)
/// Rx(roll)), and back from the engine's accelerations: the engines describe a free body by its
/// frame's origin and orientation, with its twist and its derivative on the body's axes.
struct floating_base {
  Eigen::Matrix3d R;
  Eigen::Vector3d p, p_dot, omega;  ///< omega on the fixed axes
  Eigen::Matrix3d E;                ///< omega = E (yaw', pitch', roll')
  Eigen::Vector3d rates;            ///< (yaw', pitch', roll')
  Eigen::Vector3d E_dot_rates;      ///< E' (yaw', pitch', roll')

  floating_base(const std::map<std::string, double>& q, const std::map<std::string, double>& qd) {
    const double yaw = q.at("base_yaw"), pitch = q.at("base_pitch"), roll = q.at("base_roll");
    const Eigen::Matrix3d Rz = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    const Eigen::Matrix3d Ry = Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitY()).toRotationMatrix();
    const Eigen::Matrix3d Rx = Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitX()).toRotationMatrix();
    R = Rz * Ry * Rx;
    p = {q.at("base_x"), q.at("base_y"), q.at("base_z")};
    p_dot = {qd.at("base_x"), qd.at("base_y"), qd.at("base_z")};
    const Eigen::Vector3d e1 = Eigen::Vector3d::UnitZ(), e2 = Rz * Eigen::Vector3d::UnitY(), e3 = Rz * Ry * Eigen::Vector3d::UnitX();
    E.col(0) = e1, E.col(1) = e2, E.col(2) = e3;
    rates = {qd.at("base_yaw"), qd.at("base_pitch"), qd.at("base_roll")};
    omega = E * rates;
    E_dot_rates = rates[1] * rates[0] * e1.cross(e2) + rates[2] * (rates[0] * e1 + rates[1] * e2).cross(e3);
  }
  /// The coordinates' second derivatives (x'', y'', z'', yaw'', pitch'', roll'') from the origin's
  /// acceleration and the angular acceleration, both on the fixed axes.
  std::array<double, 6> second_derivatives(const Eigen::Vector3d& p_ddot, const Eigen::Vector3d& alpha) const {
    const Eigen::Vector3d r = E.lu().solve(alpha - E_dot_rates);
    return {p_ddot[0], p_ddot[1], p_ddot[2], r[0], r[1], r[2]};
  }
};

}  // namespace engine
