#include <gelmpm/core/input_error.h>
#include <gelmpm/stability/schur_eigenvalues.h>
#include <gelmpm/stability/stability_analysis.h>

namespace GelMPM
{
  void
  StabilitySettings::declare_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Stability");
    prm.declare_entry("Inertia",
                      "false",
                      dealii::Patterns::Bool(),
                      "After every converged step, the signature (n+, n-, n0) of the tangent from "
                      "its symmetric LDL^T factorisation (MUMPS): columns n_pos, n_neg, n_zero. A "
                      "stable state has (n_dofs_u, n_dofs_mu, 0). Needs the symmetric Nitsche "
                      "variant.");
    prm.declare_entry(
      "Schur eigenvalues",
      "0",
      dealii::Patterns::Integer(0, 50),
      "k > 0: after every converged step, the k eigenvalues of smallest magnitude of "
      "the Schur complement S = K_uu - K_umu K_mumu^-1 K_muu (paper eq. (63)), by "
      "ARPACK in shift-invert mode: columns eig_1 ... eig_k. 0: off.");
    prm.leave_subsection();
  }


  void
  StabilitySettings::parse_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Stability");
    inertia       = prm.get_bool("Inertia");
    n_eigenvalues = prm.get_integer("Schur eigenvalues");
    prm.leave_subsection();
  }


  bool
  StabilitySettings::enabled() const
  {
    return inertia || n_eigenvalues > 0;
  }


  std::vector<std::string>
  StabilitySettings::columns() const
  {
    std::vector<std::string> c;
    if (inertia)
      c = {"n_pos", "n_neg", "n_zero"};
    for (unsigned int k = 0; k < n_eigenvalues; ++k)
      c.push_back("eig_" + std::to_string(k + 1));
    return c;
  }


  StabilityReport
  analyse_stability(const dealii::TrilinosWrappers::SparseMatrix &K,
                    const unsigned int                            n_u,
                    const StabilitySettings                      &settings)
  {
    StabilityReport        report;
    SymmetricFactorization factorization;
    factorization.factorize(K);
    report.inertia = factorization.inertia();
    if (settings.n_eigenvalues > 0)
      report.eigenvalues =
        smallest_schur_eigenvalues(factorization, n_u, settings.n_eigenvalues).values;
    return report;
  }
} // namespace GelMPM
