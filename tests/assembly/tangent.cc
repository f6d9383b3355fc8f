// The assembled tangent equals a central finite-difference Jacobian of the assembled residual,
// block by block (relative error < 1e-6 of each block's largest entry), on a scene with every kind
// of term: volume points, fixed / normal / tangential displacement (Nitsche), traction, prescribed
// chemical potential (Nitsche), solvent flux, at a perturbed state (u != u_bar on the Dirichlet
// pieces, so the third-derivative Nitsche term matters). The symmetric variant gives a symmetric
// tangent (1e-12); the skew-symmetric one a consistent but unsymmetric one.
#include <deal.II/lac/full_matrix.h>

#include <cmath>
#include <iostream>
#include <random>

#include "scene_fixture.h"

using namespace dealii;

namespace
{
  bool
  check(const std::string &variant)
  {
    SceneFixture   scene(variant);
    auto          &system = *scene.system;
    const auto    &spaces = system.spaces();
    const unsigned n = spaces.n_dofs(), n_u = spaces.n_u_dofs();
    std::cout << variant << " Nitsche: " << n_u << " displacement and " << spaces.n_mu_dofs()
              << " chemical-potential unknowns, " << system.n_points() << " material points"
              << std::endl;

    // A state away from equilibrium and from the prescribed values.
    Vector<double>                   state(n);
    std::mt19937                     rng(11);
    std::uniform_real_distribution<> u(-1., 1.);
    for (unsigned int i = 0; i < n; ++i)
      state(i) = (i < n_u) ? 2e-3 * u(rng) : scene.material.mu_0() + 0.02 * u(rng);
    const double dt = 0.05;

    system.assemble(state, dt, true);
    FullMatrix<double> K(n, n);
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = 0; j < n; ++j)
        K(i, j) = system.matrix().el(i, j);

    FullMatrix<double> K_fd(n, n);
    for (unsigned int j = 0; j < n; ++j)
      {
        const double   h = (j < n_u) ? 1e-7 : 1e-6;
        Vector<double> plus(state), minus(state);
        plus(j) += h;
        minus(j) -= h;
        system.assemble(plus, dt, false);
        Vector<double> r_plus = system.residual();
        system.assemble(minus, dt, false);
        for (unsigned int i = 0; i < n; ++i)
          K_fd(i, j) = (r_plus(i) - system.residual()(i)) / (2. * h);
      }

    bool        ok          = true;
    const char *names[2][2] = {{"K_uu", "K_umu"}, {"K_muu", "K_mumu"}};
    for (unsigned int bi = 0; bi < 2; ++bi)
      for (unsigned int bj = 0; bj < 2; ++bj)
        {
          double largest = 0., error = 0.;
          for (unsigned int i = (bi ? n_u : 0); i < (bi ? n : n_u); ++i)
            for (unsigned int j = (bj ? n_u : 0); j < (bj ? n : n_u); ++j)
              {
                largest = std::max(largest, std::abs(K(i, j)));
                error   = std::max(error, std::abs(K(i, j) - K_fd(i, j)));
              }
          const bool block_ok = error <= 1e-6 * largest;
          ok &= block_ok;
          std::cout << "  " << names[bi][bj]
                    << ": |K - K_fd| / max|K| < 1e-6: " << (block_ok ? "yes" : "no  FAIL")
                    << std::endl;
        }
    double asymmetry = 0., largest = 0.;
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = 0; j < n; ++j)
        {
          asymmetry = std::max(asymmetry, std::abs(K(i, j) - K(j, i)));
          largest   = std::max(largest, std::abs(K(i, j)));
        }
    const bool symmetric = asymmetry <= 1e-12 * largest;
    const bool expected  = (variant == "symmetric");
    ok &= (symmetric == expected);
    std::cout << "  symmetric to 1e-12: " << (symmetric ? "yes" : "no")
              << (symmetric == expected ? "" : "  FAIL") << std::endl;
    return ok;
  }
} // namespace


int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const bool                       ok = check("symmetric") & check("skew-symmetric");
  std::cout << (ok ? "tangent checks passed" : "TANGENT CHECKS FAILED") << std::endl;
  return ok ? 0 : 1;
}
