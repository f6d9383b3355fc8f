#ifndef gelmpm_simulator_observable_h
#define gelmpm_simulator_observable_h

#include <gelmpm/core/collective.h>
#include <gelmpm/geometry/surface_geometry.h>
#include <gelmpm/io/statistics_file.h>
#include <gelmpm/scene/material_regions.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>
#include <deal.II/particles/particle_handler.h>

#include <array>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace GelMPM
{
  /** What an observable is evaluated on. */
  template <int dim>
  struct ObservedState
  {
    /** The current material points. */
    const dealii::Particles::ParticleHandler<dim> &particles;
    /** Their gels (material_state_of()). */
    const MaterialRegions<dim> &material;
    /**
     * The largest violations (u, mu) of the weakly imposed conditions in the converged step,
     * called only by an observable that shows them; empty in the initial state.
     */
    const std::function<std::pair<double, double>()> &dirichlet_errors;
  };


  /**
   * @brief One kind of observable of the "Observables" section (Observables<dim>): some columns
   * of statistics.csv and how they are measured on the material points.
   *
   * Each kind declares its own entries next to its code (a static declare_parameters(), called
   * inside the section) and is made by a static parse(), which checks its entries and returns
   * nothing when the scene does not ask for it: a scene pays only for what it observes. Every
   * value is reduced or gathered over the communicator's ranks, and is the same on all.
   */
  template <int dim>
  class Observable
  {
  public:
    virtual ~Observable() = default;

    /** Its columns of statistics.csv, in their order. */
    virtual std::vector<std::string>
    columns() const = 0;

    /** Its columns' values in @p state into @p statistics. */
    virtual void
    evaluate(const ObservedState<dim> &state, StatisticsFile &statistics) const = 0;

    /** The ranks whose material points make the body (default: this process alone). */
    void
    set_communicator(const MPI_Comm comm)
    {
      communicator = comm;
    }

  protected:
    MPI_Comm communicator = MPI_COMM_SELF;
  };


  /** What the observables of boundary pieces share: finding the pieces, their mean positions. */
  namespace ObservedPieces
  {
    /**
     * The index of the piece @p name among @p pieces (the scene's piece names); InputError
     * naming @p entry if it is not one of them.
     */
    int
    index(const std::string              &name,
          const std::vector<std::string> &pieces,
          const std::string              &entry);

    /**
     * The indices of the two pieces named in @p names (entry @p entry, written like
     * @p example); {-1, -1} if @p names is empty.
     */
    std::array<int, 2>
    pair(const std::vector<std::string> &names,
         const std::vector<std::string> &pieces,
         const std::string              &entry,
         const std::string              &example);

    /**
     * The mean current positions of the surface points of the two pieces @p pair, then their
     * mean initial positions, over the ranks of @p communicator.
     */
    template <int dim>
    std::array<dealii::Point<dim>, 4>
    means(const dealii::Particles::ParticleHandler<dim> &particles,
          const std::array<int, 2>                      &pair,
          const MPI_Comm                                 communicator);

    /** The surface points of some pieces, per piece: what a shape of a piece is measured from. */
    template <int dim>
    struct SurfaceSample
    {
      /** Current positions and N_n A_n of the piece's points. */
      std::vector<std::vector<dealii::Point<dim>>>     positions;
      std::vector<std::vector<dealii::Tensor<1, dim>>> normal_areas;
      /** 2D only: the points as SurfaceGeometry orders them (x, X_0, N_0 A_0, mu). */
      std::vector<std::vector<SurfaceGeometry::SurfacePoint>> points;
    };

    /**
     * The surface points of the pieces numbered @p pieces, gathered from every rank of
     * @p communicator (a piece's shape needs all of it), in the order of @p pieces.
     */
    template <int dim>
    SurfaceSample<dim>
    surface_sample(const dealii::Particles::ParticleHandler<dim> &particles,
                   const std::vector<unsigned int>               &pieces,
                   const MPI_Comm                                 communicator);

    /**
     * The values @p local of every rank of @p communicator, in the order of the ranks (a shape
     * measured from a piece's points needs all of them).
     */
    template <typename T>
    std::vector<T>
    gathered(const MPI_Comm communicator, std::vector<T> local)
    {
      if (!Collective::is_parallel(communicator))
        return local;
      std::vector<T> all;
      for (const auto &part : dealii::Utilities::MPI::all_gather(communicator, local))
        all.insert(all.end(), part.begin(), part.end());
      return all;
    }
  } // namespace ObservedPieces
} // namespace GelMPM

#endif
