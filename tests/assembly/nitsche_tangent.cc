// The displacement Nitsche tangent with its third-derivative term in closed form (the default of
// add_displacement_nitsche()) against the central difference of A_n it replaced
// (add_displacement_nitsche_reference(), MixedSystem::set_reference_nitsche_tangent()):
//  - at single points (2D and 3D, random shape-function values and gradients, a perturbed gel
//    state and violation g, both Nitsche variants): the residual the same bit for bit; the
//    matrices differ by at most 1e-7 of the largest entry of the part that depends on g (the
//    third-derivative and mu terms, K(g) - K(0)) -- the central difference is about 1e-9
//    accurate; the closed form's tangent symmetric bit for bit in the symmetric variant;
//  - on the 2D scene of the assembly tests (fixed, normal and tangential displacement pieces)
//    in both variants and on a 3D cube [0, 1]^3 (16^3 grid, a prescribed displacement on its
//    top, rollers), at a perturbed state: residual bit for bit, matrices to 1e-10 of their
//    largest entry, and in the symmetric variant the whole tangent no less symmetric than the
//    reference's (in 3D both add dgemm products per block, symmetric to round-off only).
// Set NITSCHE_TANGENT_PRINT to print the figures.
#include <gelmpm/assembly/displacement_nitsche.h>
#include <gelmpm/material/flory_rehner_gel.h>
#include <gelmpm/simulator/scene.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/lac/vector.h>

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <random>

#include "matrix_entries.h"
#include "scene_fixture.h"

using namespace dealii;

namespace
{
  bool
  printing()
  {
    return std::getenv("NITSCHE_TANGENT_PRINT") != nullptr;
  }


  /** One point of @p dim with n_u (n_mu) functions, assembled both ways with symmetry @p s. */
  template <int dim>
  bool
  check_point(const double symmetry, const unsigned int seed)
  {
    const unsigned int               n_u = (dim == 2 ? 9 : 27), n_mu = n_u, n = dim * n_u + n_mu;
    std::mt19937                     rng(seed);
    std::uniform_real_distribution<> u(-1., 1.);

    const GelMPM::FloryRehnerGel<dim> gel;
    GelMPM::PointRecord<dim>          point{};
    point.gel     = &gel;
    point.measure = 0.07;
    for (unsigned int i = 0; i < dim; ++i)
      {
        point.normal[i] = u(rng);
        for (unsigned int j = 0; j < dim; ++j)
          point.F_p[i][j] = (i == j ? gel.lambda_0() * 1.1 : 0.) + 0.1 * u(rng);
      }
    point.normal /= point.normal.norm();
    // A normal-displacement projector N_0 (x) N_0 with N_0 off the normal.
    Tensor<1, dim> N0 = point.normal;
    N0[0] += 0.3;
    N0 /= N0.norm();
    const Tensor<2, dim> Pi = outer_product(N0, N0);
    Tensor<1, dim>       g;
    for (unsigned int i = 0; i < dim; ++i)
      g[i] = 0.02 * u(rng);

    std::vector<double>         N(n_u), M(n_mu);
    std::vector<Tensor<1, dim>> G(n_u);
    for (unsigned int a = 0; a < n_u; ++a)
      {
        N[a] = 0.5 + 0.5 * u(rng);
        for (unsigned int i = 0; i < dim; ++i)
          G[a][i] = 3. * u(rng);
      }
    for (unsigned int b = 0; b < n_mu; ++b)
      M[b] = 0.5 + 0.5 * u(rng);

    GelMPM::AssemblyScratch<dim> s;
    s.N    = N.data();
    s.G    = G.data();
    s.M    = M.data();
    s.n_u  = n_u;
    s.n_mu = n_mu;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        s.delta_F[i][j] = (i == j ? 1. : 0.) + 0.05 * u(rng);
    s.mu_at_point = gel.mu_0() + 0.05 * u(rng);

    const auto assemble = [&](const bool reference, const Tensor<1, dim> &violation) {
      GelMPM::AssemblyCopy copy;
      copy.matrix.reinit(n, n);
      copy.residual.reinit(n);
      if (reference)
        GelMPM::add_displacement_nitsche_reference(point,
                                                   Pi,
                                                   violation,
                                                   30.,
                                                   symmetry,
                                                   true,
                                                   s,
                                                   copy);
      else
        GelMPM::add_displacement_nitsche(point, Pi, violation, 30., symmetry, true, s, copy);
      return copy;
    };
    const auto closed = assemble(false, g), reference = assemble(true, g),
               without = assemble(false, Tensor<1, dim>());

    double difference = 0., g_part = 0., largest = 0., asymmetry = 0.;
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = 0; j < n; ++j)
        {
          difference = std::max(difference, std::abs(closed.matrix(i, j) - reference.matrix(i, j)));
          g_part     = std::max(g_part, std::abs(closed.matrix(i, j) - without.matrix(i, j)));
          largest    = std::max(largest, std::abs(reference.matrix(i, j)));
          asymmetry  = std::max(asymmetry, std::abs(closed.matrix(i, j) - closed.matrix(j, i)));
        }
    bool same_residual = true;
    for (unsigned int i = 0; i < n; ++i)
      same_residual &= (closed.residual(i) == reference.residual(i));

