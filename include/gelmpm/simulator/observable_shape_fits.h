#ifndef gelmpm_simulator_observable_shape_fits_h
#define gelmpm_simulator_observable_shape_fits_h

#include <gelmpm/geometry/shape_fit.h>
#include <gelmpm/geometry/surface_geometry.h>
#include <gelmpm/simulator/observable.h>

#include <deal.II/base/parameter_handler.h>

#include <boost/serialization/vector.hpp>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace GelMPM
{
  /**
   * @brief The fitted shape of boundary pieces and the relief on it, per piece of "Shape
   * pieces" (columns <piece>_fit_curvature, _fit_residual, _amplitude, _skewness, and in 2D
   * _wavelength, _relative_amplitude, _dip_crest_ratio):
   * - the curvature of the least-squares circle (2D: plane strain, or an axisymmetric scene's
   *   meridian) or sphere (3D) through the piece's current surface points
   *   (ShapeFit::fit_sphere()), signed positive for a convex piece, and the RMS distance of the
   *   points from it;
   * - the relief: the points' signed distances, positive along the outward normal, from the
   *   piece's smooth shape (ShapeFit::smooth_shape(): that circle or sphere where it fits, a line
   *   or plane otherwise): its amplitude (half the range) and skewness, and in 2D, along the
   *   polyline of the points in their order along the surface (SurfaceGeometry), its dominant
   *   wavelength (ShapeFit::undulation()), amplitude over wavelength, and the curvature of its
   *   dips over that of its crests (ShapeFit::dip_crest_curvature_ratio()).
   *
   * In 2D, with 'Instability threshold' > 0, the first time a piece's amplitude over wavelength
   * reaches it is the event 'instability_crease_<piece>' or 'instability_wrinkle_<piece>'
   * (new_events()): a crease where the relief is made of narrow dips between broad crests, its
   * skewness at or below -'Crease skewness', a wrinkle otherwise; a wrinkle whose skewness later
   * falls that low while above the threshold is then the event 'instability_crease_<piece>'.
   */
  template <int dim>
  class ShapeFits : public Observable<dim>
  {
  public:
    /** Its entries, in the section "Observables" (entered). */
    static void
    declare_parameters(dealii::ParameterHandler &prm);

    /** From the section (entered), @p pieces being the scene's piece names; none if off. */
    static std::unique_ptr<ShapeFits>
    parse(dealii::ParameterHandler &prm, const std::vector<std::string> &pieces);

    std::vector<std::string>
    columns() const override;

    void
    evaluate(const ObservedState<dim> &state, StatisticsFile &statistics) const override;

    /**
     * The cell size h_u (@p spacing) of the displacement grid: in 2D the polyline joins points
     * less than 2 h_u apart (SurfaceGeometry::order_along_surface()); needed in 2D before
     * evaluate().
     */
    void
    set_grid_spacing(const double spacing);

    /**
     * In 2D with 'Instability threshold', the events since the last call, as (name, 0): at most
     * a wrinkle and then a crease per piece.
     */
    std::vector<std::pair<std::string, unsigned int>>
    new_events(const dealii::Particles::ParticleHandler<dim> &particles);

    /** Whether new_events() can report anything. */
    bool
    writes_events() const;

    /** The instabilities reported per piece, for a checkpoint (the archive's fields, no class
     * record). */
    template <class Archive>
    void
    serialize(Archive &ar, const unsigned int)
    {
      ar &instabilities_seen;
    }

  private:
    /** What shapes() measures of one piece. */
    struct Shape
    {
      double fit_curvature      = 0.;
      double fit_residual       = 0.;
      double amplitude          = 0.;
      double skewness           = 0.;
      double wavelength         = 0.;
      double relative_amplitude = 0.;
      double dip_crest_ratio    = 0.;
    };

    /**
     * The shape of one piece from its points' current @p positions and @p normals (N_n A_n), and
     * in 2D its @p points for the order along the surface. At least dim + 1 points.
     */
    Shape
    shape_of(const std::vector<dealii::Point<dim>>            &positions,
             const std::vector<dealii::Tensor<1, dim>>        &normals,
             const std::vector<SurfaceGeometry::SurfacePoint> &points) const;

    /** Per piece, its shape; gathers the pieces' points over the communicator. */
    std::vector<Shape>
    shapes(const dealii::Particles::ParticleHandler<dim> &particles) const;

    std::vector<unsigned int> pieces;
    std::vector<std::string>  names;
    double                    instability_threshold = 0.;
    double                    crease_skewness       = 0.5;
    double                    h_u                   = 0.;
    /** Per piece, the last instability event written (a wrinkle may turn into creases). */
    std::vector<unsigned int>     instabilities_seen;
    static constexpr unsigned int no_instability = 0, wrinkle_seen = 1, crease_seen = 2;
  };
} // namespace GelMPM

#endif
