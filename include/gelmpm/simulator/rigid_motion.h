#ifndef gelmpm_simulator_rigid_motion_h
#define gelmpm_simulator_rigid_motion_h

#include <gelmpm/assembly/contact_settings.h>
#include <gelmpm/scene/boundary_conditions.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>
#include <deal.II/particles/particle_handler.h>

#include <string>
#include <vector>

namespace GelMPM
{
  /**
   * The rigid motions of the body (translations along x, y (, z) and rotations about the body's
   * centre) that nothing holds: no surface point prescribes a component of the displacement
   * along which the motion moves it ('Displacement' of its piece: fixed, normal, tangential at
   * its initial normal), and no contact plane ('Contact/Grid sides', taken as a roller over the
   * body's extent) lies across it. Such a motion is in the null space of the tangent: the solve
   * gives it an arbitrary amount made of round-off. Each entry names the motion ("translation
   * along x", "rotation about z"), or a combination that is not one of these; empty when the
   * body is held. Collective over @p communicator.
   *
   * In an axisymmetric scene (@p axisymmetric) the axis holds the radial translation and the
   * rotation (u_r = 0 there): only the translation along the axis (y) can be unheld.
   */
  template <int dim>
  std::vector<std::string>
  unheld_rigid_motions(const dealii::Particles::ParticleHandler<dim> &particles,
                       const BoundaryConditions<dim>                 &boundary_conditions,
                       const ContactSettings                         &contact,
                       const dealii::Point<dim>                      &grid_lower,
                       const dealii::Point<dim>                      &grid_upper,
                       const MPI_Comm                                 communicator,
                       const bool                                     axisymmetric = false);
} // namespace GelMPM

#endif
