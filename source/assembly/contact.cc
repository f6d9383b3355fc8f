#include <gelmpm/assembly/axisymmetric_terms.h>
#include <gelmpm/assembly/contact.h>
#include <gelmpm/assembly/displacement_nitsche.h>

#include <algorithm>
#include <limits>

namespace GelMPM
{
  using dealii::Point;
  using dealii::Tensor;


  template <int dim>
  void
  ContactAssembler<dim>::set_settings(const ContactSettings            &settings,
                                      const std::vector<Obstacle<dim>> *obstacles)
  {
    contact = settings;
    Point<dim> lower, upper;
    for (unsigned int d = 0; d < dim; ++d)
      {
        lower[d] = this->spaces.u_space().basis_1d(d).x_min();
        upper[d] = this->spaces.u_space().basis_1d(d).x_max();
      }
    sides.clear();
    for (const auto &plane : settings.planes(lower, upper))
      sides.push_back(Obstacle<dim>::grid_side("grid side", plane.axis, plane.value, plane.sign));
    rigid = obstacles;
    any_impermeable =
      rigid != nullptr && std::any_of(rigid->begin(), rigid->end(), [](const auto &obstacle) {
        return !obstacle.permeable;
      });
  }


  template <int dim>
  void
  ContactAssembler<dim>::start_block(AssemblyScratch<dim> &s,
                                     const unsigned int /*n_points*/,
                                     const bool with_matrix) const
  {
    if (with_matrix && contact.method == ContactSettings::Method::nitsche)
      start_displacement_nitsche_block(s, this->tangent.template batched<dim>());
  }


  template <int dim>
  void
  ContactAssembler<dim>::finish_block(AssemblyScratch<dim> &s,
                                      AssemblyCopy         &copy,
                                      const bool            with_matrix) const
  {
    if (with_matrix && contact.method == ContactSettings::Method::nitsche)
      add_displacement_nitsche_block(s, copy);
  }


  template <int dim>
  const Obstacle<dim> &
  ContactAssembler<dim>::obstacle(const unsigned int k) const
  {
    return k < sides.size() ? sides[k] : (*rigid)[k - sides.size()];
  }


  template <int dim>
  unsigned int
  ContactAssembler<dim>::n_obstacles() const
  {
    return sides.size() + n_rigid_obstacles();
  }


  template <int dim>
  bool
  ContactAssembler<dim>::enabled() const
  {
    return contact.enabled();
  }


  template <int dim>
  bool
  ContactAssembler<dim>::on_contact_plane(const unsigned int axis, const double sign) const
  {
    return std::any_of(sides.begin(), sides.end(), [&](const auto &side) {
      return side.normal[axis] == -sign;
    });
  }


  template <int dim>
  unsigned int
  ContactAssembler<dim>::n_rigid_obstacles() const
  {
    return rigid == nullptr ? 0 : rigid->size();
  }


  template <int dim>
  const Obstacle<dim> &
  ContactAssembler<dim>::rigid_obstacle(const unsigned int k) const
  {
    return (*rigid)[k];
  }


  template <int dim>
  unsigned int
  ContactAssembler<dim>::index_of_rigid(const unsigned int k) const
  {
    return sides.size() + k;
  }


  template <int dim>
  bool
  ContactAssembler<dim>::applies(const PointRecord<dim> &point) const
  {
    return contact.enabled() && !this->piece(point).displacement_prescribed();
  }


  template <int dim>
  double
  ContactAssembler<dim>::penalty(const PointRecord<dim> &point) const
  {
    return contact.penalty * point.gel->shear_modulus() / this->spaces.h_u(point.level);
  }


  template <int dim>
  Point<dim>
  ContactAssembler<dim>::position(const PointRecord<dim> &point, const Tensor<1, dim> &du)
  {
    return point.x + point.edge_offset + du;
  }


  template <int dim>
  std::pair<bool, double>
  ContactAssembler<dim>::state(const unsigned int      k,
                               const PointRecord<dim> &r,
                               const Tensor<1, dim>   &du,
                               const Tensor<2, dim>   &delta_F,
                               const double            mu) const
  {
    const auto gap = obstacle(k).gap(position(r, du));
    if (!gap.possible)
      return {false, -std::numeric_limits<double>::infinity()};
    if (contact.method == ContactSettings::Method::nitsche)
      {
        const auto state = point_state(r, delta_F, du, mu, false);
        return {contact.active_set_factor * penalty(r) * gap.g - gap.m * (state.P_n * r.normal) >
                  0.,
                gap.g};
      }
    return {gap.g > 0., gap.g};
  }


  template <int dim>
  std::int64_t
  ContactAssembler<dim>::active_rigid(const PointRecord<dim> &point,
                                      const Tensor<1, dim>   &du,
                                      const Tensor<2, dim>   &delta_F,
                                      const double            mu) const
  {
    std::int64_t active = 0;
    if (applies(point))
      for (unsigned int k = 0; k < n_rigid_obstacles(); ++k)
        if (state(index_of_rigid(k), point, du, delta_F, mu).first)
          active |= std::int64_t(1) << k;
    return active;
  }


  template <int dim>
  bool
  ContactAssembler<dim>::seals(const PointRecord<dim> &point,
                               const Tensor<1, dim>   &du,
                               const Tensor<2, dim>   &delta_F,
                               const double            mu) const
  {
    if (point.seal >= 0)
      return point.seal == 1;
    return touches_impermeable(point, du, delta_F, mu);
  }


  template <int dim>
  bool
  ContactAssembler<dim>::touches_impermeable(const PointRecord<dim> &point,
                                             const Tensor<1, dim>   &du,
                                             const Tensor<2, dim>   &delta_F,
                                             const double            mu) const
  {
    if (!any_impermeable || !applies(point))
      return false;
    for (unsigned int k = 0; k < n_rigid_obstacles(); ++k)
      if (!rigid_obstacle(k).permeable && state(index_of_rigid(k), point, du, delta_F, mu).first)
        return true;
    return false;
  }


