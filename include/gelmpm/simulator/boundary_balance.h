#ifndef gelmpm_simulator_boundary_balance_h
#define gelmpm_simulator_boundary_balance_h

#include <gelmpm/assembly/mixed_system.h>
#include <gelmpm/io/statistics_file.h>
#include <gelmpm/material/flory_rehner_gel.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/particles/particle_handler.h>

#include <boost/serialization/vector.hpp>
#include <string>
#include <vector>

namespace GelMPM
{
  /**
   * @brief 'Observables/Forces and fluxes': per boundary piece and step, the force that the
   * piece exerts on the body and the solvent that enters through it, and the body's solvent
   * volume with the balance of the two (columns of statistics.csv). Off unless the scene names
   * pieces; then one pass over the surface points and one over the volume points per accepted
   * step.
   *
   * Columns, for each piece P named:
   * - P_force_x, P_force_y (, P_force_z): the force on the body, the piece's traction, Nitsche
   *   and contact terms integrated over its surface points (MixedSystem::boundary_balances()),
   *   in G times length^(dim-1); per unit thickness in 2D. The reaction on a support or a punch
   *   is its negative.
   * - P_inflow: the solvent volume entering per unit time (the scene's time unit, as the column
   *   'time'), over the last step; negative for outflow.
   * - P_solvent_in: the solvent volume that has entered through P since the start.
   * and once:
   * - solvent_volume: the body's solvent volume, sum over the volume points of V_n (1 - 1/J)
   *   (J from the dry state);
   * - solvent_imbalance: the change of solvent_volume since the start minus the inflow through
   *   all pieces since the start, over the largest |change| seen: the mass balance, zero to the
   *   Newton tolerance (a kick along an unstable mode moves the body without a flux and shows
   *   here).
   */
  template <int dim>
  class BoundaryBalance
  {
  public:
    /** Declare the entry in the section "Observables". */
    static void
    declare_parameters(dealii::ParameterHandler &prm);

    /** Read the entry; @p pieces are the scene's boundary pieces. Throws InputError. */
    void
    parse_parameters(dealii::ParameterHandler &prm, const std::vector<std::string> &pieces);

    /** Whether any piece is named. */
    bool
    enabled() const;

    /** The columns this adds to statistics.csv. */
    std::vector<std::string>
    columns() const;

    /**
     * The initial row: zero forces and inflows, the initial solvent volume (which the balance
     * refers to).
     */
    void
    record_initial(const dealii::Particles::ParticleHandler<dim> &particles,
                   const MaterialRegions<dim>                    &material,
                   StatisticsFile                                &statistics);

    /**
     * The row of a converged step of length @p dt (the scene's time unit): @p balances of every
     * piece (MixedSystem::boundary_balances()), the solvent volume of the updated @p particles.
     */
    void
    record_step(const std::vector<typename MixedSystem<dim>::PieceBalance> &balances,
                const double                                                dt,
                const dealii::Particles::ParticleHandler<dim>              &particles,
                const MaterialRegions<dim>                                 &material,
                StatisticsFile                                             &statistics);

    /** The run's sums, for a checkpoint (boost serialization). */
    template <class Archive>
    void
    serialize(Archive &ar, const unsigned int)
    {
      ar &solvent_volume_0 &largest_change &solvent_in;
    }

    /** The ranks that hold the body's points (default: this process alone). */
    void
    set_communicator(const MPI_Comm communicator);

    /** The body's solvent volume, sum over the volume points of V_n (1 - 1/J). Collective. */
    double
    solvent_volume(const dealii::Particles::ParticleHandler<dim> &particles,
                   const MaterialRegions<dim>                    &material) const;

  private:
    std::vector<unsigned int> pieces_shown; // indices into the scene's pieces
    std::vector<std::string>  piece_names;  // of all pieces
    MPI_Comm                  communicator     = MPI_COMM_SELF;
    double                    solvent_volume_0 = 0.;
    double                    largest_change   = 0.;
    std::vector<double>       solvent_in; // per piece, since the start
  };
} // namespace GelMPM

#endif
