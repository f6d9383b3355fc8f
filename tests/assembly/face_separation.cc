// Two faces of one body on one grid ('Contact/Self contact/Separate faces', PointCache::
// separate_faces()): two blocks of one body, [0, 1] x [0, 0.75] and [0, 1] x [0.8, 1.55], 0.05
// (0.4 cells) apart, so that the B-splines along the gap are nonzero on both, in plane strain and
// axisymmetric (the left side the axis), the facing sides the pieces that touch (on a refined grid
// the fine level's functions whose tails hold less than 1 % on one face stay on both:
// tests/simulator/self_contact_blocks measures what they carry):
// - without separation many displacement functions are nonzero at points of both blocks; with it
//   no function is used by the points of both (every one that was is copied), and the copies
//   are unknowns of their own (n_u_dofs grows by dim per copy);
// - a rigid shift of the upper block alone (its functions' y-coefficients -0.04, the lower
//   block's zero) is then in the space: every upper point moves by -0.04 and every lower one by
//   0 (1e-12), and the residual is that of the unshifted state (to 1e-10 of the residual a tenth
//   of the shift gives without separation, where it compresses the lower block's top): the faces
//   slide and approach without the grid resisting;
// - the next setup keeps the sparsity pattern (the same separation);
// - the system's tangent with the copies equals the central finite-difference Jacobian of its
//   residual (1e-6 of its largest entry) on the upper block shifted into the lower one by 0.02
//   and perturbed at random, with the self-contact term active on both faces.
#include <gelmpm/assembly/self_contact.h>
#include <gelmpm/simulator/scene.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/lac/vector.h>

#include <cmath>
#include <iostream>
#include <memory>
#include <random>
#include <set>
#include <string>

#include "matrix_entries.h"
#include "two_blocks.h"

using namespace dealii;

namespace
{
  constexpr double split = 0.775; // y between the blocks

  bool
  report(const std::string &what, const bool ok)
  {
    std::cout << "  " << what << ": " << (ok ? "yes" : "no  FAIL") << std::endl;
    return ok;
  }


  /** The two blocks 0.05 apart, self-contact on, faces separated (@p separate) or not. */
  struct TwoBlocks : two_blocks::TwoBlocks
  {
    TwoBlocks(const bool separate, const bool axisymmetric, const std::string &boxes = "")
      : two_blocks::TwoBlocks(0.8,
                              axisymmetric,
                              boxes,
                              std::string("set Method = penalty\nset Separate faces = ") +
                                (separate ? "true" : "false"))
    {}
  };


  /**
   * Per u DoF of @p system, 1 if it is nonzero at points of the lower block, 2 of the upper
   * block, 3 both. (A cell's list of DoFs can hold a function that vanishes on all of the cell.)
   */
  std::vector<unsigned int>
  users(const GelMPM::MixedSystem<2> &system)
  {
    const auto               &cache = system.point_cache();
    std::vector<unsigned int> used(system.spaces().n_u_dofs() / 2, 0);
    for (const auto &block : cache.blocks())
      for (unsigned int p = block.first; p < block.end; ++p)
        {
          const auto   &r      = cache.points()[p];
          const double *values = cache.u_values_at(r);
          for (unsigned int a = 0; a < cache.u_dofs(block).size(); ++a)
            if (values[a] != 0.)
              used[cache.u_dofs(block)[a]] |= (r.X0[1] > split ? 2u : 1u);
        }
    return used;
  }


  /**
   * The upper block's functions at du_y = @p shift (those of both blocks too), mu_0 for mu,
   * plus @p noise at random.
   */
  Vector<double>
  shifted_state(const GelMPM::Scene<2> &scene, const double shift, const double noise)
  {
    const auto     used  = users(*scene.system);
    Vector<double> state = two_blocks::noisy_state(scene, noise);
    for (unsigned int i = 0; i < used.size(); ++i)
      if (used[i] & 2u)
        state(2 * i + 1) += shift;
    scene.system->hold_axis(state);
    return state;
  }


