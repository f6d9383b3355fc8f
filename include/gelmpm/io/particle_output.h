#ifndef gelmpm_io_particle_output_h
#define gelmpm_io_particle_output_h

#include <gelmpm/io/pvd_series.h>
#include <gelmpm/material/flory_rehner_gel.h>
#include <gelmpm/scene/material_regions.h>

#include <deal.II/particles/particle_handler.h>

#include <string>
#include <utility>
#include <vector>

namespace GelMPM
{
  /**
   * @brief Writes the material points for ParaView: one `particles-NNNNN.vtu` per output time and
   * the series `particles.pvd` with the simulated times (a PvdSeries).
   *
   * Fields per point: kind (PointKind), piece, mu_over_kT, J (dry to current), phi = 1 - 1/J (the
   * solvent volume fraction), measure (V_n or A_n), the principal in-plane stretches of F_n F_0
   * (stretch_1 <= stretch_2 ...), the Cauchy stress sigma = P F^T / J (tensor), the displacement
   * from the initial configuration and N_n A_n (vectors). Derived fields are computed when written,
   * so they cost nothing between outputs.
   */
  template <int dim>
  class ParticleOutput
  {
  public:
    /** A series in @p directory; on several ranks of @p communicator each writes its points. */
    ParticleOutput(const std::string          &directory,
                   const MaterialRegions<dim> &materials,
                   const MPI_Comm              communicator = MPI_COMM_SELF);

    /** Write the points at @p time (in tau_d) and update the .pvd series. */
    void
    write(const dealii::Particles::ParticleHandler<dim> &particles, const double time);

    /** (time, file name) of every output so far. */
    const std::vector<std::pair<double, std::string>> &
    times_and_names() const;

    /** The series so far, for a checkpoint (boost serialization). */
    template <class Archive>
    void
    serialize(Archive &ar, const unsigned int)
    {
      ar &series;
    }

    /** After a checkpoint was read: PvdSeries::restore_files(). */
    void
    restore_files() const
    {
      series.restore_files();
    }

  private:
    const MaterialRegions<dim> &materials;
    PvdSeries                   series;
  };
} // namespace GelMPM

#endif