    const bool matrix_ok    = difference <= 1e-7 * g_part && g_part > 1e-6 * largest;
    const bool symmetric_ok = symmetry != 1. || asymmetry == 0.;
    if (printing())
      std::cerr << dim << "D point, s = " << symmetry << ": max |K - K_ref| = " << difference
                << " = " << difference / g_part << " of max |K(g) - K(0)| (" << g_part / largest
                << " of max |K|), max |K - K^T| = " << asymmetry << std::endl;
    std::cout << dim << "D point, s = " << symmetry << std::endl
              << "  residual bit for bit: " << (same_residual ? "yes" : "no  FAIL") << std::endl
              << "  |K - K_ref| < 1e-7 max|K(g) - K(0)|: " << (matrix_ok ? "yes" : "no  FAIL")
              << std::endl;
    if (symmetry == 1.)
      std::cout << "  symmetric bit for bit: " << (symmetric_ok ? "yes" : "no  FAIL") << std::endl;
    return same_residual && matrix_ok && symmetric_ok;
  }


  const std::vector<std::string> cube_pieces = {"symmetry", "top"};

  /** The fixture's cube with the boundary conditions of this test. */
  struct Cube : public CubeFixture
  {
    Cube()
      : CubeFixture(cube_pieces, R"(
        subsection symmetry
          set Selector = nx < -0.5 || ny < -0.5 || nz < -0.5
          set Displacement = normal
        end
        subsection top
          set Selector = nz > 0.5
          set Displacement = fixed
          set Chemical potential = prescribed
          subsection Displacement value
            set Function expression = 0.01*x; 0; -0.02*t
          end
          subsection Chemical potential value
            set Function expression = -0.1
          end
        end
      )")
    {}
  };


  template <int dim>
  bool
  check_system(const std::string        &name,
               GelMPM::MixedSystem<dim> &system,
               const double              mu_0,
               const bool                symmetric)
  {
    const auto    &spaces = system.spaces();
    const unsigned n = spaces.n_dofs(), n_u = spaces.n_u_dofs();
    std::cout << name << std::endl;

    Vector<double>                   state(n);
    std::mt19937                     rng(11);
    std::uniform_real_distribution<> u(-1., 1.);
    for (unsigned int i = 0; i < n; ++i)
      state(i) = (i < n_u) ? 2e-3 * u(rng) : mu_0 + 0.02 * u(rng);
    const double dt = 0.05;

    // The entries of the sparsity pattern (the same pattern for both).
    system.set_reference_nitsche_tangent(true);
    system.assemble(state, dt, true);
    const Vector<double> residual = system.residual();
    const MatrixEntries  K(system.matrix());
    const double         reference_asymmetry = symmetric ? K.asymmetry() : 0.;

    system.set_reference_nitsche_tangent(false);
    system.assemble(state, dt, true);
    const MatrixEntries K_closed(system.matrix());
    double              largest = 0., difference = 0.;
    for (std::size_t e = 0; e < K.value.size(); ++e)
      {
        largest    = std::max(largest, std::abs(K.value[e]));
        difference = std::max(difference, std::abs(K_closed.value[e] - K.value[e]));
      }
    double residual_difference = 0.;
    for (unsigned int i = 0; i < n; ++i)
      residual_difference =
        std::max(residual_difference, std::abs(system.residual()(i) - residual(i)));
    const double closed_asymmetry = symmetric ? K_closed.asymmetry() : 0.;

    if (printing())
      std::cerr << name << ": " << system.n_points() << " material points, max |K - K_ref| / max "
                << "|K_ref| = " << difference / largest
                << ", max |R - R_ref| = " << residual_difference
                << ", max |K - K^T| / max |K| = " << closed_asymmetry / largest << " (reference "
                << reference_asymmetry / largest << ")" << std::endl;
    const bool matrix_ok = difference <= 1e-10 * largest, residual_ok = residual_difference == 0.,
               symmetric_ok = closed_asymmetry <= reference_asymmetry;
    std::cout << "  |K - K_ref| / max|K_ref| < 1e-10: " << (matrix_ok ? "yes" : "no  FAIL")
              << std::endl
              << "  residual bit for bit: " << (residual_ok ? "yes" : "no  FAIL") << std::endl;
    if (symmetric)
      std::cout << "  as symmetric as the reference: " << (symmetric_ok ? "yes" : "no  FAIL")
                << std::endl;
    return matrix_ok && residual_ok && symmetric_ok;
  }
} // namespace


int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bool                             ok = true;
  for (const double symmetry : {1., -1.})
    {
      ok &= check_point<2>(symmetry, 3);
      ok &= check_point<3>(symmetry, 5);
    }
  for (const std::string variant : {"symmetric", "skew-symmetric"})
    {
      SceneFixture scene(variant);
      ok &= check_system("2D, " + variant,
                         *scene.system,
                         scene.material.mu_0(),
                         variant == "symmetric");
    }
  {
    Cube cube;
    ok &= check_system("3D", *cube.system, cube.material.mu_0(), true);
  }
  std::cout << (ok ? "Nitsche tangent checks passed" : "NITSCHE TANGENT CHECKS FAILED")
            << std::endl;
  return ok ? 0 : 1;
}
