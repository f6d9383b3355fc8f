#ifndef gelmpm_assembly_assemblers_h
#define gelmpm_assembly_assemblers_h

#include <gelmpm/assembly/contact.h>
#include <gelmpm/assembly/contact_settings.h>
#include <gelmpm/assembly/discretisation.h>
#include <gelmpm/assembly/nitsche_settings.h>
#include <gelmpm/assembly/point_assembler.h>
#include <gelmpm/assembly/point_cache.h>
#include <gelmpm/assembly/self_contact.h>
#include <gelmpm/scene/boundary_conditions.h>
#include <gelmpm/scene/obstacle.h>

#include <memory>
#include <utility>
#include <vector>

namespace GelMPM
{
  /** @brief What the terms of a scene are built from (the assemblers' constructors' arguments). */
  template <int dim>
  struct AssemblerInputs
  {
    const BoundaryConditions<dim> &boundary_conditions;
    const NitscheSettings         &nitsche;
    const DiscreteSpaces<dim>     &spaces;
    const TangentOptions          &tangent;
    /** The "Contact" section (method none: no contact term). */
    const ContactSettings &contact;
    /** The scene's rigid obstacles, which the contact term refers to (nullptr: none). */
    const std::vector<Obstacle<dim>> *obstacles;
  };


  /**
   * The terms of the weak form that the scene of @p inputs needs, in the order of the
   * floating-point sums (Lethe's setup_assemblers()): the volume term, then at the surface points
   * traction, displacement Nitsche, contact, chemical-potential Nitsche, solvent flux and the
   * gel's contact with itself (2D, which adds beyond the blocks only). A term
   * is left out where no piece asks for it (no displacement Nitsche term on a body without
   * prescribed displacements, no contact term with contact off), so a run does no work for what
   * is off; a term that is left out is one that would add nothing at any point, so the sums of
   * the others are those of the full list, bit for bit. One line adds a term; a new term goes to
   * the end of its kind.
   */
  template <int dim>
  std::vector<std::unique_ptr<PointAssembler<dim>>>
  setup_assemblers(const AssemblerInputs<dim> &inputs);


  /**
   * @brief The terms of a system: the scene's (setup_assemblers()) and those added to them
   * (add()), in the order of the sums, and the views the assembly loops over (the terms at volume
   * points, those at surface points). It knows one term by its kind, contact, whose state and
   * reactions the system reports, and the contact of the gel with itself, whose state it reports.
   */
  template <int dim>
  class TermList
  {
  public:
    /** The scene's terms anew from @p inputs; the added terms stay after them. */
    void
    build(const AssemblerInputs<dim> &inputs);

    /** Add @p term to the end. */
    void
    add(std::unique_ptr<PointAssembler<dim>> term);

    /** Every term, in the order of the sums. */
    const std::vector<const PointAssembler<dim> *> &
    all() const;

    /** The terms at volume points, and those at the surface points of a piece, in order. */
    const std::vector<const PointAssembler<dim> *> &
    at_volume_points() const;
    const std::vector<const PointAssembler<dim> *> &
    at_surface_points() const;

    /** The contact term (nullptr: contact off). */
    const ContactAssembler<dim> *
    contact() const;

    /** The term of the gel's contact with itself (nullptr: 'Contact/Self contact' off). */
    const SelfContactAssembler<dim> *
    self_contact() const;

    /** The pairs of cells the terms couple beyond the blocks of @p cache
     * (PointAssembler::add_cell_couplings()), each (a, b) with a < b, sorted, once each. */
    std::vector<std::pair<unsigned int, unsigned int>>
    cell_couplings(const PointCache<dim> &cache) const;

  private:
    /** The views of the owned terms. */
    void
    index();

    std::vector<std::unique_ptr<PointAssembler<dim>>> scene_terms, added_terms;
    std::vector<const PointAssembler<dim> *>          terms, volume_terms, surface_terms;
    const ContactAssembler<dim>                      *contact_term      = nullptr;
    const SelfContactAssembler<dim>                  *self_contact_term = nullptr;
  };
} // namespace GelMPM

#endif
