// The update of the material points after a converged step (eq. (34)), MixedSystem's part that
// writes the particles.
#include <gelmpm/assembly/mixed_system.h>
#include <gelmpm/core/collective.h>
#include <gelmpm/core/format_point.h>
#include <gelmpm/core/non_physical_state.h>

#include <deal.II/base/parallel.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <limits>
#include <string>

namespace GelMPM
{
  using dealii::Point;
  using dealii::Tensor;


  template <int dim>
  void
  MixedSystem<dim>::update_particles(const dealii::Vector<double> &solution)
  {
    using Layout = PropertyLayout<dim>;
    // Every point writes its own particle: update them in parallel. A point beyond the grid's
    // edge is marked and the first of them (in the serial order) reported below.
    const auto                &points = cache.points();
    std::vector<unsigned char> outside(points.size(), 0);
    std::vector<Point<dim>>    moved(points.size());
    // Per direction, whether the lower and the upper side of the grid are contact planes.
    const auto                          *contact = terms.contact();
    std::array<std::array<bool, 2>, dim> on_contact_plane{};
    for (unsigned int d = 0; d < dim && contact != nullptr; ++d)
      on_contact_plane[d] = {{contact->on_contact_plane(d, -1.), contact->on_contact_plane(d, 1.)}};
    std::atomic<unsigned int> borrowed{0};
    const auto                update_point = [&](const unsigned int p) {
      const PointRecord<dim> &r    = cache.points()[p];
      const auto [du, delta_F, mu] = cache.fields_at(r, solution);

      const Tensor<2, dim> F_p =
        physical_or_borrowed_increment(r, delta_F, du, solution, borrowed) * r.F_p;
      // J_n relative to the initial configuration: in plane strain the out-of-plane stretch
      // stays lambda_0; in an axisymmetric scene the hoop stretch is r_{n+1}/R_0.
      const double lambda_0 = r.gel->lambda_0();
      const double hoop     = r.axisymmetric() ? (r.radius + du[0]) / r.X0[0] : 1.;
      const double J_n = hoop * dealii::determinant(F_p) / std::pow(lambda_0, dim);

      auto props = cache.particle(p)->get_properties();
      for (unsigned int i = 0; i < dim; ++i)
        for (unsigned int j = 0; j < dim; ++j)
          props[Layout::F + i * dim + j] = F_p[i][j];
      if constexpr (dim == 2)
        if (r.axisymmetric())
          props[Layout::out_of_plane] = lambda_0 * hoop;
      props[Layout::mu_increment] = mu - r.mu_n;
      props[Layout::mu]           = mu;
      for (unsigned int d = 0; d < dim; ++d)
        props[Layout::increment + d] = du[d];
      if (r.kind == PointKind::volume)
        props[Layout::measure_n] = J_n * props[Layout::measure_0];
      else
        {
          // eq. (34): N_n A_n = J_n F_n^{-T} N_0 A_0 with F_n = F_p / lambda_0.
          Tensor<1, dim> na0;
          for (unsigned int d = 0; d < dim; ++d)
            na0[d] = props[Layout::normal_area_0 + d];
          const Tensor<1, dim> na = J_n * (dealii::transpose(dealii::invert(F_p)) * na0) * lambda_0;
          for (unsigned int d = 0; d < dim; ++d)
            props[Layout::normal_area_n + d] = na[d];
          props[Layout::measure_n] = na.norm();
        }
      // A point held normal to a grid edge (a roller or a fixed piece on the edge, or a contact
      // plane there) crosses it by the small violation of the weakly imposed condition: its
      // particle stays on the edge and the edge offset keeps the rest of its displacement. So
      // do volume points next to such an edge; where the edge is a free face, its surface
      // points lie beyond the volume points and report the crossing. Any other point beyond
      // the edge is material the grid cannot carry.
      const Point<dim> x_next = r.x + r.edge_offset + du;
      Point<dim>       x      = x_next;
      for (unsigned int d = 0; d < dim; ++d)
        {
          const auto  &basis     = spaces_.u_space().basis_1d(d);
          const double tolerance = 0.25 * basis.cell_size();
          const bool   held = r.kind == PointKind::volume || r.projector[d][d] > 0.5;
          if ((held || on_contact_plane[d][0]) && x[d] < basis.x_min() &&
              x[d] > basis.x_min() - tolerance)
            x[d] = basis.x_min();
          if ((held || on_contact_plane[d][1]) && x[d] > basis.x_max() &&
              x[d] < basis.x_max() + tolerance)
            x[d] = basis.x_max();
          if (x[d] < basis.x_min() || x[d] > basis.x_max())
            outside[p] = 1;
        }
      for (unsigned int d = 0; d < dim; ++d)
        props[Layout::edge_offset + d] = x_next[d] - x[d];
      moved[p] = x;
      if (!outside[p])
        cache.particle(p)->set_location(x);
    };
    dealii::parallel::apply_to_subranges(
      0u,
      static_cast<unsigned int>(points.size()),
      [&](const unsigned int begin, const unsigned int end) {
        for (unsigned int p = begin; p < end; ++p)
          update_point(p);
      },
      256);
    n_borrowed_increments_ += borrowed;

    std::string failure;
    const auto  first_outside = std::find(outside.begin(), outside.end(), 1);
    if (first_outside != outside.end())
      {
        const unsigned int      p = first_outside - outside.begin();
        const PointRecord<dim> &r = cache.points()[p];
        failure                   = std::string(
          "the material point at " + format_point(moved[p]) + " (initially at " +
          format_point(r.X0) + ", " +
          (r.kind == PointKind::volume ? std::string("inside the body")
                                                         : "on the boundary, free normal to the grid edge") +
          ") has crossed the edge of the background grid; enlarge the grid so that the body "
                            "stays inside it ('Background grid/Lower corner', 'Upper corner')");
      }
    Collective::agree_on_failure<std::runtime_error>(communicator, failure);
  }


