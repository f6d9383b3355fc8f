#include <gelmpm/particles/property_layout.h>
#include <gelmpm/simulator/rigid_motion.h>

#include <deal.II/base/mpi.templates.h>
#include <deal.II/base/tensor.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace GelMPM
{
  namespace
  {
    /** Eigenvalues and eigenvectors (columns of @p V) of the symmetric @p A, by Jacobi rotations.
     */
    template <unsigned int n>
    void
    symmetric_eigen(std::array<std::array<double, n>, n> &A,
                    std::array<std::array<double, n>, n> &V)
    {
      for (unsigned int i = 0; i < n; ++i)
        for (unsigned int j = 0; j < n; ++j)
          V[i][j] = i == j ? 1. : 0.;
      for (unsigned int sweep = 0; sweep < 100; ++sweep)
        {
          double off = 0., scale = 0.;
          for (unsigned int i = 0; i < n; ++i)
            for (unsigned int j = 0; j < n; ++j)
              (i == j ? scale : off) += A[i][j] * A[i][j];
          if (off <= 1e-30 * scale)
            return;
          for (unsigned int p = 0; p < n; ++p)
            for (unsigned int q = p + 1; q < n; ++q)
              {
                if (A[p][q] == 0.)
                  continue;
                const double theta = (A[q][q] - A[p][p]) / (2. * A[p][q]);
                const double t =
                  (theta >= 0. ? 1. : -1.) / (std::abs(theta) + std::sqrt(theta * theta + 1.));
                const double c = 1. / std::sqrt(t * t + 1.), s = t * c;
                for (unsigned int k = 0; k < n; ++k)
                  {
                    const double a_kp = A[k][p], a_kq = A[k][q];
                    A[k][p] = c * a_kp - s * a_kq;
                    A[k][q] = s * a_kp + c * a_kq;
                  }
                for (unsigned int k = 0; k < n; ++k)
                  {
                    const double a_pk = A[p][k], a_qk = A[q][k];
                    A[p][k] = c * a_pk - s * a_qk;
                    A[q][k] = s * a_pk + c * a_qk;
                  }
                for (unsigned int k = 0; k < n; ++k)
                  {
                    const double v_kp = V[k][p], v_kq = V[k][q];
                    V[k][p] = c * v_kp - s * v_kq;
                    V[k][q] = s * v_kp + c * v_kq;
                  }
              }
        }
    }
  } // namespace


  template <int dim>
  std::vector<std::string>
  unheld_rigid_motions(const dealii::Particles::ParticleHandler<dim> &particles,
                       const BoundaryConditions<dim>                 &boundary_conditions,
                       const ContactSettings                         &contact,
                       const dealii::Point<dim>                      &grid_lower,
                       const dealii::Point<dim>                      &grid_upper,
                       const MPI_Comm                                 communicator,
                       const bool                                     axisymmetric)
  {
    using Layout             = PropertyLayout<dim>;
    using Condition          = typename BoundaryPiece<dim>::DisplacementCondition;
    constexpr unsigned int n = dim == 2 ? 3 : 6; // translations, then rotations

    // The body's centre and extent, from its volume points.
    std::vector<double> moments(1 + dim, 0.);
    std::vector<double> lowest(dim, 1e300), highest(dim, -1e300);
    for (const auto &p : particles)
      {
        const auto props = p.get_properties();
        if (kind_of(props) != PointKind::volume)
          continue;
        const double volume = props[Layout::measure_0];
        moments[0] += volume;
        for (unsigned int d = 0; d < dim; ++d)
          {
            const double x = props[Layout::position_0 + d];
            moments[1 + d] += volume * x;
            lowest[d]  = std::min(lowest[d], x);
            highest[d] = std::max(highest[d], x);
          }
      }
    dealii::Utilities::MPI::sum(moments, communicator, moments);
    dealii::Utilities::MPI::min(lowest, communicator, lowest);
    dealii::Utilities::MPI::max(highest, communicator, highest);
    dealii::Point<dim> centre;
    double             size = 0.;
    for (unsigned int d = 0; d < dim; ++d)
      {
        centre[d] = moments[0] > 0. ? moments[1 + d] / moments[0] : 0.;
        size      = std::max(size, highest[d] - lowest[d]);
      }
    if (!(size > 0.))
      size = 1.;

    // The rigid motions at x, rotations scaled by the body's size so that all have about unit
    // size on it.
    const auto modes = [&](const dealii::Point<dim> &x) {
      std::array<dealii::Tensor<1, dim>, n> r;
      for (unsigned int d = 0; d < dim; ++d)
        r[d][d] = 1.;
      const dealii::Tensor<1, dim> y = (x - centre) / size;
      if constexpr (dim == 2)
        {
          r[2][0] = -y[1];
          r[2][1] = y[0];
        }
      else
        for (unsigned int a = 0; a < 3; ++a)
          {
            // e_a x y
            const unsigned int b = (a + 1) % 3, c = (a + 2) % 3;
            r[3 + a][b] = -y[c];
            r[3 + a][c] = y[b];
          }
      return r;
    };
    // M = sum over constraints of (P r_k) . (P r_l) A, with P the projector onto the constrained
    // directions at a point.
    std::vector<double> M(n * n, 0.);
    const auto          add = [&](const dealii::Point<dim>     &x,
                         const dealii::Tensor<2, dim> &projector,
                         const double                  weight) {
      const auto r = modes(x);
      for (unsigned int k = 0; k < n; ++k)
        for (unsigned int l = 0; l < n; ++l)
          M[k * n + l] += weight * ((projector * r[k]) * (projector * r[l]));
    };
    const auto planes     = contact.enabled() ? contact.planes(grid_lower, grid_upper)
                                              : std::vector<ContactSettings::Plane>();
    double     total_area = 0.;
    for (const auto &p : particles)
      {
        const auto props = p.get_properties();
        const int  piece = piece_of(props);
        if (piece < 0)
          continue;
        dealii::Point<dim>     x;
        dealii::Tensor<1, dim> normal;
        for (unsigned int d = 0; d < dim; ++d)
          {
            x[d]      = props[Layout::position_0 + d];
            normal[d] = props[Layout::normal_area_0 + d];
          }
        const double area = normal.norm();
        if (!(area > 0.))
          continue;
        normal /= area;
        total_area += area;
        const auto             condition = boundary_conditions.piece(piece).displacement_condition;
        dealii::Tensor<2, dim> identity;
        for (unsigned int d = 0; d < dim; ++d)
          identity[d][d] = 1.;
        const dealii::Tensor<2, dim> nn = dealii::outer_product(normal, normal);
        if (condition == Condition::fixed)
          add(x, identity, area);
        else if (condition == Condition::normal)
          add(x, nn, area);
        else if (condition == Condition::tangential)
          add(x, identity - nn, area);
        else
          // A contact plane acts on the free pieces as a roller where they touch it: taken
          // over the body's extent, projected onto the plane.
          for (const auto &plane : planes)
            {
              dealii::Point<dim> on_plane = x;
              on_plane[plane.axis]        = plane.value;
              dealii::Tensor<2, dim> axis;
              axis[plane.axis][plane.axis] = 1.;
              add(on_plane, axis, area);
            }
      }
    dealii::Utilities::MPI::sum(M, communicator, M);
    total_area = dealii::Utilities::MPI::sum(total_area, communicator);
    if (axisymmetric)
      {
        // u_r = 0 along the axis, held at its two ends over the body's height.
        const double           weight = std::max(total_area, moments[0] / size);
        dealii::Tensor<2, dim> radial;
        radial[0][0] = 1.;
        for (const double z : {lowest[1], highest[1]})
          {
            dealii::Point<dim> on_axis;
            on_axis[1] = z;
            add(on_axis, radial, weight);
          }
        total_area = std::max(total_area, weight);
      }

    std::array<std::array<double, n>, n> A, V;
    for (unsigned int k = 0; k < n; ++k)
      for (unsigned int l = 0; l < n; ++l)
        A[k][l] = M[k * n + l];
    symmetric_eigen<n>(A, V);
    // A held motion moves a constrained part of the boundary (of area at least a fraction of
    // the whole) by about its size: its eigenvalue is a sizeable fraction of the area. An
    // unheld one moves none: zero but for round-off.
    const double                       threshold = 1e-10 * std::max(total_area, 1e-300);
    std::vector<std::array<double, n>> free;
    for (unsigned int k = 0; k < n; ++k)
      if (A[k][k] <= threshold)
        {
          std::array<double, n> v;
          for (unsigned int i = 0; i < n; ++i)
            v[i] = V[i][k];
          free.push_back(v);
        }
    // Name each elementary motion that lies in the unheld space; what is left are combinations.
    const char              *axes = "xyz";
    std::vector<std::string> names;
    unsigned int             named = 0;
    for (unsigned int k = 0; k < n; ++k)
      {
        double projection = 0.;
        for (const auto &v : free)
          projection += v[k] * v[k];
        if (projection > 1. - 1e-6)
          {
            ++named;
            if (k < dim)
              names.push_back(std::string("translation along ") + axes[k]);
            else
              names.push_back(std::string("rotation about ") + (dim == 2 ? 'z' : axes[k - dim]));
          }
      }
    if (free.size() > named)
      names.push_back(std::to_string(free.size() - named) +
                      " combination(s) of translations and rotations");
    return names;
  }


  template std::vector<std::string>
  unheld_rigid_motions<2>(const dealii::Particles::ParticleHandler<2> &,
                          const BoundaryConditions<2> &,
                          const ContactSettings &,
                          const dealii::Point<2> &,
                          const dealii::Point<2> &,
                          const MPI_Comm,
                          const bool);
  template std::vector<std::string>
  unheld_rigid_motions<3>(const dealii::Particles::ParticleHandler<3> &,
                          const BoundaryConditions<3> &,
                          const ContactSettings &,
                          const dealii::Point<3> &,
                          const dealii::Point<3> &,
                          const MPI_Comm,
                          const bool);
} // namespace GelMPM
