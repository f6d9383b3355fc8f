// A small 2D scene with every kind of boundary term, built from a parameter string, shared by the
// assembly tests: Q2-Q2SD on a 24 x 24 grid of [-1, 2]^2, a cut box [0, 1.3] x [0, 1.1], pieces
// with fixed, normal, tangential and free displacement, prescribed mu and flux, time-dependent
// values.
#include <gelmpm/assembly/discretisation.h>
#include <gelmpm/assembly/mixed_system.h>
#include <gelmpm/assembly/nitsche_settings.h>
#include <gelmpm/material/flory_rehner_gel.h>
#include <gelmpm/particles/material_point_generator.h>
#include <gelmpm/scene/background_grid.h>
#include <gelmpm/scene/boundary_conditions.h>
#include <gelmpm/scene/geometry.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/tria.h>
#include <deal.II/particles/particle_handler.h>

#include <memory>
#include <string>

struct SceneFixture
{
  static constexpr int dim = 2;

  GelMPM::FloryRehnerGel<dim>                  material;
  GelMPM::BackgroundGrid<dim>                  grid;
  GelMPM::Geometry<dim>                        geometry;
  GelMPM::BoundaryConditions<dim>              boundary_conditions;
  GelMPM::MaterialPointGenerator<dim>          generator;
  GelMPM::DiscretisationSettings               discretisation;
  GelMPM::NitscheSettings                      nitsche;
  dealii::Triangulation<dim>                   triangulation;
  dealii::MappingQ1<dim>                       mapping;
  dealii::Particles::ParticleHandler<dim>      particles;
  std::unique_ptr<GelMPM::DiscreteSpaces<dim>> spaces;
  std::unique_ptr<GelMPM::MixedSystem<dim>>    system;

  /** @p overrides: parameter text read after the scene's, to change some of its entries. */
  explicit SceneFixture(const std::string &variant = "symmetric", const std::string &overrides = "")
  {
    const std::vector<std::string> pieces = {"bottom", "left", "right", "top"};
    dealii::ParameterHandler       prm;
    GelMPM::FloryRehnerGel<dim>::declare_parameters(prm);
    GelMPM::BackgroundGrid<dim>::declare_parameters(prm);
    GelMPM::Geometry<dim>::declare_parameters(prm);
    GelMPM::BoundaryConditions<dim>::declare_parameters(prm, pieces);
    GelMPM::MaterialPointGenerator<dim>::declare_parameters(prm);
    GelMPM::DiscretisationSettings::declare_parameters(prm);
    GelMPM::NitscheSettings::declare_parameters(prm);
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
    material.parse_parameters(prm);
    grid.parse_parameters(prm);
    geometry.parse_parameters(prm);
    boundary_conditions.parse_parameters(prm, pieces);
    generator.parse_parameters(prm);
    discretisation.parse_parameters(prm);
    nitsche.parse_parameters(prm);

    grid.create_triangulation(triangulation);
    particles.initialize(triangulation, mapping, GelMPM::PropertyLayout<dim>::n_properties);
    generator.generate(geometry,
                       grid,
                       triangulation,
                       boundary_conditions,
                       material.lambda_0(),
                       material.mu_0(),
                       particles);
    spaces = std::make_unique<GelMPM::DiscreteSpaces<dim>>(grid, discretisation);
    system =
      std::make_unique<GelMPM::MixedSystem<dim>>(material, boundary_conditions, nitsche, *spaces);
    system->setup(particles);
    system->set_boundary_values(0.5);
  }
};