  template <int dim>
  Tensor<2, dim>
  MixedSystem<dim>::physical_or_borrowed_increment(const PointRecord<dim>       &r,
                                                   const Tensor<2, dim>         &delta_F,
                                                   const Tensor<1, dim>         &du,
                                                   const dealii::Vector<double> &solution,
                                                   std::atomic<unsigned int>    &borrowed) const
  {
    if (r.kind == PointKind::volume)
      return delta_F;
    const auto physical = [&r, &du](const Tensor<2, dim> &increment) {
      const Tensor<2, dim> F_p = increment * r.F_p;
      try
        {
          if (r.axisymmetric())
            r.gel->mobility(F_p, r.hoop * (r.radius + du[0]) / r.radius);
          else
            r.gel->mobility(F_p);
          return true;
        }
      catch (const NonPhysicalState &)
        {
          return false;
        }
    };
    if (physical(delta_F))
      return delta_F;
    // Where the surface folds (a crease closing) the field's gradient extrapolated to a surface
    // point can invert its F, which serves its normal and mobility only: it takes the increment
    // of the nearest volume point of its block (whose functions it shares) instead.
    const PointBlock &block   = cache.blocks()[r.block];
    unsigned int      nearest = dealii::numbers::invalid_unsigned_int;
    double            closest = std::numeric_limits<double>::max();
    for (unsigned int q = block.first; q < block.end; ++q)
      if (const auto &v = cache.points()[q];
          v.kind == PointKind::volume && (v.x - r.x).norm() < closest)
        {
          closest = (v.x - r.x).norm();
          nearest = q;
        }
    if (nearest == dealii::numbers::invalid_unsigned_int)
      return delta_F;
    const Tensor<2, dim> increment = cache.fields_at(cache.points()[nearest], solution).delta_F;
    if (!physical(increment))
      return delta_F;
    ++borrowed;
    return increment;
  }


  template void
  MixedSystem<2>::update_particles(const dealii::Vector<double> &);
  template void
  MixedSystem<3>::update_particles(const dealii::Vector<double> &);
  template Tensor<2, 2>
  MixedSystem<2>::physical_or_borrowed_increment(const PointRecord<2> &,
                                                 const Tensor<2, 2> &,
                                                 const Tensor<1, 2> &,
                                                 const dealii::Vector<double> &,
                                                 std::atomic<unsigned int> &) const;
  template Tensor<2, 3>
  MixedSystem<3>::physical_or_borrowed_increment(const PointRecord<3> &,
                                                 const Tensor<2, 3> &,
                                                 const Tensor<1, 3> &,
                                                 const dealii::Vector<double> &,
                                                 std::atomic<unsigned int> &) const;
} // namespace GelMPM
