// Two blocks of one body, shared by the self-contact assembly tests: [0, 1] x [0, 0.75] and
// [0, 1] x [b, b + 0.75] (Table 1 gel), Q2-Q2SD on 12 x 18 cells of [-0.25, 1.25] x [-0.25, 2]
// (axisymmetric: 10 x 18 of [0, 1.25] x [-0.25, 2], the left side the axis), the facing sides the
// pieces lower_top and upper_bottom that touch; optionally refined in boxes (then without the
// extension). Built as the simulator builds a scene; the self-contact's entries are the test's.
#ifndef gelmpm_tests_two_blocks_h
#define gelmpm_tests_two_blocks_h

#include <gelmpm/simulator/scene.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/lac/vector.h>

#include <memory>
#include <random>
#include <string>
#include <vector>

namespace two_blocks
{
  const std::vector<std::string> pieces = {"lower_top", "upper_bottom", "rest"};

  /**
   * A state of @p scene's unknowns: @p noise times uniform numbers in [-1, 1] for the
   * displacement increments, mu_0 plus 10 times that for mu (the same numbers on every run).
   */
  template <int dim>
  dealii::Vector<double>
  noisy_state(const GelMPM::Scene<dim> &scene, const double noise)
  {
    const auto                      &spaces = scene.system->spaces();
    dealii::Vector<double>           state(spaces.n_dofs());
    std::mt19937                     rng(7);
    std::uniform_real_distribution<> u(-1., 1.);
    for (unsigned int i = 0; i < spaces.n_dofs(); ++i)
      state(i) =
        i < spaces.n_u_dofs() ? noise * u(rng) : scene.material.mu_0() + 10. * noise * u(rng);
    return state;
  }

  /** The scene, set up at its first step (the boundary values at t = 0.5 of a step from 0). */
  struct TwoBlocks
  {
    dealii::ParameterHandler          prm;
    std::unique_ptr<GelMPM::Scene<2>> scene;

    /**
     * @p bottom: the upper block's lower side; @p self_contact: the entries of 'Contact/Self
     * contact' besides its pieces; @p boxes: 'Background grid/Refinement boxes'; @p sections:
     * further sections of the parameter file.
     */
    TwoBlocks(const double       bottom,
              const bool         axisymmetric,
              const std::string &boxes,
              const std::string &self_contact,
              const std::string &sections = "")
    {
      const std::string split = std::to_string(0.5 * (0.75 + bottom));
      GelMPM::Scene<2>::declare_parameters(prm, pieces);
      prm.parse_input_from_string(
        std::string("subsection Background grid\n") +
        "set Coordinate system = " + (axisymmetric ? "axisymmetric" : "Cartesian") + "\n" +
        "set Lower corner = " + (axisymmetric ? "0" : "-0.25") + ", -0.25\n" +
        "set Upper corner = 1.25, 2\n" + "set Cells = " + (axisymmetric ? "10" : "12") + ", 18\n" +
        "set Refinement boxes = " + boxes + "\nend\n" +
        "subsection Discretisation\nset Extended B-splines = " +
        (boxes.empty() ? "true" : "false") + "\nend\n" + "subsection Geometry\n" +
        "set Boxes = 0, 0 : 1, 0.75; 0, " + std::to_string(bottom) + " : 1, " +
        std::to_string(bottom + 0.75) + "\nend\n" +
        "subsection Material points\nset Points per cell = 3\nend\n" +
        "subsection Boundary conditions\n" +
        // The facing sides (flat: no corner touches); the rest not the axis of an axisymmetric
        // scene, which has no area.
        "subsection lower_top\nset Selector = ny > 0.5 && y < " + split + "\nend\n" +
        "subsection upper_bottom\nset Selector = ny < -0.5 && y > " + split + "\nend\n" +
        "subsection rest\nset Selector = x > 1e-6\nend\nend\n" +
        "subsection Contact\nsubsection Self contact\nset Pieces = lower_top, upper_bottom\n" +
        self_contact + "\nend\nend\n" + sections);
      scene = std::make_unique<GelMPM::Scene<2>>(prm, pieces);
      scene->create_material_points();
      scene->create_system();
      scene->system->setup(scene->particles);
      scene->system->set_boundary_values(0.5, 0.);
    }
  };
} // namespace two_blocks

#endif
