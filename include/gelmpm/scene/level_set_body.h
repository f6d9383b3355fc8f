#ifndef gelmpm_scene_level_set_body_h
#define gelmpm_scene_level_set_body_h

#include <gelmpm/scene/body.h>

#include <deal.II/base/function_parser.h>

#include <array>
#include <memory>
#include <string>
#include <vector>

namespace GelMPM
{
  /**
   * @brief A body given by "Geometry/Level set": the open set where an expression phi(x, y[, z])
   * (with the "Level set constants") is negative, inside the background grid. Holes are written
   * into the expression (max(phi, r - |x - c|)).
   *
   * Its boundary, the zero set of phi, is found on a sampling grid of the background grid's box
   * and moved onto the zero set by Newton steps along the gradient (project_onto_zero_set()):
   * - 2D: marching squares trace the closed contours, which are cut at their corners (where
   *   normals turn by more than 30 degrees) and divided into elements of equal length; an
   *   element's normal_area is the rotated chord between its end points, the exact integral of
   *   the normal over the contour between them, so that the sum over a closed contour vanishes
   *   to round-off;
   * - 3D: one element per sampling cube the surface crosses, its normal integral from the
   *   divergence theorem on the cube (exact closure), split among the faces of an edge of the
   *   body that runs through the cube (split_at_edge()).
   * phi < 0 on the edge of the grid is an InputError (the body would be cut off by the grid).
   */
  template <int dim>
  class LevelSetBody : public Body<dim>
  {
  public:
    using typename Body<dim>::SurfaceElement;

    /**
     * The body where @p expression (in x, y[, z] and @p constants) is negative. Throws
     * InputError naming "Geometry/Level set" (or its constants) if it cannot be parsed.
     */
    LevelSetBody(const std::string &expression, const std::string &constants);

    BodySource
    source() const override;

    std::string
    entry() const override;

    /** Whether phi(@p p) < 0. */
    bool
    inside(const dealii::Point<dim> &p) const override;

    /** Blames the level set: it is negative at no sub-cell centre. */
    void
    check_volume_points(const unsigned long n_points,
                        const bool          any_in_boxes,
                        const unsigned long n_samples) const override;

    /**
     * The zero set inside the box [@p lower, @p upper] (the background grid): 2D by marching
     * squares on a sampling grid of spacing at most @p spacing / 2, the closed contours divided
     * into elements of length at most @p spacing; 3D by sampling cubes of edge at most
     * @p spacing. Throws InputError if phi < 0 on the edge of the box.
     */
    std::vector<SurfaceElement>
    surface_elements(const double              spacing,
                     const dealii::Point<dim> &lower,
                     const dealii::Point<dim> &upper) const override;

    /** phi at @p p; throws InputError if it is not finite there. */
    double
    level_set(const dealii::Point<dim> &p) const;

    /** Gradient of phi by central differences with step @p delta. */
    dealii::Tensor<1, dim>
    gradient(const dealii::Point<dim> &p, const double delta) const;

    /**
     * @p p moved onto the zero set of phi by Newton steps along the gradient, at most
     * @p max_shift from where it started (else @p p itself: a degenerate gradient).
     */
    dealii::Point<dim>
    project_onto_zero_set(const dealii::Point<dim> &p, const double max_shift) const;

  private:
    /**
     * 3D: one element in each sampling cube (edge at most @p spacing) the zero surface crosses,
     * with the integral of the normal over the surface in it from the divergence theorem
     * (exact closure), at the mean of its edge crossings projected onto the zero set.
     */
    std::vector<SurfaceElement>
    surface_elements_3d(const double              spacing,
                        const dealii::Point<dim> &lower,
                        const dealii::Point<dim> &upper) const;

    /**
     * 3D: the area of the face of a sampling cube at @p origin normal to the axis @p a (edges
     * @p step) where phi < 0, from the sign changes of phi along 8 strips (bisection).
     */
    double
    face_inside_area(const dealii::Point<dim>      &origin,
                     const unsigned int             a,
                     const std::array<double, dim> &step) const;

    /**
     * 3D: when the @p crossings of the zero set with a sampling cube's edges fall into two or
     * three groups of distinct normals (an edge or a corner of the body runs through the cube),
     * add one element per group with that group's normal, the cube's integral of the normal
     * @p normal_area split among them, and return true; false (nothing added) for a smooth
     * piece of surface or a split that would not carry the integral.
     */
    bool
    split_at_edge(const std::vector<dealii::Point<dim>> &crossings,
                  const dealii::Tensor<1, dim>          &normal_area,
                  const double                           max_shift,
                  std::vector<SurfaceElement>           &elements) const;

    // Shared, not unique: a body stays copyable, and the parser is not changed after parsing.
    std::shared_ptr<dealii::FunctionParser<dim>> phi;
    std::string                                  expression;
  };
} // namespace GelMPM

#endif
