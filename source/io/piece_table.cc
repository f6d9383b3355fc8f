#include <gelmpm/io/piece_table.h>
#include <gelmpm/particles/property_layout.h>

#include <deal.II/base/tensor.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>
#include <tuple>

namespace GelMPM
{
  namespace
  {
    /**
     * What a point's initial @p measure ("area" or "volume") is in a table: in 2D per unit
     * thickness in plane strain, the revolved one (2 pi R times the meridian's) in an
     * axisymmetric scene.
     */
    std::string
    area_name(const int dim, const bool axisymmetric, const std::string &measure)
    {
      if (dim == 3)
        return measure;
      return axisymmetric ? "revolved " + measure + " (2 pi R times the meridian's)"
                          : measure + " per unit thickness";
    }
  } // namespace


  template <int dim>
  std::string
  piece_table(const dealii::Particles::ParticleHandler<dim> &particles,
              const std::vector<std::string>                &piece_names,
              const bool                                     axisymmetric,
              const MPI_Comm                                 communicator)
  {
    using Layout = PropertyLayout<dim>;
    // Per piece (the last row: surface points of no piece): count, area, then the smallest and
    // the largest of each normal component.
    const unsigned int  n_rows = piece_names.size() + 1;
    std::vector<double> count(n_rows, 0.), area(n_rows, 0.);
    std::vector<double> lowest(n_rows * dim, std::numeric_limits<double>::infinity());
    std::vector<double> highest(n_rows * dim, -std::numeric_limits<double>::infinity());
    for (const auto &p : particles)
      {
        const auto props = p.get_properties();
        if (kind_of(props) == PointKind::volume)
          continue;
        const int          piece = piece_of(props);
        const unsigned int row   = piece >= 0 ? piece : n_rows - 1;
        count[row] += 1.;
        area[row] += props[Layout::measure_0];
        dealii::Tensor<1, dim> normal;
        for (unsigned int d = 0; d < dim; ++d)
          normal[d] = props[Layout::normal_area_0 + d];
        normal /= normal.norm();
        // Round-off of a normal's zero component would print as -0.000.
        for (unsigned int d = 0; d < dim; ++d)
          if (std::abs(normal[d]) < 1e-12)
            normal[d] = 0.;
        for (unsigned int d = 0; d < dim; ++d)
          {
            lowest[row * dim + d]  = std::min(lowest[row * dim + d], normal[d]);
            highest[row * dim + d] = std::max(highest[row * dim + d], normal[d]);
          }
      }
    dealii::Utilities::MPI::sum(count, communicator, count);
    dealii::Utilities::MPI::sum(area, communicator, area);
    dealii::Utilities::MPI::min(lowest, communicator, lowest);
    dealii::Utilities::MPI::max(highest, communicator, highest);

    std::size_t width = 6;
    for (const auto &name : piece_names)
      width = std::max(width, name.size());
    std::ostringstream out;
    out << "  boundary pieces (initial " << area_name(dim, axisymmetric, "area")
        << "; range of each component of the initial normal):\n";
    for (unsigned int row = 0; row < n_rows; ++row)
      {
        if (row == n_rows - 1 && count[row] == 0.)
          break;
        const std::string name = row < n_rows - 1 ? piece_names[row] : std::string("(none)");
        out << "    " << std::left << std::setw(width) << name << std::right << std::setw(8)
            << static_cast<unsigned long>(count[row]) << " points  area " << std::setw(10)
            << std::setprecision(5) << area[row];
        if (count[row] > 0.)
          for (unsigned int d = 0; d < dim; ++d)
            out << "  n"
                << "xyz"[d] << " " << std::fixed << std::setprecision(3) << std::setw(6)
                << lowest[row * dim + d] << " .. " << std::setw(6) << highest[row * dim + d]
                << std::defaultfloat;
        out << '\n';
      }
    return out.str();
  }


  template <int dim>
  std::string
  region_table(const dealii::Particles::ParticleHandler<dim> &particles,
               const MaterialRegions<dim>                    &regions,
               const bool                                     axisymmetric,
               const MPI_Comm                                 communicator)
  {
    if (regions.size() < 2)
      return "";
    std::vector<double> count(regions.size(), 0.), volume(regions.size(), 0.);
    for (const auto &p : particles)
      {
        const auto props = p.get_properties();
        if (kind_of(props) != PointKind::volume)
          continue;
        const unsigned int region = region_of_point<dim>(props);
        count[region] += 1.;
        volume[region] += props[PropertyLayout<dim>::measure_0];
      }
    dealii::Utilities::MPI::sum(count, communicator, count);
    dealii::Utilities::MPI::sum(volume, communicator, volume);

    std::size_t width = 8;
    for (unsigned int k = 0; k < regions.size(); ++k)
      width = std::max(width, regions.name(k).size());
    std::ostringstream out;
    out << "  material regions (volume points, initial " << area_name(dim, axisymmetric, "volume")
        << "; constants that differ from the section 'Material', its value in parentheses):\n";
    const auto &base = regions[0];
    for (unsigned int k = 0; k < regions.size(); ++k)
      {
        const auto &gel = regions[k];
        out << "    " << std::left << std::setw(width) << regions.name(k) << std::right
            << std::setw(8) << static_cast<unsigned long>(count[k]) << " points  volume "
            << std::setw(10) << std::setprecision(5) << volume[k];
        std::string separator = "  ";
        for (const auto &[name, value, base_value] :
             {std::make_tuple("G", gel.shear_modulus(), base.shear_modulus()),
              std::make_tuple("N nu", gel.N_nu(), base.N_nu()),
              std::make_tuple("chi", gel.chi(), base.chi()),
              std::make_tuple("D", gel.diffusivity(), base.diffusivity()),
              std::make_tuple("lambda_0", gel.lambda_0(), base.lambda_0())})
          if (value != base_value)
            {
              out << separator << name << " " << std::setprecision(6) << value << " (" << base_value
                  << ")";
              separator = ", ";
            }
        out << '\n';
      }
    return out.str();
  }


  template std::string
  piece_table<2>(const dealii::Particles::ParticleHandler<2> &,
                 const std::vector<std::string> &,
                 const bool,
                 const MPI_Comm);
  template std::string
  piece_table<3>(const dealii::Particles::ParticleHandler<3> &,
                 const std::vector<std::string> &,
                 const bool,
                 const MPI_Comm);
  template std::string
  region_table<2>(const dealii::Particles::ParticleHandler<2> &,
                  const MaterialRegions<2> &,
                  const bool,
                  const MPI_Comm);
  template std::string
  region_table<3>(const dealii::Particles::ParticleHandler<3> &,
                  const MaterialRegions<3> &,
                  const bool,
                  const MPI_Comm);
} // namespace GelMPM
