#ifndef gelmpm_io_piece_table_h
#define gelmpm_io_piece_table_h

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
   * that a selector that took the wrong points shows before the run. Collective over
   * @p communicator; the text is the same on every rank.
   */
  template <int dim>
  std::string
  piece_table(const dealii::Particles::ParticleHandler<dim> &particles,
              const std::vector<std::string>                &piece_names,
              const MPI_Comm                                 communicator);
} // namespace GelMPM

#endif
