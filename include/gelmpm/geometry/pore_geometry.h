#ifndef gelmpm_geometry_pore_geometry_h
#define gelmpm_geometry_pore_geometry_h

#include <deal.II/base/point.h>

#include <vector>

namespace GelMPM
{
  /**
   * Shape measures of a pore's surface, given as the polyline of its surface points in their
   * order along the boundary (paper §4.4, Fig. 12b: creasing). Open polylines: a quarter pore
   * ends on the planes of symmetry.
   */
  namespace PoreGeometry
  {
    /**
     * The largest Menger curvature 4 A / (|a| |b| |c|) over the triangles of three consecutive
     * points (A the triangle's area, a, b, c its sides): 1/R on points of a circle of radius R.
     * 0 for fewer than three points.
     */
    double
    largest_curvature(const std::vector<dealii::Point<2>> &polyline);

    /**
     * The largest angle (radians, 0 ... pi) by which the direction of the polyline turns from
     * one segment to the next. A smooth surface resolved by points a distance d apart turns by
     * about d/r at a point of curvature radius r; a crease turns by a finite angle at one point.
     */
    double
    largest_turning(const std::vector<dealii::Point<2>> &polyline);

    /**
     * The number of sharp corners: runs of consecutive points at which the polyline turns by more
     * than @p angle (radians); a corner resolved by several points counts once.
     */
    unsigned int
    sharp_corners(const std::vector<dealii::Point<2>> &polyline, const double angle);

    /** Whether two segments of the polyline that do not share a point cross each other. */
    bool
    self_intersects(const std::vector<dealii::Point<2>> &polyline);
  } // namespace PoreGeometry
} // namespace GelMPM

#endif