  bool
  check_separation(const bool axisymmetric, const std::string &boxes = "")
  {
    std::cout << (axisymmetric ? "axisymmetric" : "plane strain")
              << (boxes.empty() ? "" : ", refined " + boxes) << std::endl;
    TwoBlocks  tied(false, axisymmetric, boxes), apart(true, axisymmetric, boxes);
    auto      &system = *apart.scene->system;
    const auto shared = [](const std::vector<unsigned int> &used) {
      return std::count(used.begin(), used.end(), 3u);
    };
    const auto n_shared = shared(users(*tied.scene->system));
    const auto n_copies = system.point_cache().n_function_copies();
    std::cout << "  " << n_shared << " functions on both blocks without separation, " << n_copies
              << " copies with it" << std::endl;
    bool ok = report("functions on both blocks without separation", n_shared > 10);
    ok &= report("none with it", shared(users(system)) == 0);
    ok &= report("one copy per function that was on both", n_copies == n_shared);
    ok &=
      report("the copies are unknowns",
             system.spaces().n_u_dofs() == tied.scene->system->spaces().n_u_dofs() + 2 * n_copies);
    ok &= report("the next setup keeps the pattern", !system.setup(apart.scene->particles));
    const auto &ties = system.point_cache().copy_ties();
    std::cout << "  " << ties.size()
              << " copies tied to their face's functions (a quarter of the weight or less)"
              << std::endl;
    // Lagrange extrapolation (eq. (54)) reproduces constants: the weights sum to 1.
    double sum_error = 0.;
    for (const auto &tie : ties)
      {
        double sum = 0.;
        for (const auto &[dof, E] : tie.donors)
          sum += E;
        sum_error = std::max(sum_error, std::abs(sum - 1.));
      }
    ok &= report("weak copies tied, their weights summing to 1 (1e-12)",
                 !ties.empty() && sum_error < 1e-12);
    system.set_boundary_values(0.5, 0.);

    // The upper block alone moved rigidly.
    const double         dt      = 0.05;
    const Vector<double> at_rest = shifted_state(*apart.scene, 0., 0.);
    const Vector<double> moved   = shifted_state(*apart.scene, -0.04, 0.);
    double               error   = 0.;
    const auto          &cache   = system.point_cache();
    for (const auto &r : cache.points())
      if (r.assembled)
        {
          const auto fields = cache.fields_at(r, moved);
          error = std::max(error, std::abs(fields.du[1] - (r.X0[1] > split ? -0.04 : 0.)));
          error = std::max(error, std::abs(fields.du[0]));
        }
    ok &= report("upper points moved by -0.04, lower ones by 0 (1e-12)", error < 1e-12);
    system.assemble(at_rest, dt, false);
    Vector<double> residual_at_rest(system.residual());
    system.assemble(moved, dt, false);
    double difference = 0.;
    for (unsigned int i = 0; i < system.spaces().n_dofs(); ++i)
      difference = std::max(difference, std::abs(system.residual()(i) - residual_at_rest(i)));
    // The scale: a tenth of the shift on the tied grid, which compresses the lower block's top
    // (the whole shift takes it out of the physical range on the refined grid).
    auto &tied_system = *tied.scene->system;
    tied_system.assemble(shifted_state(*tied.scene, -0.004, 0.), dt, false);
    const double tied_residual = tied_system.residual().linfty_norm();
    ok &= report("residual unchanged by the shift (1e-10 of the tied grid's for a tenth of it)",
                 tied_residual > 0. && difference <= 1e-10 * tied_residual);

    // The tangent with the copies and the contact active.
    const Vector<double> pressed = shifted_state(*apart.scene, -0.07, 2e-4);
    std::cout << "  " << system.self_contact_state(pressed).points
              << " points in contact on the pressed state" << std::endl;
    ok &= report("points in contact", system.self_contact_state(pressed).points > 0);
    const unsigned int n = system.spaces().n_dofs();
    system.assemble(pressed, dt, true);
    const MatrixEntries K(system.matrix());
    std::vector<bool>   on_axis(n, false);
    for (const auto i : system.spaces().axis_unknowns())
      on_axis[i] = true;
    double largest = 0., deviation = 0.;
    for (unsigned int j = 0; j < n; ++j)
      {
        if (on_axis[j])
          continue;
        const double   h = j < system.spaces().n_u_dofs() ? 1e-7 : 1e-6;
        Vector<double> plus(pressed), minus(pressed);
        plus(j) += h;
        minus(j) -= h;
        system.assemble(plus, dt, false);
        Vector<double> fd(system.residual());
        system.assemble(minus, dt, false);
        fd -= system.residual();
        fd /= 2. * h;
        for (unsigned int i = 0; i < n; ++i)
          if (!on_axis[i])
            {
              deviation = std::max(deviation, std::abs(K.at(i, j) - fd(i)));
              largest   = std::max(largest, std::abs(K.at(i, j)));
            }
      }
    std::cout << "  |K - K_fd| / max|K| = " << (deviation < 1e-6 * largest ? "< 1e-6" : "larger")
              << std::endl;
    ok &= report("tangent = finite differences (1e-6)", deviation <= 1e-6 * largest);
    return ok;
  }
} // namespace


int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bool                             ok = check_separation(false);
  ok &= check_separation(true);
  std::cout << (ok ? "face separation checks passed" : "FACE SEPARATION CHECKS FAILED")
            << std::endl;
  return ok ? 0 : 1;
}
