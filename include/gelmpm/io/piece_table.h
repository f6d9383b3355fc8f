#ifndef gelmpm_io_piece_table_h
#define gelmpm_io_piece_table_h

#include <gelmpm/scene/material_regions.h>

#include <deal.II/base/mpi.h>
#include <deal.II/particles/particle_handler.h>

#include <string>
#include <vector>

namespace GelMPM
{
  /**
   * The table of a body's boundary pieces that a run prints at start-up (and `gelmpm --check`):
   * per piece of @p piece_names its surface points, their initial area and the range of each
   * component of their initial normal, and a row "(none)" for surface points of no piece, so
   * that a selector that took the wrong points shows before the run. In 2D the area is per unit
   * thickness, or with @p axisymmetric the revolved area (2 pi R ds). Collective over
   * @p communicator; the text is the same on every rank.
   */
  template <int dim>
  std::string
  piece_table(const dealii::Particles::ParticleHandler<dim> &particles,
              const std::vector<std::string>                &piece_names,
              const bool                                     axisymmetric,
              const MPI_Comm                                 communicator);

  /**
   * The table of a body's material regions that a run prints at start-up (and `gelmpm --check`)
   * when the scene has regions: per gel of @p regions (the section 'Material' first) its volume
   * points, their initial volume (per unit thickness in 2D, revolved with @p axisymmetric) and
   * the constants in which it differs from the section 'Material' (G, N nu, chi, D and the
   * initial stretch lambda_0 that follows), so that a selector that took the wrong part of the
   * body, or a constant in the wrong region, shows before the run. Empty with one gel.
   * Collective over @p communicator; the text is the same on every rank.
   */
  template <int dim>
  std::string
  region_table(const dealii::Particles::ParticleHandler<dim> &particles,
               const MaterialRegions<dim>                    &regions,
               const bool                                     axisymmetric,
               const MPI_Comm                                 communicator);
} // namespace GelMPM

#endif
