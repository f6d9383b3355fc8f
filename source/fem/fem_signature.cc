#include <gelmpm/fem/fem_signature.h>

namespace GelMPM
{
  template <int dim>
  FemTangentSignature<dim>::FemTangentSignature(const FemMixedSystem<dim> &system,
                                                const bool                 drained)
    : system(system)
    , drained(drained)
  {}


  template <int dim>
  FemSignature
  FemTangentSignature<dim>::expected(const FemMixedSystem<dim> &system)
  {
    const auto  &K           = system.matrix();
    const auto  &constraints = system.increment_constraints();
    FemSignature signature;
    unsigned int positive = 0, negative = 0, zero = 0;
    Inertia      constrained_u_signs;
    for (unsigned int i = 0; i < system.n_dofs(); ++i)
      if (constraints.is_constrained(i))
        {
          (i < system.n_u_dofs() ? signature.constrained_u : signature.constrained_mu) += 1;
          // The only entry of the row and column: an eigenvalue of K by itself.
          const double diagonal = K.diag_element(i);
          (diagonal > 0. ? positive : diagonal < 0. ? negative : zero) += 1;
          if (i < system.n_u_dofs())
            (diagonal > 0.   ? constrained_u_signs.n_positive
             : diagonal < 0. ? constrained_u_signs.n_negative
                             : constrained_u_signs.n_zero) += 1;
        }
    signature.drained_expected.n_positive =
      system.n_u_dofs() - signature.constrained_u + constrained_u_signs.n_positive;
    signature.drained_expected.n_negative = constrained_u_signs.n_negative;
    signature.drained_expected.n_zero     = constrained_u_signs.n_zero;
    signature.expected.n_positive         = system.n_u_dofs() - signature.constrained_u + positive;
    signature.expected.n_negative = system.n_mu_dofs() - signature.constrained_mu + negative;
    signature.expected.n_zero     = zero;
    return signature;
  }


  template <int dim>
  const FemSignature &
  FemTangentSignature<dim>::evaluate()
  {
    last_ = expected(system);
    factorization.factorize(system.matrix());
    last_.measured = factorization.inertia();
    if (drained)
      {
        // The displacement unknowns come first: the leading block is K_uu.
        factorization.factorize(system.matrix(), system.n_u_dofs());
        last_.drained_measured = factorization.inertia();
      }
    return last_;
  }


  template <int dim>
  const FemSignature &
  FemTangentSignature<dim>::last() const
  {
    return last_;
  }


  template class FemTangentSignature<2>;
  template class FemTangentSignature<3>;
} // namespace GelMPM
