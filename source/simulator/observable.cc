#include <gelmpm/core/input_error.h>
#include <gelmpm/particles/property_layout.h>
#include <gelmpm/simulator/observable.h>

#include <algorithm>
#include <cmath>

namespace GelMPM
{
  namespace ObservedPieces
  {
    int
    index(const std::string &name, const std::vector<std::string> &pieces, const std::string &entry)
    {
      const auto it = std::find(pieces.begin(), pieces.end(), name);
      require(it != pieces.end(),
              entry,
              "names the piece '" + name + "' that is not in 'Boundary conditions/Pieces'",
              "use one of the declared pieces");
      return it - pieces.begin();
    }


    std::array<int, 2>
    pair(const std::vector<std::string> &names,
         const std::vector<std::string> &pieces,
         const std::string              &entry,
         const std::string              &example)
    {
      std::array<int, 2> pair = {{-1, -1}};
      if (names.empty())
        return pair;
      require(names.size() == 2, entry, "must name exactly two pieces", "write '" + example + "'");
      for (unsigned int k = 0; k < 2; ++k)
        pair[k] = index(names[k], pieces, entry);
      return pair;
    }


    template <int dim>
    std::array<dealii::Point<dim>, 4>
    means(const dealii::Particles::ParticleHandler<dim> &particles,
          const std::array<int, 2>                      &pair,
          const MPI_Comm                                 communicator)
    {
      using Layout = PropertyLayout<dim>;
      std::array<dealii::Point<dim>, 4> sum;
      std::array<unsigned int, 2>       count = {{0, 0}};
      for (const auto &particle : particles)
        {
          const auto props = particle.get_properties();
          const int  piece = piece_of(props);
          for (unsigned int k = 0; k < 2; ++k)
            if (piece == pair[k])
              {
                for (unsigned int d = 0; d < dim; ++d)
                  {
                    sum[k][d] += position_of(particle.get_location(), props)[d];
                    sum[2 + k][d] += props[Layout::position_0 + d];
                  }
                ++count[k];
              }
        }
      std::vector<double> flat;
      for (unsigned int k = 0; k < 4; ++k)
        for (unsigned int d = 0; d < dim; ++d)
          flat.push_back(sum[k][d]);
      flat.push_back(count[0]);
      flat.push_back(count[1]);
      Collective::sum_in_place(communicator, flat);
      for (unsigned int k = 0; k < 4; ++k)
        for (unsigned int d = 0; d < dim; ++d)
          sum[k][d] = flat[k * dim + d] / flat[4 * dim + k % 2];
      return sum;
    }


    template <int dim>
    SurfaceSample<dim>
    surface_sample(const dealii::Particles::ParticleHandler<dim> &particles,
                   const std::vector<unsigned int>               &pieces,
                   const MPI_Comm                                 communicator)
    {
      using Layout = PropertyLayout<dim>;
      // Per point: the piece's place in @p pieces, x, N_n A_n, and in 2D X_0, N_0 A_0 and mu.
      const unsigned int  n_values = dim == 2 ? 1 + 4 * dim + 1 : 1 + 2 * dim;
      std::vector<double> local;
      for (const auto &particle : particles)
        {
          const auto props = particle.get_properties();
          const int  piece = piece_of(props);
          const auto it    = std::find(pieces.begin(), pieces.end(), piece);
          if (piece < 0 || it == pieces.end())
            continue;
          local.push_back(it - pieces.begin());
          const auto x = position_of(particle.get_location(), props);
          for (unsigned int d = 0; d < dim; ++d)
            local.push_back(x[d]);
          for (unsigned int d = 0; d < dim; ++d)
            local.push_back(props[Layout::normal_area_n + d]);
          if (dim == 2)
            {
              for (unsigned int d = 0; d < dim; ++d)
                local.push_back(props[Layout::position_0 + d]);
              for (unsigned int d = 0; d < dim; ++d)
                local.push_back(props[Layout::normal_area_0 + d]);
              local.push_back(props[Layout::mu]);
            }
        }
      const std::vector<double> all = gathered(communicator, std::move(local));

      SurfaceSample<dim> sample;
      sample.positions.resize(pieces.size());
      sample.normal_areas.resize(pieces.size());
      sample.points.resize(pieces.size());
      for (std::size_t first = 0; first < all.size(); first += n_values)
        {
          const unsigned int     k = std::lround(all[first]);
          dealii::Point<dim>     x;
          dealii::Tensor<1, dim> normal_area;
          for (unsigned int d = 0; d < dim; ++d)
            {
              x[d]           = all[first + 1 + d];
              normal_area[d] = all[first + 1 + dim + d];
            }
          sample.positions[k].push_back(x);
          sample.normal_areas[k].push_back(normal_area);
          if (dim == 2)
            {
              SurfaceGeometry::SurfacePoint point;
              for (unsigned int d = 0; d < 2; ++d)
                {
                  point.x[d]        = x[d];
                  point.X_0[d]      = all[first + 1 + 2 * dim + d];
                  point.normal_0[d] = all[first + 1 + 3 * dim + d];
                }
              point.mu = all[first + 1 + 4 * dim];
              sample.points[k].push_back(point);
            }
        }
      return sample;
    }


    template SurfaceSample<2>
    surface_sample(const dealii::Particles::ParticleHandler<2> &,
                   const std::vector<unsigned int> &,
                   const MPI_Comm);
    template SurfaceSample<3>
    surface_sample(const dealii::Particles::ParticleHandler<3> &,
                   const std::vector<unsigned int> &,
                   const MPI_Comm);
    template std::array<dealii::Point<2>, 4>
    means(const dealii::Particles::ParticleHandler<2> &,
          const std::array<int, 2> &,
          const MPI_Comm);
    template std::array<dealii::Point<3>, 4>
    means(const dealii::Particles::ParticleHandler<3> &,
          const std::array<int, 2> &,
          const MPI_Comm);
  } // namespace ObservedPieces
} // namespace GelMPM
