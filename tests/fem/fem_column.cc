// The body-fitted finite-element peer on the swell-induced buckling of a gel column (paper §4.3,
// FemColumn: Taylor-Hood Q2-Q1 on n x 8n cells of the column [0, H] x [0, 8H], mu on the sides
// ramped from mu_0 to 0 over t_inc = 0.75 tau_d, rollers on the ends), steps capped at 0.02 tau_d,
// a loss of stability bracketed to 1e-3 tau_d by the signature of the tangent. Asserted:
// - the signature: on 1 x 8 cells, at every converged step, the numbers of positive, negative
//   and zero eigenvalues of the tangent counted densely (LAPACK, on the lower triangle that
//   MUMPS reads) equal the LDL^T inertia; and the state is judged stable exactly when they equal
//   the expectation corrected for the constrained rows (FemTangentSignature), which differs from
//   the uncorrected (n_u, n_mu, 0) since the rows of the prescribed mu carry positive diagonal
//   entries;
// - the onset: on 4 x 32 and 8 x 64 cells exactly one loss of stability before 0.4 tau_d, each
//   bracketed to at most 1e-3 tau_d; it rises under refinement towards the paper's
//   t_onset = 0.28 tau_d but lies below it on these meshes: on 8 x 64 cells within 0.005 tau_d of
//   the measured 0.2516 tau_d, which is 10.1 % below 0.28 (printed, not required). Finer meshes
//   (16 x 128: 0.264 tau_d) and the mesh study are in doc/fem_peer.md, "The buckling onset of
//   the §4.3 column"; they take longer than a test should;
// - the drained criterion (--onset-criterion drained): on 1 x 8 cells, at every step the dense
//   count of the K_uu block's eigenvalues equals its LDL^T inertia, K_uu is judged definite
//   exactly when that equals the expectation corrected for the constrained rows, and the one
//   onset it brackets lies at or before the tangent criterion's.
#include <gelmpm/core/parameters.h>
#include <gelmpm/fem/fem_column.h>

#include <deal.II/base/mpi.h>
#include <deal.II/lac/lapack_full_matrix.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <vector>

using GelMPM::FemColumn;

namespace
{
  /** The inertia of the symmetric matrix whose lower triangle @p K holds, from its eigenvalues
   * (|lambda| <= 1e-12 max |lambda| counts as zero). */
  GelMPM::Inertia
  dense_inertia(const dealii::TrilinosWrappers::SparseMatrix &K, const unsigned int leading = 0)
  {
    // With @p leading > 0: the leading block of that size (K_uu).
    const unsigned int               n = leading > 0 ? leading : K.m();
    dealii::LAPACKFullMatrix<double> dense(n, n);
    for (unsigned int row = 0; row < n; ++row)
      for (auto entry = K.begin(row); entry != K.end(row); ++entry)
        if (entry->column() <= row)
          {
            dense(row, entry->column()) = entry->value();
            dense(entry->column(), row) = entry->value();
          }
    dense.compute_eigenvalues();
    double largest = 0.;
    for (unsigned int i = 0; i < n; ++i)
      largest = std::max(largest, std::abs(dense.eigenvalue(i).real()));
    GelMPM::Inertia inertia;
    for (unsigned int i = 0; i < n; ++i)
      {
        const double lambda = dense.eigenvalue(i).real();
        if (std::abs(lambda) <= 1e-12 * largest)
          ++inertia.n_zero;
        else
          (lambda > 0. ? inertia.n_positive : inertia.n_negative) += 1;
      }
    return inertia;
  }


  GelMPM::FemRunSettings
  settings()
  {
    return GelMPM::fem_run_settings({{"Characteristic length", "0.5"},
                                     {"Initial step", "0.02"},
                                     {"End time", "0.4"},
                                     {"Step caps", "1: 0.02"}},
                                    {});
  }
} // namespace


