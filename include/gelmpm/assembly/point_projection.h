#ifndef gelmpm_assembly_point_projection_h
#define gelmpm_assembly_point_projection_h

#include <gelmpm/assembly/discretisation.h>
#include <gelmpm/assembly/point_cache.h>

#include <deal.II/base/mpi.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>

#include <array>
#include <functional>
#include <memory>
#include <vector>

namespace GelMPM
{
  /**
   * @brief Particle-to-grid transfer: L2 projections onto the step's extended bases with the
   * volume points as quadrature (MixedSystem::mu_from_points(), displacement_from_points()), and
   * the mu mass matrix on the points (for the inf-sup analysis).
   *
   * The sparsity of the projections' mass matrices depends on the classification alone: it is
   * built on first use and kept until forget_patterns() (a new sparsity pattern of the step).
   * On several ranks the mass matrices are summed entry by entry over the ranks and every rank
   * solves the whole (small) projection.
   */
  template <int dim>
  class PointProjection
  {
  public:
    PointProjection(const PointCache<dim>     &cache,
                    const DiscreteSpaces<dim> &spaces,
                    const MPI_Comm             communicator);

    /**
     * The L2 projection over the volume points onto the displacement (@p displacement) or the
     * chemical potential basis of the @p n_components point values @p value(r, component):
     * per component, the coefficients c of M c = b, M_ij = sum_p V_p N_i N_j,
     * b_i = sum_p V_p N_i value_p. Returned interleaved (component fastest).
     */
    std::vector<double>
    project(const bool                                                           displacement,
            const unsigned int                                                   n_components,
            const std::function<double(const PointRecord<dim> &, unsigned int)> &value) const;

    /**
     * The mass matrix of the chemical-potential basis integrated on the volume points,
     * M_ij = sum_p V_p Ñ_i(x_p) Ñ_j(x_p), dense.
     */
    dealii::FullMatrix<double>
    mu_mass_matrix() const;

    /** Drop the projections' sparsity patterns (the classification has changed). */
    void
    forget_patterns();

  private:
    const PointCache<dim>     &cache;
    const DiscreteSpaces<dim> &spaces;
    const MPI_Comm             communicator;
    // The sparsity of the mass matrices (mu, displacement), built on first use after each new
    // pattern.
    mutable std::array<std::unique_ptr<dealii::SparsityPattern>, 2> patterns;
  };
} // namespace GelMPM

#endif
