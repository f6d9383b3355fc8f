#ifndef gelmpm_simulator_observable_surface_shapes_h
#define gelmpm_simulator_observable_surface_shapes_h

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
   * @brief The shapes of boundary pieces (columns <piece>_relief, and in 2D <piece>_curvature,
   * <piece>_turning, <piece>_folds, per piece of "Surface pieces"): the extent of the piece's
   * current surface points along its mean current normal (SurfaceGeometry::relief()); in 2D, of
   * the polyline of the points ordered along the surface in the initial configuration
   * (SurfaceGeometry::order_along_surface(), no centre needed), the largest Menger curvature
   * times h_u, the largest turning angle in degrees, and the number of folds
   * (SurfaceGeometry::count_folds(): self-approach within 'Fold approach distance' of points
   * more than 'Fold arc length' apart along the surface, or self-intersection). Made for a
   * film's surface crease: once resolved it turns by less than 'Crease angle' at every point,
   * and folds.
   *
   * In 2D, a new fold is the event 'crease_<piece>', and at every output time the polyline is
   * written to surface_<piece>-NNNNN.csv (write_surfaces()).
   */
  template <int dim>
  class SurfaceShapes : public Observable<dim>
  {
  public:
    /** Its entries, in the section "Observables" (entered). */
    static void
    declare_parameters(dealii::ParameterHandler &prm);

    /** From the section (entered), @p pieces being the scene's piece names; none if off. */
    static std::unique_ptr<SurfaceShapes>
    parse(dealii::ParameterHandler &prm, const std::vector<std::string> &pieces);

    std::vector<std::string>
    columns() const override;

    void
    evaluate(const ObservedState<dim> &state, StatisticsFile &statistics) const override;

    /**
     * The cell size h_u (@p spacing) of the displacement grid, the unit of the measures ('Fold
     * approach distance', 'Fold arc length', <piece>_curvature); needed in 2D before
     * evaluate().
     */
    void
    set_grid_spacing(const double spacing);

    /** In 2D, the events since the last call, as ('crease_<piece>', 0); none in 3D. */
    std::vector<std::pair<std::string, unsigned int>>
    new_events(const dealii::Particles::ParticleHandler<dim> &particles);

    /**
     * In 2D, write each piece's polyline, in its order along the surface, to
     * `<directory>/surface_<piece>-NNNNN.csv` (columns s_0, x, y, mu: the arc length in the
     * initial configuration, the current position and mu/k_BT), NNNNN counting the calls from 0
     * (the number of the particles-NNNNN.vtu written at the same time). Collective; rank 0
     * writes, under a temporary name renamed when complete. Nothing in 3D.
     */
    void
    write_surfaces(const dealii::Particles::ParticleHandler<dim> &particles,
                   const std::string                             &directory);

    /** The folds seen and the files written so far, for a checkpoint (the archive's fields, no
     * class record). */
    template <class Archive>
    void
    serialize(Archive &ar, const unsigned int)
    {
      ar &folds_seen &surface_outputs;
    }

  private:
    /** What shapes() measures of one piece. */
    struct Shape
    {
      double       relief    = 0.;
      double       curvature = 0.; // times h_u
      double       turning   = 0.; // radians
      unsigned int folds     = 0;
    };

    /**
     * Per piece, its shape; in 2D its polyline into @p polylines if given. Gathers the pieces'
     * points over the communicator.
     */
    std::vector<Shape>
    shapes(const dealii::Particles::ParticleHandler<dim> &particles,
           std::vector<SurfaceGeometry::Polyline>        *polylines = nullptr) const;

    std::vector<unsigned int> surface_pieces;
    std::vector<std::string>  surface_names;
    double                    fold_approach_distance = 0.5; // times h_u
    double                    fold_arc_length        = 3.;  // times h_u
    double                    h_u                    = 0.;
    std::vector<unsigned int> folds_seen;
    unsigned int              surface_outputs = 0;
  };
} // namespace GelMPM

#endif
