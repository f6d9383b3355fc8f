#ifndef gelmpm_geometry_pair_gap_h
#define gelmpm_geometry_pair_gap_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <array>
#include <vector>

namespace GelMPM
{
  /**
   * @brief The signed gap g of a surface point x_s from the surface of a pair term and its first
   * and second derivatives with respect to the coordinates of the pair's three points
   * (x_s, x_a, x_b) (component fastest). g < 0: the point is behind the surface.
   *
   * 2D (point_segment_gap()): from the line of the segment [x_a, x_b] of a surface polyline,
   * g = (x_s - x_a) . n with n the segment's outward unit normal. point_plane_gap() (3D, and 2D
   * with 'Other face = tangent planes'): from the tangent plane of a surface point x_a with its
   * unit normal n at the start of the step, g = (x_s - x_a) . n (x_b is x_a and has no share).
   */
  template <int dim>
  struct PairGap
  {
    double g = 0.;
    /** 2D: the parameter of the point's projection, 0 at x_a, 1 at x_b. 3D: the distance of
     * x_s from the normal line through x_a (along the tangent plane). */
    double xi = 0.;
    /** The surface's outward unit normal. */
    dealii::Tensor<1, dim>                           normal;
    std::array<double, 3 * dim>                      gradient{};
    std::array<std::array<double, 3 * dim>, 3 * dim> hessian{};
  };

  using PointSegmentGap = PairGap<2>;

  /**
   * The gap of @p x_s from the segment [@p x_a, @p x_b] (a segment of nonzero length), whose
   * outward normal is its tangent turned by +90 degrees (the polylines run with the body on
   * their right, SurfaceGeometry::order_along_surface()).
   */
  PointSegmentGap
  point_segment_gap(const dealii::Point<2> &x_s,
                    const dealii::Point<2> &x_a,
                    const dealii::Point<2> &x_b);

  /** The gap of @p x_s from the plane through @p x_a with the unit normal @p normal (in 2D a
   * line). */
  template <int dim>
  PairGap<dim>
  point_plane_gap(const dealii::Point<dim>     &x_s,
                  const dealii::Point<dim>     &x_a,
                  const dealii::Tensor<1, dim> &normal);


  /**
   * The first and second derivatives of the normal of a pair's surface with respect to the
   * coordinates (x_s, x_a, x_b) of PairGap: first[i][k] = dn_i/dX_k, second[i][k][l]. In 3D the
   * normal is the paired point's at the start of the step: zero.
   */
  template <int dim>
  struct NormalDerivatives
  {
    double first[dim][3 * dim]           = {};
    double second[dim][3 * dim][3 * dim] = {};
  };

  /** Those of a segment's unit normal n = R e / |e| (e = x_b - x_a, R the rotation by +90
   * degrees). */
  NormalDerivatives<2>
  normal_derivatives(const dealii::Point<2> &x_a, const dealii::Point<2> &x_b);

  /** In 3D: zero (the normal is fixed over a step). */
  NormalDerivatives<3>
  normal_derivatives(const dealii::Point<3> &x_a, const dealii::Point<3> &x_b);

  /** For each of the points @p x, the others within @p radius, in increasing order (by buckets
   * of the radius). */
  template <int dim>
  std::vector<std::vector<unsigned int>>
  points_within(const std::vector<dealii::Point<dim>> &x, const double radius);
} // namespace GelMPM

#endif
