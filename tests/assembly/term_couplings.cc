// The scene's list of terms (MixedSystem::assemblers(), setup_assemblers()) and the couplings a
// term declares beyond the blocks (PointAssembler::add_cell_couplings()), on the assembly scene:
// - the list holds the terms the scene needs: the volume term, traction, displacement and
//   chemical-potential Nitsche, solvent flux; the contact term only once contact is on;
// - a term added to the list that couples the first and the last block's cells (cells far apart,
//   with no unknown in common: the entries between them are not in the pattern before) puts
//   the entries between their unknowns into the pattern at the next setup(), both ways; the
//   setup after it keeps the pattern, as the couplings have not changed.
#include <gelmpm/assembly/point_assembler.h>

#include <deal.II/lac/vector.h>

#include <algorithm>
#include <iostream>
#include <memory>

#include "scene_fixture.h"

using namespace dealii;

namespace
{
  /** A term that adds nothing and couples the cells @p a and @p b. */
  class CouplingTerm : public GelMPM::PointAssembler<2>
  {
  public:
    CouplingTerm(const unsigned int a, const unsigned int b)
      : a(a)
      , b(b)
    {}

    bool
    at_volume_points() const override
    {
      return false;
    }

    void
    assemble(const GelMPM::PointRecord<2> &,
             const double,
             const bool,
             GelMPM::AssemblyScratch<2> &,
             GelMPM::AssemblyCopy &) const override
    {}

    void
    add_cell_couplings(const GelMPM::PointCache<2> &,
                       std::vector<std::pair<unsigned int, unsigned int>> &pairs) const override
    {
      pairs.emplace_back(b, a);
    }

  private:
    const unsigned int a, b;
  };


  bool
  report(const std::string &what, const bool ok)
  {
    std::cout << "  " << what << ": " << (ok ? "yes" : "no  FAIL") << std::endl;
    return ok;
  }


  /** Whether the tangent's pattern holds the entry (@p row, @p column). */
  bool
  in_pattern(const GelMPM::MixedSystem<2> &system,
             const unsigned int            row,
             const unsigned int            column)
  {
    const auto &matrix = system.matrix();
    for (auto entry = matrix.begin(row); entry != matrix.end(row); ++entry)
      if (entry->column() == column)
        return true;
    return false;
  }
} // namespace


int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  SceneFixture                     scene;
  auto                            &system = *scene.system;
  bool                             ok     = true;

  std::cout << "terms of the scene" << std::endl;
  ok &= report("five without contact", system.assemblers().size() == 5);
  GelMPM::ContactSettings contact;
  contact.method = GelMPM::ContactSettings::Method::penalty;
  contact.sides  = {"top"};
  system.set_contact(contact);
  ok &= report("six with contact", system.assemblers().size() == 6);

  std::cout << "a term's couplings between cells" << std::endl;
  // The first and the last cell with volume points: the first displacement unknown of one, the
  // last of the other (the chemical potential's cells are twice as large, and its extended
  // functions reach across most of the body).
  const auto  &spaces         = system.spaces();
  const auto  &classification = system.classification_of_pattern();
  unsigned int first_cell = classification.size(), last_cell = 0;
  for (unsigned int c = 0; c < classification.size(); ++c)
    if (classification[c])
      {
        first_cell = std::min(first_cell, c);
        last_cell  = c;
      }
  const unsigned int first = 2 * spaces.u().cell_dofs(first_cell)[0];
  const unsigned int last  = 2 * spaces.u().cell_dofs(last_cell).back() + 1;
  ok &= report("not in the pattern before",
               !in_pattern(system, first, last) && !in_pattern(system, last, first));

  system.add_term(std::make_unique<CouplingTerm>(first_cell, last_cell));
  ok &= report("the next setup builds a new pattern", system.setup(scene.particles));
  ok &= report("which holds both entries",
               in_pattern(system, first, last) && in_pattern(system, last, first));
  ok &= report("the setup after it keeps it", !system.setup(scene.particles));

  std::cout << (ok ? "term couplings checks passed" : "TERM COUPLINGS CHECKS FAILED") << std::endl;
  return ok ? 0 : 1;
}