int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  std::cout << std::boolalpha;
  const GelMPM::FloryRehnerGel<2> material; // Table 1
  const auto                      run_settings = settings();

  // (a) The signature against a dense eigenvalue count, on a tiny mesh.
  double tangent_onset = 0.;
  {
    FemColumn::Parameters parameters;
    parameters.cells = 1;
    FemColumn    column(material, parameters);
    const auto  &system = column.system();
    unsigned int steps = 0, agreeing = 0, judged_right = 0, unstable = 0, uncorrected_differs = 0;
    const auto   result =
      column.run(run_settings.time_stepping,
                 run_settings.newton,
                 GelMPM::LinearSolver(),
                 1e-3,
                 0.,
                 [&](const FemColumn::Step &s) {
                   // The matrix is still the converged attempt's tangent.
                   const auto  dense     = dense_inertia(system.matrix());
                   const auto &signature = s.signature;
                   ++steps;
                   agreeing += (dense == signature.measured);
                   judged_right += ((dense == signature.expected) == signature.stable());
                   unstable += !signature.stable();
                   const GelMPM::Inertia uncorrected{system.n_u_dofs(), system.n_mu_dofs(), 0};
                   uncorrected_differs += !(uncorrected == signature.expected);
                 });
    std::cout << "1 x 8 cells (" << system.n_dofs() << " DoFs): run completed: " << result.completed
              << "; dense eigenvalue count equals the LDL^T inertia at every step: "
              << (agreeing == steps) << "; stable exactly when it equals the corrected "
              << "expectation: " << (judged_right == steps)
              << "; the correction matters (uncorrected expectation differs): "
              << (uncorrected_differs == steps) << "; steps checked: more than 10: " << (steps > 10)
              << "; unstable steps among them: " << (unstable > 0) << std::endl;
    tangent_onset = result.onsets.empty() ? 0. : result.onsets[0].t_unstable;
  }

  // (d) The drained criterion (K_uu indefinite) on the same mesh: its inertia against a dense
  // count of the K_uu block, and its onset at or before the tangent's.
  {
    FemColumn::Parameters parameters;
    parameters.cells         = 1;
    parameters.drained_onset = true;
    FemColumn    column(material, parameters);
    const auto  &system = column.system();
    unsigned int steps = 0, agreeing = 0, judged_right = 0;
    const auto   result =
      column.run(run_settings.time_stepping,
                 run_settings.newton,
                 GelMPM::LinearSolver(),
                 1e-3,
                 0.,
                 [&](const FemColumn::Step &s) {
                   const auto  dense     = dense_inertia(system.matrix(), system.n_u_dofs());
                   const auto &signature = s.signature;
                   ++steps;
                   agreeing += (dense == signature.drained_measured);
                   judged_right +=
                     ((dense == signature.drained_expected) == signature.drained_stable());
                 });
    const bool one = result.onsets.size() == 1;
    std::cout << "1 x 8 cells, drained criterion: run completed: " << result.completed
              << "; dense eigenvalue count of K_uu equals its LDL^T inertia at every step: "
              << (agreeing == steps) << "; K_uu definite exactly when it equals the corrected "
              << "expectation: " << (judged_right == steps) << "; one onset: " << one
              << "; at or before the tangent criterion's: "
              << (one && result.onsets[0].t_unstable <= tangent_onset + 1e-12) << std::endl;
  }

  // (b), (c) The onset on two coarse meshes.
  std::vector<double> onsets;
  for (const unsigned int cells : {4u, 8u})
    {
      FemColumn::Parameters parameters;
      parameters.cells = cells;
      FemColumn  column(material, parameters);
      const auto result = column.run(run_settings.time_stepping,
                                     run_settings.newton,
                                     GelMPM::LinearSolver(),
                                     1e-3,
                                     0.,
                                     nullptr);
      std::cout << cells << " x " << 8 * cells << " cells (" << column.system().n_dofs()
                << " DoFs): run completed: " << result.completed
                << "; losses of stability bracketed: " << result.onsets.size() << std::endl;
      for (const auto &onset : result.onsets)
        {
          const double width = onset.t_unstable - onset.t_stable;
          const double t_mid = 0.5 * (onset.t_stable + onset.t_unstable);
          onsets.push_back(t_mid);
          std::cout << "  bracket at most 1e-3 tau_d wide: " << (width <= 1e-3 * (1. + 1e-9))
                    << "; before 0.4 tau_d: " << (onset.t_unstable <= 0.4)
                    << "; t_onset/tau_d = " << std::fixed << std::setprecision(2) << t_mid
                    << std::defaultfloat << std::endl;
        }
    }
  // Measured: 0.2181-0.2188 (4 x 32) and 0.2513-0.2519 (8 x 64); the paper's 0.28 is approached
  // from below under refinement (16 x 128: 0.2638-0.2644, doc/fem_peer.md).
  if (onsets.size() == 2)
    {
      std::cout << "onset rises under refinement towards the paper's 0.28: "
                << (onsets[0] < onsets[1] && onsets[1] < 0.28)
                << "; 8 x 64 onset within 0.005 tau_d of the measured 0.2516: "
                << (std::abs(onsets[1] - 0.2516) <= 0.005)
                << "; within 10 % of the paper's 0.28: " << (std::abs(onsets[1] - 0.28) <= 0.028)
                << std::endl;
      if (!(std::abs(onsets[1] - 0.2516) <= 0.005))
        std::cout << "  (onsets " << std::setprecision(8) << onsets[0] << ", " << onsets[1] << ")"
                  << std::endl;
    }
  return 0;
}
