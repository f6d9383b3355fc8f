#include <gelmpm/assembly/axisymmetric_terms.h>
#include <gelmpm/assembly/displacement_nitsche.h>
#include <gelmpm/assembly/plane_contact.h>

#include <algorithm>
#include <limits>

namespace GelMPM
{
  using dealii::Point;
  using dealii::Tensor;


  template <int dim>
  void
  PlaneContactAssembler<dim>::set_settings(const ContactSettings &settings)
  {
    contact = settings;
    Point<dim> lower, upper;
    for (unsigned int d = 0; d < dim; ++d)
      {
        lower[d] = this->spaces.u_space().basis_1d(d).x_min();
        upper[d] = this->spaces.u_space().basis_1d(d).x_max();
      }
    planes = settings.planes(lower, upper);
  }


  template <int dim>
  bool
  PlaneContactAssembler<dim>::enabled() const
  {
    return contact.enabled();
  }


  template <int dim>
  bool
  PlaneContactAssembler<dim>::on_contact_plane(const unsigned int axis, const double sign) const
  {
    return std::any_of(planes.begin(), planes.end(), [&](const auto &plane) {
      return plane.axis == axis && plane.sign == sign;
    });
  }


  template <int dim>
  std::pair<bool, double>
  PlaneContactAssembler<dim>::state(const PointRecord<dim> &r,
                                    const Tensor<1, dim>   &du,
                                    const Tensor<2, dim>   &delta_F,
                                    const double            mu) const
  {
    bool         is_active   = false;
    double       penetration = -std::numeric_limits<double>::infinity();
    const double beta        = contact.penalty * r.gel->shear_modulus() / this->spaces.h_u();
    for (const auto &plane : planes)
      {
        const double g =
          plane.sign * (r.x[plane.axis] + r.edge_offset[plane.axis] + du[plane.axis] - plane.value);
        penetration = std::max(penetration, g);
        if (contact.method == ContactSettings::Method::nitsche)
          {
            Tensor<1, dim> n;
            n[plane.axis]    = plane.sign;
            const auto state = point_state(r, delta_F, du, mu, false);
            is_active |= beta * g - n * (state.P_n * r.normal) > 0.;
          }
        else
          is_active |= g > 0.;
      }
    return {is_active, penetration};
  }


  template <int dim>
  void
  PlaneContactAssembler<dim>::assemble(const PointRecord<dim> &point,
                                       const double /*dt*/,
                                       const bool            with_matrix,
                                       AssemblyScratch<dim> &s,
                                       AssemblyCopy         &copy) const
  {
    if (!contact.enabled() || this->piece(point).displacement_prescribed())
      return;
    const double beta = contact.penalty * point.gel->shear_modulus() / this->spaces.h_u();
    // The traction P_n N, once per point for all planes (Nitsche only).
    Tensor<1, dim> traction;
    if (contact.method == ContactSettings::Method::nitsche)
      traction =
        point_state(point, s.delta_F, s.du_at_point, s.mu_at_point, false).P_n * point.normal;
    for (const auto &plane : planes)
      {
        const double   g = plane.sign * (point.x[plane.axis] + point.edge_offset[plane.axis] +
                                       s.du_at_point[plane.axis] - plane.value);
        Tensor<1, dim> n;
        n[plane.axis] = plane.sign;
        if (contact.method == ContactSettings::Method::nitsche)
          {
            // Nitsche's active set: the augmented normal traction sigma_n - beta g < 0.
            const double sigma_n = n * traction;
            if (beta * g - sigma_n > 0.)
              add_displacement_nitsche(point,
                                       outer(n, n),
                                       g * n,
                                       beta,
                                       this->nitsche.symmetry,
                                       with_matrix,
                                       s,
                                       copy);
            continue;
          }
        if (g <= 0.)
          continue;
        const unsigned int i    = plane.axis;
        const double       area = point.measure;
        for (unsigned int a = 0; a < s.n_u; ++a)
          copy.residual(dim * a + i) += area * beta * g * plane.sign * s.N[a];
        if (with_matrix)
          for (unsigned int a = 0; a < s.n_u; ++a)
            for (unsigned int c = 0; c < s.n_u; ++c)
              copy.matrix(dim * a + i, dim * c + i) += area * beta * s.N[a] * s.N[c];
      }
  }


  template class PlaneContactAssembler<2>;
  template class PlaneContactAssembler<3>;
} // namespace GelMPM
