#ifndef gelmpm_geometry_surface_geometry_h
#define gelmpm_geometry_surface_geometry_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <vector>

namespace GelMPM
{
  /**
   * Shape measures of a boundary piece as a whole (Observables, 'Surface pieces'): its relief,
   * and in 2D the polyline of its surface points along the surface and the folds of that
   * polyline. Unlike PoreGeometry, nothing is given about the piece's shape (no centre): the
   * points are ordered from their initial positions and normals alone.
   */
  namespace SurfaceGeometry
  {
    /**
     * The relief of a surface: the extent max - min of (x_i - x_mean) . n over the points
     * @p positions, with x_mean their mean and n the unit vector along the sum of
     * @p normal_areas (N_n A_n per point: the area-weighted mean normal). 0 for no points and
     * for a piece that has no mean normal, |sum N A| <= 0.1 sum |N A|: a closed surface, whose
     * normals cancel, or two opposite faces.
     */
    template <int dim>
    double
    relief(const std::vector<dealii::Point<dim>>     &positions,
           const std::vector<dealii::Tensor<1, dim>> &normal_areas);

    /** A surface point of a 2D piece, as gathered by Observables. */
    struct SurfacePoint
    {
      dealii::Point<2>     X_0;      ///< position in the initial configuration
      dealii::Tensor<1, 2> normal_0; ///< outward normal there (any length, N_0 A_0)
      dealii::Point<2>     x;        ///< current position
      double               mu = 0.;  ///< chemical potential mu/k_BT
      unsigned int index = 0; ///< the caller's number of the point, carried through the ordering
    };

    /**
     * The points of a 2D piece in their order along the surface: one or more curves (a piece
     * may outline several pores), each open or closed, one after the other.
     */
    struct Polyline
    {
      /** The points, curve after curve, each curve in the order along it. */
      std::vector<SurfacePoint> points;
      /**
       * Arc length in the initial configuration from the first point, the sum of the distances
       * between consecutive initial positions; from one curve to the next it grows by the
       * straight distance between them, so that it increases along the whole list.
       */
      std::vector<double> s_0;
      /** The index of the first point of each curve, and points.size() at the end. */
      std::vector<unsigned int> curve_begin;
      /** Per curve: whether it is closed (its last point continues to its first). */
      std::vector<bool> closed;
      /** Per curve: its initial length, for a closed curve with the closing segment. */
      std::vector<double> length_0;

      /** The number of curves. */
      unsigned int
      n_curves() const
      {
        return closed.size();
      }

      /**
       * The current positions of curve @p c in order; a closed curve starts with its last
       * point and ends with its first, so that every point has both neighbours and the
       * closing segment appears (for PoreGeometry's measures of open polylines).
       */
      std::vector<dealii::Point<2>>
      current_curve(const unsigned int c) const;
    };

    /**
     * Order the surface points of a 2D piece along the surface, from their initial positions
     * X_0 and initial normals N_0 only; the input order does not matter.
     *
     * The tangent t = (N_y, -N_x) orients the surface with the body on its right (outward
     * normals: clockwise about the body; a top surface from left to right). The points are first
     * sorted lexicographically by X_0, so that the result does not depend on their order on entry
     * or on the MPI ranks. From the first point not yet taken, a curve grows forwards by the
     * nearest point not yet taken that lies ahead, (X_j - X_i) . (t_i + t_j) > 0, no farther than
     * @p largest_gap and whose tangent does not turn back (t_i . t_j > -0.9, i.e. by less than
     * about 154 degrees: the two faces of a thin slit are not joined), until there is none; then
     * backwards from its first point in the same way. A curve is closed when its first point lies
     * ahead of its last within these limits. A curve that begins ahead of another's end is appended
     * to it; a curve of one or two points (points that the nearest-neighbour walk stepped over) is
     * put into the segment of a longer curve where it adds the least length, if that segment is
     * shorter than
     * @p largest_gap. Initial surfaces resolved by points less than @p largest_gap apart are
     * ordered correctly whatever their curvature, corners of up to about 150 degrees included;
     * the current positions do not enter, so a fold of the current surface cannot disturb the
     * order.
     */
    Polyline
    order_along_surface(std::vector<SurfacePoint> points, const double largest_gap);

    /**
     * The number of folds of @p polyline: the disjoint stretches of surface that are folded onto
     * themselves. A point and a segment fold the stretch between them when both ends of the
     * segment are farther than @p arc_length from the point along the current surface (on a
     * closed curve the shorter way round; points of different curves always) but the point is
     * closer than @p approach_distance to the segment (self-approach); two crossing segments
     * (PoreGeometry's self-intersection) fold the stretch between them whatever its length.
     * Stretches that overlap or are less than @p arc_length apart along the surface make one fold:
     * the nested pairs of the two flanks of one crease, and on a closed curve whose sides touch the
     * pairs that take one way round and those that take the other (also across its first point).
     */
    unsigned int
    count_folds(const Polyline &polyline, const double approach_distance, const double arc_length);
  } // namespace SurfaceGeometry
} // namespace GelMPM

#endif
