#include <gelmpm/core/input_error.h>
#include <gelmpm/particles/property_layout.h>
#include <gelmpm/simulator/observable_chemical_potential_oscillation.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace GelMPM
{
  template <int dim>
  void
  ChemicalPotentialOscillation<dim>::declare_parameters(dealii::ParameterHandler &prm)
  {
    prm.declare_entry("Chemical potential oscillation",
                      "false",
                      dealii::Patterns::Bool(),
                      "Adds the column mu_oscillation: along every row of volume points (points "
                      "with the same initial y, ordered by initial x), the sum of |second "
                      "differences| of mu; the mean over rows, divided by the range of mu over "
                      "all volume points. Spurious (inf-sup) pressure modes make it of order one; "
                      "a smooth field gives a small value that shrinks with the point spacing "
                      "(doc/flat_punch.md). 2D only.");
  }


  template <int dim>
  std::unique_ptr<ChemicalPotentialOscillation<dim>>
  ChemicalPotentialOscillation<dim>::parse(dealii::ParameterHandler &prm)
  {
    if (!prm.get_bool("Chemical potential oscillation"))
      return nullptr;
    // Its rows are the points of equal initial y, ordered by x: lines in 2D, but in 3D planes
    // whose points in x order jump between lines of different z.
    require(dim == 2,
            "Observables/Chemical potential oscillation",
            "is set in a 3D scene, but it is measured along rows of points of equal initial y, "
            "which are lines in 2D only",
            "set it to false in 3D");
    return std::make_unique<ChemicalPotentialOscillation>();
  }


  template <int dim>
  std::vector<std::string>
  ChemicalPotentialOscillation<dim>::columns() const
  {
    return {"mu_oscillation"};
  }


  template <int dim>
  void
  ChemicalPotentialOscillation<dim>::evaluate(const ObservedState<dim> &state,
                                              StatisticsFile           &statistics) const
  {
    statistics.set("mu_oscillation", oscillation(state.particles));
  }


  template <int dim>
  double
  ChemicalPotentialOscillation<dim>::oscillation(
    const dealii::Particles::ParticleHandler<dim> &particles) const
  {
    using Layout = PropertyLayout<dim>;
    // (row coordinate, position along the row, mu) of every volume point. Points are generated at
    // sub-cell centres of the background grid, so rows of equal initial y exist for any body.
    std::vector<std::array<double, 3>> local;
    for (const auto &particle : particles)
      {
        const auto props = particle.get_properties();
        if (kind_of(props) == PointKind::volume)
          local.push_back(
            {{props[Layout::position_0 + dim - 1], props[Layout::position_0], props[Layout::mu]}});
      }
    auto points = ObservedPieces::gathered(this->communicator, std::move(local));
    if (points.size() < 3)
      return 0.;
    std::sort(points.begin(), points.end());
    double mu_min = points[0][2], mu_max = points[0][2];
    for (const auto &p : points)
      mu_min = std::min(mu_min, p[2]), mu_max = std::max(mu_max, p[2]);
    const double extent = std::abs(points.back()[0] - points.front()[0]) + 1.;

    double       sum    = 0.;
    unsigned int n_rows = 0;
    for (std::size_t first = 0; first < points.size();)
      {
        std::size_t end = first + 1;
        while (end < points.size() && points[end][0] - points[first][0] <= 1e-9 * extent)
          ++end;
        for (std::size_t i = first + 1; i + 1 < end; ++i)
          sum += std::abs(points[i + 1][2] - 2. * points[i][2] + points[i - 1][2]);
        ++n_rows;
        first = end;
      }
    return (mu_max > mu_min) ? sum / n_rows / (mu_max - mu_min) : 0.;
  }


  template class ChemicalPotentialOscillation<2>;
  template class ChemicalPotentialOscillation<3>;
} // namespace GelMPM
