#ifndef gelmpm_geometry_shape_fit_h
#define gelmpm_geometry_shape_fit_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <vector>

namespace GelMPM
{
  /**
   * The smooth shape of a set of surface points and how the points depart from it
   * (Observables, 'Shape pieces'): a least-squares circle (2D) or sphere (3D), which becomes a
   * line or plane as its curvature goes to zero, the points' signed distances from it, and the
   * measures of the relief those distances make along a 2D curve (amplitude, dominant
   * wavelength, skewness, the curvature of its dips against that of its crests).
   */
  namespace ShapeFit
  {
    /**
     * A circle (2D) or sphere (3D), or its limit a line or plane: the zero set of
     *   P(x) = a |x - o|^2 + b . (x - o) + c,   normalised so that |b|^2 - 4 a c = 1.
     * With this normalisation 2a is the signed curvature 1/R (0 for a line or plane), the
     * signed distance of x from the shape is 2 P / (1 + sqrt(1 + 4 a P)) (exact for every a,
     * no cancellation for large R), positive on the side towards which grad P = 2a (x - o) + b
     * points: outside a circle of a > 0, inside one of a < 0. Multiplying (a, b, c) by -1 gives
     * the same shape with the other side positive (orient()).
     */
    template <int dim>
    struct Hypersphere
    {
      /** The origin the coefficients refer to (the mean of the fitted points). */
      dealii::Point<dim> origin;
      double             a = 0.;
      /** A unit normal of a line or plane (a = 0). */
      dealii::Tensor<1, dim> b;
      double                 c = 0.;

      /** The signed curvature 2a: 1/R, with the sign of the side that distance() counts positive.
       */
      double
      curvature() const
      {
        return 2. * a;
      }

      /** The signed distance of @p x from the shape (see the class). */
      double
      distance(const dealii::Point<dim> &x) const;

      /** The direction in which distance() grows at @p x (not normalised). */
      dealii::Tensor<1, dim>
      gradient(const dealii::Point<dim> &x) const;

      /**
       * Make distance() positive along @p normals at @p points on the whole (the sum of
       * normal . gradient() over the points positive; e.g. the body's outward N A), so that
       * curvature() is positive where the body lies on the side of the centre (a convex body,
       * a sphere's surface) and negative where it lies away from it (a concave face).
       */
      void
      orient(const std::vector<dealii::Point<dim>>     &points,
             const std::vector<dealii::Tensor<1, dim>> &normals);
    };

    /**
     * The circle (2D) or sphere (3D) of Taubin's algebraic least-squares fit (G. Taubin, IEEE
     * PAMI 13 (1991) 1115; N. Chernov, Circular and linear regression, 2010): the coefficients
     * that minimise sum_i P(x_i)^2 under 4 a^2 mean|x - o|^2 + |b|^2 = 1 (the smallest
     * eigenvector of a (dim + 1)^2 symmetric matrix, by Jacobi rotations), renormalised as
     * Hypersphere. It agrees with the geometric fit (least squares of the distances) up to
     * second order in the points' scatter about the shape, reproduces an exact circle or sphere,
     * and, unlike Kasa's fit, stays well posed for points on a line or plane (a = 0). At least
     * dim + 1 points not all in one point.
     */
    template <int dim>
    Hypersphere<dim>
    fit_sphere(const std::vector<dealii::Point<dim>> &points);

    /** The line (2D) or plane (3D) of total least squares through @p points (a = 0). */
    template <int dim>
    Hypersphere<dim>
    fit_plane(const std::vector<dealii::Point<dim>> &points);

    /** The root mean square of the distances of @p points from @p shape (0 for no points). */
    template <int dim>
    double
    rms_distance(const Hypersphere<dim> &shape, const std::vector<dealii::Point<dim>> &points);

    /**
     * The smooth shape of @p points the relief is measured from: the sphere of fit_sphere() if
     * its RMS distance is at most half that of the plane of fit_plane() (the points bend), the
     * plane otherwise (a flat surface, or one whose relief a sphere would only follow in part,
     * such as a single crease in a flat film).
     */
    template <int dim>
    Hypersphere<dim>
    smooth_shape(const std::vector<dealii::Point<dim>> &points);

    /**
     * The skewness mean((v - mean v)^3) / s^3 of @p values, s their standard deviation: 0 for
     * values symmetric about their mean (a sinusoid's); negative when a few values lie far below
     * the rest. 0 for fewer than two distinct values.
     */
    double
    skewness(const std::vector<double> &values);

    /** What undulation() measures of the signed distances of a curve's points from its shape. */
    struct Undulation
    {
      /** Half the range, (max - min)/2: A for A sin(...). */
      double amplitude = 0.;
      /** The root mean square about zero. */
      double rms = 0.;
      /**
       * The dominant wavelength along the current arc length (see undulation()); 0 if the
       * curve has fewer than 8 points.
       */
      double wavelength = 0.;
      /**
       * skewness() of the distances: 0 for a sinusoid; negative when narrow deep dips (d < 0)
       * sit between broad low crests, as creases do with d positive along the outward normal.
       */
      double skewness = 0.;
    };

    /**
     * The relief of the curve @p curve (points in order, @p closed: the last continues to the
     * first) whose points lie at the signed distances @p deviations from its smooth shape.
     * The wavelength comes from the discrete Fourier transform of the deviation over the
     * current arc length: resampled at as many equally spaced places as there are points
     * (linear interpolation), its mean removed, a closed curve as one period of length L, an
     * open one under a Hann window (as if of period T = L n/(n - 1)); the wavelength is T/k at
     * the largest |coefficient| k >= 1 (k >= 2 open, where k = 1 is the window's own), refined
     * by the parabola through the magnitudes at k - 1, k, k + 1. A Fourier transform rather
     * than the spacing of extrema or zero crossings: the points of a smooth surface scatter at
     * the scale of their spacing, which adds extrema and zero crossings everywhere before an
     * undulation has grown but spreads over all wavenumbers in the transform, whose peak stays
     * on the undulation. Resolved: wavelengths from about 3 point spacings to L/2 (open) or L
     * (closed).
     */
    Undulation
    undulation(const std::vector<dealii::Point<2>> &curve,
               const std::vector<double>           &deviations,
               const bool                           closed);

    /**
     * The ratio of the largest curvature of the dips to that of the crests of a 2D relief:
     * with the Menger curvature kappa_i of the points of @p curve (in order, the body on the
     * right, @p closed as for undulation()), positive where the curve bends about the body
     * (convex), and the smooth shape's @p shape_curvature (same sign convention), the relief's
     * curvature k_i = kappa_i - shape_curvature; the largest -k_i (a dip) over the largest k_i
     * (a crest). 1 for a sinusoidal relief; a crease's dip is curved at the scale of the point
     * spacing, its crests at that of the creases' spacing. 0 if no point bends as a dip; a
     * large value (1e6) if none bends as a crest.
     */
    double
    dip_crest_curvature_ratio(const std::vector<dealii::Point<2>> &curve,
                              const bool                           closed,
                              const double                         shape_curvature);
  } // namespace ShapeFit
} // namespace GelMPM

#endif
