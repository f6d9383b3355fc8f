#include <gelmpm/assembly/assemblers.h>
#include <gelmpm/assembly/chemical_potential_nitsche.h>
#include <gelmpm/assembly/contact.h>
#include <gelmpm/assembly/displacement_nitsche.h>
#include <gelmpm/assembly/neumann_terms.h>
#include <gelmpm/assembly/self_contact.h>
#include <gelmpm/assembly/volume_term.h>

#include <algorithm>

namespace GelMPM
{
  namespace
  {
    /** A term at the surface points of a piece, built from @p in. */
    template <template <int> class Term, int dim>
    std::unique_ptr<Term<dim>>
    surface_term(const AssemblerInputs<dim> &in)
    {
      return std::make_unique<Term<dim>>(in.boundary_conditions, in.nitsche, in.spaces, in.tangent);
    }
  } // namespace


  template <int dim>
  std::vector<std::unique_ptr<PointAssembler<dim>>>
  setup_assemblers(const AssemblerInputs<dim> &in)
  {
    using Piece = BoundaryPiece<dim>;
    // Whether some piece asks for a term: the condition under which the term adds something at
    // the points of a piece.
    const auto some_piece = [&in](const auto &condition) {
      for (unsigned int p = 0; p < in.boundary_conditions.n_pieces(); ++p)
        if (condition(in.boundary_conditions.piece(p)))
          return true;
      return false;
    };
    const auto not_fixed = [](const Piece &p) {
      return p.displacement_condition != Piece::DisplacementCondition::fixed;
    };
    const auto u_given = [](const Piece &p) {
      return p.displacement_prescribed();
    };
    const auto mu_given = [](const Piece &p) {
      return p.chemical_potential_prescribed();
    };
    const auto flux_given = [](const Piece &p) {
      return !p.chemical_potential_prescribed();
    };

    std::vector<std::unique_ptr<PointAssembler<dim>>> terms;
    const auto                                        add = [&terms](auto term) -> auto &
    {
      auto &added = *term;
      terms.push_back(std::move(term));
      return added;
    };
    add(std::make_unique<VolumeTermAssembler<dim>>(in.tangent));
    if (some_piece(not_fixed))
      add(surface_term<TractionAssembler>(in));
    if (some_piece(u_given))
      add(surface_term<DisplacementNitscheAssembler>(in));
    const ContactAssembler<dim> *contact = nullptr;
    if (in.contact.enabled())
      {
        auto &term = add(surface_term<ContactAssembler>(in));
        term.set_settings(in.contact, in.obstacles);
        contact = &term;
      }
    if (some_piece(mu_given))
      {
        auto &term = add(surface_term<ChemicalPotentialNitscheAssembler>(in));
        // An impermeable obstacle seals the surface it touches.
        if (contact != nullptr)
          term.set_contact(*contact);
      }
    if (some_piece(flux_given))
      add(surface_term<SolventFluxAssembler>(in));
    // The gel against itself adds nothing at its points, only beyond the blocks: last.
    if (in.contact.self_contact.enabled())
      add(surface_term<SelfContactAssembler>(in)).set_settings(in.contact.self_contact);
    return terms;
  }


  template <int dim>
  void
  TermList<dim>::build(const AssemblerInputs<dim> &inputs)
  {
    scene_terms = setup_assemblers(inputs);
    index();
  }


  template <int dim>
  void
  TermList<dim>::add(std::unique_ptr<PointAssembler<dim>> term)
  {
    added_terms.push_back(std::move(term));
    index();
  }


  template <int dim>
  void
  TermList<dim>::index()
  {
    terms.clear();
    volume_terms.clear();
    surface_terms.clear();
    contact_term      = nullptr;
    self_contact_term = nullptr;
    for (const auto *list : {&scene_terms, &added_terms})
      for (const auto &term : *list)
        {
          terms.push_back(term.get());
          (term->at_volume_points() ? volume_terms : surface_terms).push_back(term.get());
          if (const auto *contact = dynamic_cast<const ContactAssembler<dim> *>(term.get()))
            contact_term = contact;
          if (const auto *self = dynamic_cast<const SelfContactAssembler<dim> *>(term.get()))
            self_contact_term = self;
        }
  }


  template <int dim>
  const std::vector<const PointAssembler<dim> *> &
  TermList<dim>::all() const
  {
    return terms;
  }


  template <int dim>
  const std::vector<const PointAssembler<dim> *> &
  TermList<dim>::at_volume_points() const
  {
    return volume_terms;
  }


  template <int dim>
  const std::vector<const PointAssembler<dim> *> &
  TermList<dim>::at_surface_points() const
  {
    return surface_terms;
  }


  template <int dim>
  const ContactAssembler<dim> *
  TermList<dim>::contact() const
  {
    return contact_term;
  }


  template <int dim>
  const SelfContactAssembler<dim> *
  TermList<dim>::self_contact() const
  {
    return self_contact_term;
  }


  template <int dim>
  std::vector<std::pair<unsigned int, unsigned int>>
  TermList<dim>::cell_couplings(const PointCache<dim> &cache) const
  {
    std::vector<std::pair<unsigned int, unsigned int>> pairs;
    for (const auto *term : terms)
      term->add_cell_couplings(cache, pairs);
    for (auto &[a, b] : pairs)
      if (b < a)
        std::swap(a, b);
    std::sort(pairs.begin(), pairs.end());
    pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
    return pairs;
  }


  template class TermList<2>;
  template class TermList<3>;
  template std::vector<std::unique_ptr<PointAssembler<2>>>
  setup_assemblers(const AssemblerInputs<2> &);
  template std::vector<std::unique_ptr<PointAssembler<3>>>
  setup_assemblers(const AssemblerInputs<3> &);
} // namespace GelMPM
