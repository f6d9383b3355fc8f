// The volume points' tangent contracted with the structure of A_n (the default) equals the
// contraction with the entries of A_n (the former assembly, MixedSystem::
// set_generic_volume_tangent()) to round-off, and the residual is the same bit for bit: on the
// 2D scene of the assembly tests (Q2-Q2SD, every kind of boundary term) and on a small 3D cube [0,
// 1]^3 (16^3 grid) (Q2-Q2SD, 3 x 3 x 3 points per cell, rollers and a prescribed chemical
// potential), at a perturbed state. Set VOLUME_TANGENT_PRINT to print the largest differences.
#include <gelmpm/simulator/scene.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/lac/vector.h>

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <random>
#include <utility>

#include "matrix_entries.h"
#include "scene_fixture.h"

using namespace dealii;

namespace
{


  template <int dim>
  bool
  compare(const std::string &name, GelMPM::MixedSystem<dim> &system, const double mu_0)
  {
    const auto    &spaces = system.spaces();
    const unsigned n = spaces.n_dofs(), n_u = spaces.n_u_dofs();
    if (std::getenv("VOLUME_TANGENT_PRINT"))
      std::cerr << name << ": " << n_u << " displacement and " << spaces.n_mu_dofs()
                << " chemical-potential unknowns, " << system.n_points() << " material points"
                << std::endl;
    std::cout << name << std::endl;

    Vector<double>                   state(n);
    std::mt19937                     rng(11);
    std::uniform_real_distribution<> u(-1., 1.);
    for (unsigned int i = 0; i < n; ++i)
      state(i) = (i < n_u) ? 2e-3 * u(rng) : mu_0 + 0.02 * u(rng);
    const double dt = 0.05;

    system.set_generic_volume_tangent(true);
    system.assemble(state, dt, true);
    const Vector<double> residual = system.residual();
    // The entries of the sparsity pattern (the same pattern for both).
    const MatrixEntries K(system.matrix());

    system.set_generic_volume_tangent(false);
    system.assemble(state, dt, true);
    const MatrixEntries K_structured(system.matrix());
    double              largest = 0., difference = 0., entry = 0.;
    for (std::size_t e = 0; e < K.value.size(); ++e)
      {
        const double k = K.value[e], d = std::abs(K_structured.value[e] - k);
        largest    = std::max(largest, std::abs(k));
        difference = std::max(difference, d);
        if (d > 0.)
          entry = std::max(entry, d / std::abs(k));
      }
    double residual_difference = 0.;
    for (unsigned int i = 0; i < n; ++i)
      residual_difference =
        std::max(residual_difference, std::abs(system.residual()(i) - residual(i)));

    if (std::getenv("VOLUME_TANGENT_PRINT"))
      std::cerr << name << ": max |K - K_generic| / max |K_generic| = " << difference / largest
                << ", largest entrywise relative difference " << entry
                << ", max |R - R_generic| = " << residual_difference << std::endl;
    const bool matrix_ok = difference <= 1e-13 * largest, residual_ok = residual_difference == 0.;
    std::cout << "  |K - K_generic| / max|K_generic| < 1e-13: " << (matrix_ok ? "yes" : "no  FAIL")
              << std::endl
              << "  residual bit for bit: " << (residual_ok ? "yes" : "no  FAIL") << std::endl;
    return matrix_ok && residual_ok;
  }
} // namespace


int
main(int argc, char **argv)
{
  return compare_2d_and_3d(argc, argv, "volume tangent", [](auto &&...args) {
    return compare(std::forward<decltype(args)>(args)...);
  });
}
