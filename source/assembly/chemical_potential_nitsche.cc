#include <gelmpm/assembly/chemical_potential_nitsche.h>

namespace GelMPM
{
  template <int dim>
  void
  ChemicalPotentialNitscheAssembler<dim>::set_contact(const ContactAssembler<dim> &assembler)
  {
    contact = &assembler;
  }


  template <int dim>
  void
  ChemicalPotentialNitscheAssembler<dim>::assemble(const PointRecord<dim> &point,
                                                   const double            dt,
                                                   const bool              with_matrix,
                                                   AssemblyScratch<dim>   &s,
                                                   AssemblyCopy           &copy) const
  {
    if (!this->piece(point).chemical_potential_prescribed() ||
        (contact != nullptr && contact->seals(point, s.du_at_point, s.delta_F, s.mu_at_point)))
      return;
    const double       area = point.measure;
    const auto        &N    = point.normal;
    const double       sym  = this->nitsche.symmetry;
    const unsigned int mu0  = dim * s.n_u;
    auto              &K    = copy.matrix;
    auto              &r    = copy.residual;
    const double       m    = point.mobility;
    const double       beta_mu =
      this->nitsche.chemical_potential_penalty * m / this->spaces.h_mu(point.level);
    const double diff = s.mu_at_point - point.mu_bar;
    const double gN   = s.grad_mu * N;
    for (unsigned int b = 0; b < s.n_mu; ++b)
      r(mu0 + b) +=
        dt * area * (m * gN * s.M[b] + sym * m * (s.GM[b] * N) * diff - beta_mu * diff * s.M[b]);
    if (with_matrix)
      for (unsigned int b = 0; b < s.n_mu; ++b)
        for (unsigned int d = 0; d < s.n_mu; ++d)
          K(mu0 + b, mu0 + d) += dt * area *
                                 (m * (s.GM[d] * N) * s.M[b] + sym * m * (s.GM[b] * N) * s.M[d] -
                                  beta_mu * s.M[b] * s.M[d]);
  }


  template class ChemicalPotentialNitscheAssembler<2>;
  template class ChemicalPotentialNitscheAssembler<3>;
} // namespace GelMPM
