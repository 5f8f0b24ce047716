// The integrator table: every keyword of <integrator type="..."> and what it builds.
#include "explicit_integrators.h"
#include "implicit_system.h"

namespace fosssim {
namespace {

template <class T>
std::unique_ptr<Integrator> make() {
  return std::make_unique<T>();
}

}  // namespace

const std::vector<IntegratorEntry>& integratorTable() {
  static const std::vector<IntegratorEntry> table = {
      {"explicit-euler", make<ExplicitEuler>, "x += h v, v += h F(x, v)/m", false},
      {"symplectic-euler", make<SymplecticEuler>, "v += h F(x, v)/m, then x += h v", false},
      {"forward-backward-euler", make<SymplecticEuler>, "same as symplectic-euler", false},
      {"implicit-euler", make<ImplicitEuler>, "backward Euler solved by Newton's method", true},
      {"linearized-implicit-euler", make<LinearizedImplicitEuler>,
       "backward Euler with one Newton step", true},
  };
  return table;
}

const IntegratorEntry* findIntegrator(const std::string& keyword) {
  for (const auto& entry : integratorTable())
    if (keyword == entry.keyword) return &entry;
  return nullptr;
}

}  // namespace fosssim
