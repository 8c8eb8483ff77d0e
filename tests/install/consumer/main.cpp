#include <frictionlab/identify/idim_workspace.hpp>
#include <frictionlab/models/friction_law.hpp>
#include <frictionlab/version.hpp>

#include <iostream>

int main() {
  frictionlab::FrictionLaw law = frictionlab::Stribeck{};
  // At rest a stuck Stribeck contact holds up to Fs; sliding fast it approaches Fc (+ Fv v).
  std::cout << law.name() << " " << law.breakaway_positive() << " " << std::fixed;
  std::cout.precision(1);
  std::cout << law.sliding(1.0) - 0.4;
  // A caller-owned workspace (installed header, no library call needed): empty until used.
  frictionlab::IdimWorkspace workspace;
  std::cout << (workspace.capacity() == 0 && workspace.buffer(0, 8).size() == 8 ? " consumer ok\n" : " workspace broken\n");
  return frictionlab::kVersion[0] == '\0';
}
