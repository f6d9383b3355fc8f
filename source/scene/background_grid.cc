#include <gelmpm/core/available_memory.h>
#include <gelmpm/core/input_error.h>
#include <gelmpm/core/parameters.h>
#include <gelmpm/core/round_off.h>
#include <gelmpm/scene/background_grid.h>

#include <deal.II/grid/grid_generator.h>

#include <cmath>
#include <sstream>
#include <unistd.h>

namespace GelMPM
{
  template <int dim>
  void
  BackgroundGrid<dim>::declare_parameters(dealii::ParameterHandler &prm)
  {
    using namespace dealii;
    prm.enter_subsection("Background grid");
    prm.declare_entry("Lower corner",
                      dim == 2 ? "0, 0" : "0, 0, 0",
                      Patterns::List(Patterns::Double(), dim, dim),
                      "Lower corner of the fixed background grid, one coordinate per direction.");
    prm.declare_entry("Upper corner",
                      dim == 2 ? "1, 1" : "1, 1, 1",
                      Patterns::List(Patterns::Double(), dim, dim),
                      "Upper corner of the background grid. The body must stay inside the grid for "
                      "the whole run (it swells): a face that reaches the edge of the grid stops "
                      "the run unless a roller or a fixed condition holds it there.");
    prm.declare_entry("Cells",
                      dim == 2 ? "10, 10" : "10, 10, 10",
                      Patterns::List(Patterns::Integer(1), dim, dim),
                      "Number of cells per direction of the displacement grid (cell size h_u). "
                      "With mu on the coarse grid (subdivision) the counts must be even.");
    prm.declare_entry("Coordinate system",
                      "Cartesian",
                      Patterns::Selection("Cartesian|axisymmetric"),
                      "Cartesian: x, y (, z); in 2D the gel is in plane strain. axisymmetric (2D "
                      "only): the grid is the meridian plane of a body of revolution, x the "
                      "radius R and y the axis z; the hoop stretch r/R enters F, every volume "
                      "and area is that of the revolved body (2 pi R), and u_r = 0 on the axis. "
                      "The grid's 'Lower corner' must then have x = 0: its left edge is the axis "
                      "(doc/axisymmetric.md).");
    prm.leave_subsection();
  }


  template <int dim>
  void
  BackgroundGrid<dim>::parse_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Background grid");
    const auto lo = get_double_list(prm, "Lower corner", "Background grid/Lower corner", dim);
    const auto hi = get_double_list(prm, "Upper corner", "Background grid/Upper corner", dim);
    const auto n  = get_double_list(prm, "Cells", "Background grid/Cells", dim);
    axisymmetric  = prm.get("Coordinate system") == "axisymmetric";
    prm.leave_subsection();
    require(!axisymmetric || dim == 2,
            "Background grid/Coordinate system",
            "is axisymmetric in a 3D scene: a body of revolution is modelled in its meridian "
            "plane",
            "set 'Dimension = 2' for an axisymmetric scene, or 'Coordinate system = Cartesian'");
    std::ostringstream lower_x;
    lower_x << lo[0];
    require(!axisymmetric || lo[0] == 0.,
            "Background grid/Lower corner",
            "has x = " + lower_x.str() +
              " in an axisymmetric scene, whose grid starts on the axis R = 0",
            "give 'Lower corner = 0, <z_min>' and keep the body at R >= 0");
    check_memory(n);
    for (unsigned int d = 0; d < dim; ++d)
      {
        lower[d]   = lo[d];
        upper[d]   = hi[d];
        n_cells[d] = static_cast<unsigned int>(n[d]);
        require(upper[d] > lower[d],
                "Background grid/Upper corner",
                "is not above 'Lower corner' in direction " + std::to_string(d),
                "give an upper corner larger than the lower corner in every coordinate");
      }
  }


  template <int dim>
  void
  BackgroundGrid<dim>::check_memory(const std::vector<double> &cells) const
  {
    // A lower bound: the cell of the triangulation, its points, its rows of the tangent. Above
    // the machine's memory the allocation fails late, with nothing that names the entry.
    const double bytes_per_cell = dim == 2 ? 1024. : 4096.;
    double       n              = 1.;
    for (const double c : cells)
      n *= c;
    const double available = available_memory();
    if (!(available > 0.) || n * bytes_per_cell <= available)
      return;
    std::ostringstream problem;
    problem.precision(3);
    problem << "asks for " << n << " cells, which need at least " << n * bytes_per_cell / 1e9
            << " GB of memory, more than the " << available / 1e9
            << " GB this machine has available";
    throw InputError("Background grid/Cells", problem.str(), "give fewer cells per direction");
  }


  template <int dim>
  double
  BackgroundGrid<dim>::cell_size(const unsigned int d) const
  {
    return (upper[d] - lower[d]) / n_cells[d];
  }


  template <int dim>
  bool
  BackgroundGrid<dim>::contains(const dealii::Point<dim> &p) const
  {
    for (unsigned int d = 0; d < dim; ++d)
      {
        const double tolerance = relative_position_tolerance * (upper[d] - lower[d]);
        if (p[d] < lower[d] - tolerance || p[d] > upper[d] + tolerance)
          return false;
      }
    return true;
  }


  template <int dim>
  void
  BackgroundGrid<dim>::create_triangulation(dealii::Triangulation<dim> &triangulation) const
  {
    std::vector<unsigned int> repetitions(n_cells.begin(), n_cells.end());
    dealii::GridGenerator::subdivided_hyper_rectangle(triangulation, repetitions, lower, upper);
  }


  template struct BackgroundGrid<2>;
  template struct BackgroundGrid<3>;
} // namespace GelMPM
