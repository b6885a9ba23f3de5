// appell/system/definition.hpp -- a mechanical system described by expressions: the scene
// model "system" (SCENES.md in this repository), as the library holds it.
//
// The model is in phases, one header each (include appell/system/motion.hpp for all):
//   definition.hpp  the description, scalar-free (this file)
//   tapes.hpp       compiled_system<T>: the expressions compiled to tapes, constants in T
//   mechanics.hpp   expression_system<T> (the generic path's view), expression_constraints<T>,
//                   solve_speeds
//   wrenches.hpp    constraint_wrenches: the constraints' reactions as wrenches
//   contacts.hpp    contact_forces: normal and tangential forces of the contacts
//   tree.hpp        a tree of links by recursion: M (composite rigid bodies), b, Q and the
//                   links' accelerations (Newton-Euler passes)
//   motion.hpp      system_motion: u', the reactions, the multipliers and eq. (4)
//   joint_wrenches.hpp, linearize.hpp: a tree's joint wrenches; the linearized motion
// The reader (src/models/system.cpp) builds the definition from a file in named phases.
//
// The description (system_definition) is scalar-free: parsed expressions in
// the variables  parameters..., q..., u..., t  (in that order), with the
// partial derivatives the dynamics need taken symbolically once, when the
// scene is read.  compiled_system<T> holds their constants and the
// parameters' values in T; expression_system<T> is then an ordinary
// mechanical system of the generic path (gibbs_appell.hpp):
//   q' = kinematics(q, u, t)  (u = q' when the speeds are the coordinates' rates);
//   for each body, on the fixed axes,
//     v_G   = sum_i dr_G/dq_i q'_i + dr_G/dt,
//     omega = sum_m a_m' R_1 ... R_(m-1) e_(axis m)  for the orientation
//             R = R_1(a_1) R_2(a_2) ... (elementary rotations about x, y, z
//             by angles a_m(q, t), composed left to right, body axes to fixed),
//             or, for an orientation given as a matrix R(q, t), the vector of the
//             skew matrix R' R^T (on the body's axes: of R^T R'),
//     force = mass g + F,  couple Gamma;
//   a body that turns is given to the generic path on its own axes (a frame
//   turning with omega; components R^T x, each R_m^T applied in turn, so the
//   inertia is the exact I_body and never R I_body R^T, which intervals would
//   widen), unless its inertia is a multiple of the identity as written: then
//   R I R^T = I and the fixed axes serve;
// the library differentiates these once more (multi_dual) for J and the
// velocity-product terms, as for every other system.
// The constraints (expression_constraints<T>) read A(q, t) u = a(q, t), one row each:
//   holonomic f(q, t) = 0:       A = df/dq W,  a = -(df/dq w + df/dt),
//                                with q' = W u + w (W = dq'/du, w = q'(u = 0));
//   nonholonomic g(q, u, t) = 0: A = dg/du,    a = -g(q, 0, t)   (g affine in u).
// Their reactions are Cotton's Q'_c in speeds adapted with v_c = A u - a, equal
// to the Lagrange multipliers of those rows (both are computed; the scene's
// checks carry the difference).
// A wrench (system_wrench_definition) gathers some constraints' reactions into a
// force at a point of one body and a couple, from their virtual work.
#pragma once

#include <algorithm>
#include <array>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "appell/expr/expression.hpp"

