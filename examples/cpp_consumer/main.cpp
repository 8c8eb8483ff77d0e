// A friction law and a short simulation through the installed library: a 1 kg axis with Coulomb
// (1 N) and viscous (0.1 N s/m) friction, pushed from rest by a constant 2 N for 1 s. Its velocity
// is v(t) = (2 - 1) / 0.1 (1 - exp(-0.1 t / 1)): 0.9516 m/s at t = 1 s.
#include <frictionlab/models/friction_law.hpp>
#include <frictionlab/plants/axis.hpp>
#include <frictionlab/simulate/simulate.hpp>
#include <frictionlab/version.hpp>

#include <cmath>
#include <cstdio>
#include <string>

int main() {
  namespace fl = frictionlab;
  fl::CoulombViscous cv;
  cv.Fc = 1.0;  // N
  cv.Fv = 0.1;  // N s/m
  const fl::FrictionLaw law = cv;
  const fl::RigidAxis axis(fl::AxisParams{.M = 1.0});  // kg
  fl::InputSignal push;                                 // constant force
  push.value = 2.0;                                     // N
  fl::SimulationOptions options;
  options.duration = 1.0;  // s
  const fl::Trajectory tr = fl::simulate(axis, law, push, options);
  const double v = tr.velocity.back();
  const double expected = (2.0 - 1.0) / 0.1 * (1.0 - std::exp(-0.1 * 1.0));
  std::printf("frictionlab %s: %s law, friction at 1 m/s %.2f N; velocity after %.1f s %.4f m/s (exact %.4f m/s)\n",
              fl::kVersion, law.name().c_str(), law.sliding(1.0), tr.time.back(), v, expected);
  return std::abs(v - expected) < 1e-6 ? 0 : 1;
}