  template <int dim>
  std::pair<bool, double>
  ContactAssembler<dim>::state(const PointRecord<dim> &r,
                               const Tensor<1, dim>   &du,
                               const Tensor<2, dim>   &delta_F,
                               const double            mu) const
  {
    bool   is_active   = false;
    double penetration = -std::numeric_limits<double>::infinity();
    for (unsigned int k = 0; k < n_obstacles(); ++k)
      {
        const auto [active, g] = state(k, r, du, delta_F, mu);
        penetration            = std::max(penetration, g);
        is_active |= active;
      }
    return {is_active, penetration};
  }


  template <int dim>
  void
  ContactAssembler<dim>::add_obstacle(const Obstacle<dim>    &obstacle,
                                      const PointRecord<dim> &point,
                                      const Tensor<1, dim>   &traction,
                                      const bool              with_matrix,
                                      AssemblyScratch<dim>   &s,
                                      AssemblyCopy           &copy,
                                      const int               held) const
  {
    const auto gap = obstacle.gap(position(point, s.du_at_point));
    if (!gap.possible)
      return;
    const double          beta = penalty(point);
    const double          g    = gap.g;
    const Tensor<1, dim> &n    = gap.m;
    if (contact.method == ContactSettings::Method::nitsche)
      {
        // Nitsche's active set: the augmented normal traction sigma_n - f beta g < 0.
        const double sigma_n = n * traction;
        if (held >= 0 ? held == 1 : contact.active_set_factor * beta * g - sigma_n > 0.)
          {
            add_displacement_nitsche(point,
                                     outer(n, n),
                                     g * n,
                                     beta,
                                     this->nitsche.symmetry,
                                     with_matrix,
                                     s,
                                     copy,
                                     this->tangent.reference_nitsche);
            // The curvature of a sphere or a punch's rounded edge: beta g dm/dx, the derivative
            // of g m beyond m (x) m.
            if (with_matrix && gap.dm_dx != Tensor<2, dim>())
              for (unsigned int a = 0; a < s.n_u; ++a)
                for (unsigned int c = 0; c < s.n_u; ++c)
                  for (unsigned int k = 0; k < dim; ++k)
                    for (unsigned int m = 0; m < dim; ++m)
                      copy.matrix(dim * a + k, dim * c + m) +=
                        point.measure * beta * g * gap.dm_dx[k][m] * s.N[a] * s.N[c];
          }
        return;
      }
    if (held >= 0 ? held == 0 : g <= 0.)
      return;
    // R_u[w] += A beta g m . w; its derivative A beta (m (x) m + g dm/dx). The components of m
    // that are zero (a plane along an axis) are skipped, so that a grid side adds what it
    // always has, bit for bit.
    const double area = point.measure;
    for (unsigned int i = 0; i < dim; ++i)
      if (n[i] != 0.)
        for (unsigned int a = 0; a < s.n_u; ++a)
          copy.residual(dim * a + i) += area * beta * g * n[i] * s.N[a];
    if (!with_matrix)
      return;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        {
          const double curvature = g * gap.dm_dx[i][j];
          if (n[i] * n[j] == 0. && curvature == 0.)
            continue;
          if (curvature == 0.)
            for (unsigned int a = 0; a < s.n_u; ++a)
              for (unsigned int c = 0; c < s.n_u; ++c)
                copy.matrix(dim * a + i, dim * c + j) +=
                  area * beta * n[i] * n[j] * s.N[a] * s.N[c];
          else
            for (unsigned int a = 0; a < s.n_u; ++a)
              for (unsigned int c = 0; c < s.n_u; ++c)
                copy.matrix(dim * a + i, dim * c + j) +=
                  area * beta * (n[i] * n[j] + curvature) * s.N[a] * s.N[c];
        }
  }


  template <int dim>
  Tensor<1, dim>
  ContactAssembler<dim>::nitsche_traction(const PointRecord<dim>     &point,
                                          const AssemblyScratch<dim> &s) const
  {
    if (contact.method != ContactSettings::Method::nitsche)
      return Tensor<1, dim>();
    return point_state(point, s.delta_F, s.du_at_point, s.mu_at_point, false).P_n * point.normal;
  }


  template <int dim>
  void
  ContactAssembler<dim>::assemble_obstacle(const unsigned int      k,
                                           const PointRecord<dim> &point,
                                           const bool              with_matrix,
                                           AssemblyScratch<dim>   &s,
                                           AssemblyCopy           &copy) const
  {
    if (!applies(point))
      return;
    const int held = k < sides.size() ? -1 : held_state(point, k - sides.size());
    add_obstacle(obstacle(k), point, nitsche_traction(point, s), with_matrix, s, copy, held);
  }


  template <int dim>
  void
  ContactAssembler<dim>::assemble(const PointRecord<dim> &point,
                                  const double /*dt*/,
                                  const bool            with_matrix,
                                  AssemblyScratch<dim> &s,
                                  AssemblyCopy         &copy) const
  {
    if (!applies(point))
      return;
    // Once per point for all obstacles.
    const Tensor<1, dim> traction = nitsche_traction(point, s);
    for (const auto &side : sides)
      add_obstacle(side, point, traction, with_matrix, s, copy);
    if (rigid != nullptr)
      for (unsigned int k = 0; k < rigid->size(); ++k)
        add_obstacle((*rigid)[k], point, traction, with_matrix, s, copy, held_state(point, k));
  }


  template class ContactAssembler<2>;
  template class ContactAssembler<3>;
} // namespace GelMPM
