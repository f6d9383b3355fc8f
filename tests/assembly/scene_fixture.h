// A small 2D scene with every kind of boundary term, built from a parameter string, shared by the
// assembly tests: Q2-Q2SD on a 24 x 24 grid of [-1, 2]^2, a cut box [0, 1.3] x [0, 1.1], pieces
// with fixed, normal, tangential and free displacement, prescribed mu and flux, time-dependent
// values. It is a GelMPM::Scene, built as the simulator builds one; only the text is the test's.
// Also a 3D cube (CubeFixture) whose boundary conditions are the test's.
#ifndef gelmpm_tests_scene_fixture_h
#define gelmpm_tests_scene_fixture_h

#include <gelmpm/simulator/scene.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <cctype>
#include <iostream>
#include <string>
#include <vector>

namespace scene_fixture
{
  const std::vector<std::string> pieces = {"bottom", "left", "right", "top"};

  /** The fixture's parameters: the scene text, Nitsche's @p variant, then @p overrides. */
  struct Parameters
  {
    dealii::ParameterHandler prm;

    Parameters(const std::string &variant, const std::string &overrides)
    {
      GelMPM::Scene<2>::declare_parameters(prm, pieces);
      prm.parse_input_from_string(R"(
      subsection Background grid
        set Lower corner = -1, -1
        set Upper corner = 2, 2
        set Cells = 24, 24
      end
      subsection Geometry
        set Boxes = 0, 0 : 1.3, 1.1
      end
      subsection Material points
        set Points per cell = 3
      end
      subsection Nitsche
        set Variant = )" + variant +
                                  R"(
      end
      subsection Boundary conditions
        subsection bottom
          set Selector = ny < -0.5
          set Displacement = fixed
          subsection Displacement value
            set Function expression = 0.01*x; -0.02*t
          end
          subsection Flux
            set Function expression = 0.1
          end
        end
        subsection left
          set Selector = nx < -0.5
          set Displacement = normal
          set Chemical potential = prescribed
          subsection Displacement value
            set Function expression = 0.005; 0
          end
          subsection Chemical potential value
            set Function expression = -0.05
          end
        end
        subsection right
          set Selector = nx > 0.5
          set Displacement = tangential
          subsection Displacement value
            set Function expression = 0; 0.01*y
          end
        end
        subsection top
          set Selector = ny > 0.5
          set Chemical potential = prescribed
          subsection Traction
            set Function expression = 0.01; -0.02
          end
          subsection Chemical potential value
            set Function expression = -0.1 + 0.05*x
          end
        end
      end)" + overrides);
    }
  };


  /** A cube's parameters: the text of cube(), with @p boundary_conditions (the subsections of
   * @p pieces) in "Boundary conditions". */
  struct CubeParameters
  {
    dealii::ParameterHandler prm;

    CubeParameters(const std::vector<std::string> &pieces, const std::string &boundary_conditions)
    {
      GelMPM::Scene<3>::declare_parameters(prm, pieces);
      prm.parse_input_from_string(R"(
      subsection Background grid
        set Lower corner = -0.5, -0.5, -0.5
        set Upper corner = 1.5, 1.5, 1.5
        set Cells = 16, 16, 16
      end
      subsection Geometry
        set Boxes = 0, 0, 0 : 1, 1, 1
      end
      subsection Material points
        set Points per cell = 3
      end
      subsection Boundary conditions
      )" + boundary_conditions + R"(
      end)");
    }
  };
} // namespace scene_fixture

/**
 * The scene with its points, spaces and system set up at its initial state, boundary values at
 * t = 0.5.
 */
struct SceneFixture : private scene_fixture::Parameters, public GelMPM::Scene<2>
{
  static constexpr int dim = 2;

  /** @p overrides: parameter text read after the scene's, to change some of its entries. */
  explicit SceneFixture(const std::string &variant = "symmetric", const std::string &overrides = "")
    : scene_fixture::Parameters(variant, overrides)
    , GelMPM::Scene<2>(prm, scene_fixture::pieces)
  {
    create_material_points();
    create_system();
    system->setup(particles);
    system->set_boundary_values(0.5, 0.);
  }
};


/**
 * A cube [0, 1]^3 on a 16^3 grid of [-0.5, 1.5]^3 (Q2-Q2SD, 27 points per cell) with the pieces
 * @p pieces and their subsections @p boundary_conditions, set up as SceneFixture is.
 */
struct CubeFixture : private scene_fixture::CubeParameters, public GelMPM::Scene<3>
{
  CubeFixture(const std::vector<std::string> &pieces, const std::string &boundary_conditions)
    : scene_fixture::CubeParameters(pieces, boundary_conditions)
    , GelMPM::Scene<3>(prm, pieces)
  {
    create_material_points();
    create_system();
    system->setup(particles);
    system->set_boundary_values(0.5, 0.);
  }
};


/** The cube with rollers on its three faces at 0 and mu = -0.1 prescribed on the other three. */
struct RollerCube : public CubeFixture
{
  RollerCube()
    : CubeFixture({"symmetry", "outer"}, R"(
        subsection symmetry
          set Selector = nx < -0.5 || ny < -0.5 || nz < -0.5
          set Displacement = normal
        end
        subsection outer
          set Selector = nx > 0.5 || ny > 0.5 || nz > 0.5
          set Chemical potential = prescribed
          subsection Chemical potential value
            set Function expression = -0.1
          end
        end
      )")
  {}
};


/**
 * A test's main(): @p compare(name, system, mu_0) on the 2D scene (symmetric variant) and on the
 * RollerCube, then "<what> checks passed" or "... FAILED"; the exit status says the same.
 */
template <typename Compare>
int
compare_2d_and_3d(int argc, char **argv, const std::string &what, const Compare &compare)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bool                                     ok = true;
  {
    SceneFixture scene("symmetric");
    ok &= compare("2D", *scene.system, scene.material.mu_0());
  }
  {
    RollerCube cube;
    ok &= compare("3D", *cube.system, cube.material.mu_0());
  }
  std::string upper = what;
  for (char &c : upper)
    c = std::toupper(c);
  std::cout << (ok ? what + " checks passed" : upper + " CHECKS FAILED") << std::endl;
  return ok ? 0 : 1;
}

#endif
