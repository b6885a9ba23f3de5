// The planar N-link pendulum in Simbody (see simbody_chain.hpp), compiled as C++17.
#include "simbody_chain.hpp"

#include <Simbody.h>

struct simbody_chain::impl {
  SimTK::MultibodySystem system;
  SimTK::SimbodyMatterSubsystem matter{system};
  SimTK::GeneralForceSubsystem forces{system};
  SimTK::State state;
};

simbody_chain::simbody_chain(int n, const std::vector<double>& q, const std::vector<double>& u) : p_(new impl) {
  using namespace SimTK;
  Force::UniformGravity gravity(p_->forces, p_->matter, Vec3(0, -9.81, 0));
  const Vec3 com(0.5, 0, 0);
  const Body::Rigid link(MassProperties(1.0, com, Inertia(1.0 / 12).shiftFromMassCenter(com, 1.0)));
  MobilizedBody parent = p_->matter.Ground();
  for (int i = 0; i < n; ++i) {
    MobilizedBody::Pin pin(parent, Transform(Vec3(i == 0 ? 0.0 : 1.0, 0, 0)), link, Transform(Vec3(0)));
    parent = pin;
  }
  p_->system.realizeTopology();
  p_->state = p_->system.getDefaultState();
  for (int i = 0; i < n; ++i) {
    p_->state.updQ()[i] = q[static_cast<std::size_t>(i)];
    p_->state.updU()[i] = u[static_cast<std::size_t>(i)];
  }
}

simbody_chain::~simbody_chain() = default;

const double* simbody_chain::accelerations() {
  p_->state.updQ()[0] = p_->state.getQ()[0];
  p_->system.realize(p_->state, SimTK::Stage::Acceleration);
  return &p_->state.getUDot()[0];
}