namespace appell {

/// Where each kind of variable sits in the expressions' variable list.
struct system_variables {
  int parameters = 0, coordinates = 0, speeds = 0;
  int q(int i) const { return parameters + i; }
  int u(int j) const { return parameters + coordinates + j; }
  int t() const { return parameters + coordinates + speeds; }
  int size() const { return t() + 1; }
};

using shared_expression = std::shared_ptr<const expression>;

/// A function of (q, t) with its partial derivatives that are not 0 as written.
struct differentiated_expression {
  shared_expression value;
  std::vector<std::pair<int, shared_expression>> dq;  ///< (i, d value / dq_i)
  shared_expression dt;                               ///< d value / dt, or null
};

/// A link's joint (SCENES.md, "links of a tree"): how the link hangs from its parent (another
/// link, or the ground).  The link's frame L is the joint's frame: on the parent's frame P,
///   L = P . (origin, Rz(yaw) Ry(pitch) Rx(roll)) . (its motion),
/// the motion a rotation by q about `axis` (revolute), a translation q axis (prismatic), or none
/// (fixed); `axis` on L's axes (the rotation leaves it in place).  URDF's conventions.
struct system_joint_definition {
  enum class kind { revolute, prismatic, fixed };
  std::string name;
  kind type = kind::fixed;
  int parent = -1;      ///< the parent link's body number; -1: the ground (the fixed axes)
  int coordinate = -1;  ///< revolute, prismatic: the coordinate the joint's motion is
  std::array<shared_expression, 3> origin, rpy, axis;  ///< constants (null: 0)
  shared_expression effort;  ///< the actuator's torque (revolute) or force (prismatic), in q, u, t; null: none
  /// The axis as written is along +-e_along (two components literally 0): its rotations are then
  /// elementary, exactly; -1: another direction (normalized, Rodrigues' formula).
  int along = -1, sign = 1;
};

struct system_body_definition {
  std::string name;
  /// A link of a tree: placed by its joint (no centre, orientation or omega); its centre of
  /// mass at `com` on the link's axes, its inertia on the axes turned by `com_rpy` from the link's.
  bool is_link = false;
  system_joint_definition joint;
  std::array<shared_expression, 3> com, com_rpy;
  shared_expression mass;
  std::array<shared_expression, 6> inertia;  ///< central, on body axes: xx yy zz xy yz zx (null: 0)
  std::array<differentiated_expression, 3> center;  ///< G on the fixed axes
  std::vector<std::pair<int, differentiated_expression>> rotations;  ///< (axis 0/1/2, angle), left to right
  /// Or the orientation as a matrix R (body axes to fixed), row by row: R(q, t) orthogonal, det 1.
  std::array<differentiated_expression, 9> matrix;
  bool has_matrix = false;
  std::array<shared_expression, 3> force, couple;  ///< force through G and couple (null: 0), on the body's axes
  /// Given instead of an orientation: the angular velocity (affine in u), on
  /// the fixed axes (an isotropic inertia: its orientation plays no part), or
  /// with body_axes on the body's own axes, with the centre's velocity there
  /// too (the paper's free body on moving axes, sec. 3 and 4).
  std::array<shared_expression, 3> omega, velocity;
  bool has_omega = false, body_axes = false;
};

struct system_constraint_definition {
  std::string name;
  bool holonomic = true;
  differentiated_expression f;                        ///< holonomic: f(q, t) = 0
  shared_expression g;                                ///< nonholonomic: g(q, u, t) = 0
  std::vector<std::pair<int, shared_expression>> du;  ///< nonholonomic: (j, dg/du_j) not 0
  /// point_velocity (nonholonomic): n . v = 0 for the material point of body
  /// number `body` at `point`, v = v_G + omega x (point - G), n = `direction`
  /// (point and direction on the fixed axes, functions of q and t).
  int body = -1;
  std::array<shared_expression, 3> point, direction;
  /// point_velocity on a moving support: the support's velocity at the point (fixed axes, a
  /// function of q and t; null: 0), so that n . (v - support) = 0.
  std::array<shared_expression, 3> support;
  /// A row of a link's contact (system_contact_definition::link >= 0): the contact's number
  /// and the row, 0 to 2 the contact point's velocity, 3 to 5 the link's angular velocity,
  /// along the contact frame's axes x, y, z (nonholonomic, A u = 0: the support is fixed).
  int link_contact = -1, link_row = -1;
};

/// The wrench that some constraints exert on one body, reduced to a point of
/// it: a force F at P and a couple M (the moment about P), on the fixed axes,
/// fixed by the constraints' virtual work (Cotton sec. 5, end):
///   J_P^T F + J_w^T M = sum_c A_c^T Q'_c   for every virtual displacement,
/// J_P, J_w the velocity of the body's material point at P and its angular
/// velocity per unit of each speed.  Unique when the body moves in 6
/// independent ways (J of rank 6); a wrench when each constraint's row A_c is
/// a virtual power of that body alone (checked when the file is read).
struct system_wrench_definition {
  std::string name;
  int body = -1;
  std::array<shared_expression, 3> point;  ///< P on the fixed axes, a function of q and t
  std::vector<int> constraints;            ///< the constraints whose reactions it gathers
};

/// A contact (SCENES.md, "contacts"): the force that some constraints exert on
/// one body at one point, split into its normal component N (along the side the
/// support pushes from) and its tangential part F_t, so that the contact can be
/// judged: it holds while N > 0 and |F_t| < mu N.  The force of each constraint c
/// per unit of its reaction is d_c: a point_velocity constraint's direction, or
/// (with `body` and `point`) the force of the wrench its unit reaction exerts
/// there (system_wrench_definition), which must be a force alone (no couple
/// about the point: checked when the file is read).
struct system_contact_definition {
  std::string name;
  std::vector<int> constraints;
  /// The body and point the force acts at; -1 when every constraint is a point_velocity
  /// constraint at one point of one body (then d_c is the direction, no wrench is solved).
  int body = -1;
  std::array<shared_expression, 3> point;
  /// An omega body (SCENES.md): d omega_i / du_j, the columns of its angular velocity.
  std::array<std::vector<std::pair<int, shared_expression>>, 3> omega_du;
  int normal = -1;  ///< the constraint whose force is along the normal, or -1: `direction` gives it
  int side = 1;     ///< +1: the support pushes along d_normal (or `direction`); -1: against it
  std::array<shared_expression, 3> direction;
  std::string mu;   ///< the friction coefficient as written (a decimal), empty: none given
  /// A contact of a link of a tree with the fixed ground (SCENES.md, "contacts of links"): the
  /// link's body number (-1: a contact of the kinds above).  Its constraints are made by the
  /// reader, one per row (system_constraint_definition::link_contact), on the contact frame F:
  ///   point:   F's origin `point` on the link's axes, its axes the fixed axes; three rows, the
  ///            point's velocity: a force at the point (the normal `direction` on the fixed axes,
  ///            by default +z);
  ///   surface: F the sole's frame (origin its centre, axes turned by `rpy` from the link's, z
  ///            its normal out of the ground into the link); six rows, the velocity of the
  ///            centre and the angular velocity: the wrench at the centre on the sole's axes,
  ///            judged by the rectangle's contact wrench cone (reactions/wrench_cone.hpp).
  /// Every number a decimal as written.
  int link = -1;
  bool surface = false;
  std::array<std::string, 3> frame_origin{"0", "0", "0"}, frame_rpy{"0", "0", "0"};
  std::array<std::string, 3> frame_normal{"0", "0", "1"};  ///< point: the normal, fixed axes
  std::array<std::string, 2> half_lengths{"0", "0"};       ///< surface: X, Y along the sole's x, y
};

/// A whole system file's mechanics, independent of any scalar.
struct system_definition {
  system_variables vars;
  std::vector<std::string> names;              ///< every variable, in order
  std::vector<shared_expression> parameters;   ///< each parameter's value (an expression of parameters)
  std::vector<int> parameter_order;            ///< each parameter after those it uses
  bool rates_as_speeds = true;                 ///< u = q' (no kinematics given)
  std::vector<shared_expression> kinematics;   ///< q'_i(q, u, t), when not rates_as_speeds
  std::vector<std::vector<std::pair<int, shared_expression>>> kinematics_du;  ///< (j, dq'_i/du_j) not 0
  std::array<shared_expression, 3> gravity;    ///< null: none
  std::vector<system_body_definition> bodies;
  std::vector<int> link_order;  ///< the links' body numbers, each after its parent
  std::vector<system_constraint_definition> constraints;
  std::vector<system_wrench_definition> wrenches;
  std::vector<system_contact_definition> contacts;
  table_list tables;  ///< functions of time an applied force, couple or effort may call (SCENES.md, "tables")
};

}  // namespace appell
