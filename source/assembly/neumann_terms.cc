#include <gelmpm/assembly/neumann_terms.h>

namespace GelMPM
{
  template <int dim>
  void
  TractionAssembler<dim>::assemble(const PointRecord<dim> &point,
                                   const double /*dt*/,
                                   const bool /*with_matrix*/,
                                   AssemblyScratch<dim> &s,
                                   AssemblyCopy         &copy) const
  {
    // Traction on the components the piece leaves free.
    if (this->piece(point).displacement_condition ==
        BoundaryPiece<dim>::DisplacementCondition::fixed)
      return;
    const double                 area = point.measure;
    const dealii::Tensor<1, dim> t    = point.traction - point.projector * point.traction;
    for (unsigned int a = 0; a < s.n_u; ++a)
      for (unsigned int i = 0; i < dim; ++i)
        copy.residual(dim * a + i) -= area * t[i] * s.N[a];
  }


  template <int dim>
  void
  SolventFluxAssembler<dim>::assemble(const PointRecord<dim> &point,
                                      const double            dt,
                                      const bool /*with_matrix*/,
                                      AssemblyScratch<dim> &s,
                                      AssemblyCopy         &copy) const
  {
    if (this->piece(point).chemical_potential_prescribed())
      return;
    const double       area = point.measure;
    const double       kTnu = point.gel->kT_over_nu();
    const unsigned int mu0  = dim * s.n_u;
    for (unsigned int b = 0; b < s.n_mu; ++b)
      copy.residual(mu0 + b) += dt * area * kTnu * point.flux * s.M[b];
  }


  template class TractionAssembler<2>;
  template class TractionAssembler<3>;
  template class SolventFluxAssembler<2>;
  template class SolventFluxAssembler<3>;
} // namespace GelMPM
