#include <gelmpm/core/input_error.h>
#include <gelmpm/particles/property_layout.h>
#include <gelmpm/simulator/observable.h>

#include <algorithm>

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
