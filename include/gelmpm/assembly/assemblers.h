#ifndef gelmpm_assembly_assemblers_h
#define gelmpm_assembly_assemblers_h

#include <gelmpm/assembly/contact_settings.h>
#include <gelmpm/assembly/discretisation.h>
#include <gelmpm/assembly/nitsche_settings.h>
#include <gelmpm/assembly/point_assembler.h>
#include <gelmpm/scene/boundary_conditions.h>
#include <gelmpm/scene/obstacle.h>

#include <memory>
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
   * traction, displacement Nitsche, contact, chemical-potential Nitsche and solvent flux. A term
   * is left out where no piece asks for it (no displacement Nitsche term on a body without
   * prescribed displacements, no contact term with contact off), so a run does no work for what
   * is off; a term that is left out is one that would add nothing at any point, so the sums of
   * the others are those of the full list, bit for bit. One line adds a term; a new term goes to
   * the end of its kind.
   */
  template <int dim>
  std::vector<std::unique_ptr<PointAssembler<dim>>>
  setup_assemblers(const AssemblerInputs<dim> &inputs);
} // namespace GelMPM

#endif
