// 'Observables/Shape pieces' on the bilayer actuator (prm/bilayer_actuator.prm) on a coarse grid
// (h = 1/30, six cells through the thickness 0.2; the scene has eight), to 10 tau_d: the fitted
// curvature of the lower face against Timoshenko's bending of the drained strip, computed here
// from the gel law (GelReferences: each layer's plane-strain free-swelling stretch a_k at the
// bath's mu = -0.04 and its drained plane-strain modulus; swollen thicknesses 0.1 a_k):
// - the lower face is concave (the strip curls towards the passive layer), so its curvature is
//   negative, and its magnitude lies within 2% of Timoshenko's 0.19589 (+0.76% measured; the
//   scene's grid +0.55%, doc/own_scenes.md section 6: the formula's own error at 3.3% mismatch is
//   about +0.45%, the peer's mesh limit);
// - its points lie on the fitted circle: RMS distance below 1% of a cell (0.24% measured);
// - the face bends without relief: relative amplitude below 0.01 (at most 0.0024 during the run),
// and with
//   'Instability threshold = 0.01' no instability event.
#include <gelmpm/material/flory_rehner_gel.h>
#include <gelmpm/material/gel_references.h>

#include <deal.II/base/mpi.h>

#include <cmath>
#include <fstream>
#include <iostream>
#include <string>

#include "../scene_run.h"

namespace
{
  /** The Table 1 gel (G = 1, N nu = 7.299e-3) with @p chi at the scene's mu_0 (lambda_0 = 1.2801
   * for chi = 0.1). */
  GelMPM::FloryRehnerGel<2>
  gel(const double chi)
  {
    const double N_nu = 7.299e-3;
    const double mu_0 = GelMPM::FloryRehnerGel<2>::mu_0_from_lambda_0(1.2801, 0.1, N_nu);
    return GelMPM::FloryRehnerGel<2>(1.,
                                     chi,
                                     N_nu,
                                     1.,
                                     GelMPM::FloryRehnerGel<2>::lambda_0_from_mu_0(mu_0,
                                                                                   chi,
                                                                                   N_nu));
  }

  /** The number of rows of events.csv in @p directory whose event starts with @p prefix. */
  unsigned int
  events_starting(const std::string &directory, const std::string &prefix)
  {
    std::ifstream in(directory + "/events.csv");
    unsigned int  count = 0;
    for (std::string line; std::getline(in, line);)
      count += line.rfind(prefix, 0) == 0;
    return count;
  }
} // namespace


int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::cout << std::boolalpha;

  const double                mu_b       = -0.04;
  const auto                  kinematics = GelMPM::SwellingKinematics::plane_strain;
  const GelMPM::GelReferences active(gel(0.1)), passive(gel(0.3));
  const double                a_1 = active.free_swelling(mu_b, kinematics).stretch_from_initial;
  const double                a_2 = passive.free_swelling(mu_b, kinematics).stretch_from_initial;
  const double                timoshenko =
    GelMPM::timoshenko_curvature(a_1 / a_2 - 1.,
                                 0.1 * a_1,
                                 0.1 * a_2,
                                 active.drained_moduli(mu_b, kinematics).plane_strain_modulus,
                                 passive.drained_moduli(mu_b, kinematics).plane_strain_modulus);

  const double h = 1. / 30.;
  const auto   run =
    GelMPMTests::run_scene(std::string(SOURCE_DIR) + "/../../prm/bilayer_actuator.prm",
                           "shape_fits_bilayer",
                           {"Background grid/Cells=90, 42",
                            "Observables/Shape pieces=bottom",
                            "Observables/Instability threshold=0.01"});
  std::cout << "run completed: " << (run.status == 0) << std::endl;
  const double curvature = run.statistics.at("bottom_fit_curvature").back();
  std::cout << "the lower face is concave: " << (curvature < 0.) << std::endl;
  const bool close = std::abs(-curvature / timoshenko - 1.) <= 0.02;
  std::cout << "its fitted curvature within 2% of Timoshenko's: " << close << std::endl;
  if (!close)
    std::cout << "  (" << -curvature << " against " << timoshenko << ")" << std::endl;
  std::cout << "its points within 1% of a cell of the circle (RMS): "
            << (run.statistics.at("bottom_fit_residual").back() < 0.01 * h) << std::endl;
  std::cout << "no relief: relative amplitude below 0.01: "
            << (run.statistics.at("bottom_relative_amplitude").back() < 0.01) << std::endl;
  std::cout << "no instability event: "
            << (events_starting("shape_fits_bilayer", "instability_") == 0) << std::endl;
  return 0;
}
