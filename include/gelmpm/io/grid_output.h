#ifndef gelmpm_io_grid_output_h
#define gelmpm_io_grid_output_h

#include <gelmpm/bspline/bspline_space.h>
#include <gelmpm/bspline/extended_bspline_space.h>
#include <gelmpm/io/pvd_series.h>

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/vector.h>
#include <deal.II/particles/particle_handler.h>

#include <string>
#include <vector>

namespace GelMPM
{
  /**
   * @brief Writes the background grid for ParaView (`Output/Write grid`): one `grid-NNNNN.vtu`
   * per output time and the series `grid.pvd` with the simulated times (a PvdSeries), through
   * deal.II's DataOut.
   *
   * What is written is the grid of the last converged step, as the solver saw it (the grid is
   * reset every step, paper §3.2): its cell classification, made from where the volume points
   * were at the start of that step, and the fields solved for on it. Fields:
   *
   * - per cell: `u_cell_kind` and `mu_cell_kind`, the CellKind (0 interior, 1 boundary, 2 outer;
   *   paper §3.5) of the cell in the displacement space and of the chemical-potential cell that
   *   covers it (with subdivision one mu cell covers 2^dim cells); `n_volume_points`, the volume
   *   points the cell held; on a locally refined grid also `refinement_level`, the finest level
   *   of the cell's leaf cells (0: not refined; the leaves themselves are not drawn);
   * - per vertex of each cell: `displacement_increment` (vector), the increment du of the step,
   *   and `mu_over_kT`, both evaluated from the extended B-spline fields (eq. (53)) of the cell.
   *   Outer cells (no material) have NaN at their vertices; ParaView shows NaN in its own colour
   *   and *Threshold* on `u_cell_kind` < 2 keeps the cells with material. Vertex values are
   *   written per cell (a discontinuous Q1 field); the B-spline fields are continuous, so the
   *   cells sharing a vertex agree.
   *
   * The .vtu files store single precision.
   */
  template <int dim>
  class GridOutput
  {
  public:
    /**
     * @param triangulation The background grid, whose active cell index equals the cell index of
     *   the displacement BSplineSpace (GridGenerator::subdivided_hyper_rectangle with the same
     *   box and cell counts). It must outlive this object.
     * @param basename The files are `<basename>-NNNNN.vtu` and `<basename>.pvd` ("mode" for the
     *   critical mode of the stability analysis, whose `displacement_increment` is the mode).
     */
    GridOutput(const std::string                &directory,
               const dealii::Triangulation<dim> &triangulation,
               const std::string                &basename = "grid");

    /** The number of volume points in each cell of @p space, from the points' current positions. */
    static std::vector<unsigned int>
    count_volume_points(const dealii::Particles::ParticleHandler<dim> &particles,
                        const BSplineSpace<dim>                       &space);

    /**
     * Take the grid state of a converged step (or of the initial state) for the next write():
     * the classification of @p u and @p mu, the @p volume_points per displacement cell that the
     * classification was made from, and the fields of @p solution, which holds the increment du
     * then mu in the layout of DiscreteSpaces (index dim*i + c for component c of u DoF i,
     * n_u + j for mu DoF j, n_u = solution.size() - mu.n_dofs(): copies of u functions may
     * follow u's own, DiscreteSpaces::set_u_copies(); the grid shows u's own functions).
     */
    void
    record(const ExtendedBSplineSpace<dim> &u,
           const ExtendedBSplineSpace<dim> &mu,
           const std::vector<unsigned int> &volume_points,
           const dealii::Vector<double>    &solution);

    /** Write the state last recorded at @p time (in tau_d) and update grid.pvd. */
    void
    write(const double time);

    /** (time, file name) of every output so far. */
    const std::vector<std::pair<double, std::string>> &
    times_and_names() const;

    /**
     * The series and the state last recorded (the next write() writes it), for a checkpoint
     * (boost serialization).
     */
    template <class Archive>
    void
    serialize(Archive &ar, const unsigned int)
    {
      ar &series &recorded &u_cell_kind &mu_cell_kind &n_volume_points &vertex_values;
    }

    /** After a checkpoint was read: PvdSeries::restore_files(). */
    void
    restore_files() const
    {
      series.restore_files();
    }

  private:
    /** Values of du (components 0..dim-1) and mu (component dim) at the vertices of @p cell. */
    void
    evaluate_vertices(const typename dealii::DoFHandler<dim>::active_cell_iterator &cell,
                      const ExtendedBSplineSpace<dim>                              &u,
                      const ExtendedBSplineSpace<dim>                              &mu,
                      const dealii::Vector<double>                                 &solution);

    dealii::FESystem<dim>   fe;
    dealii::DoFHandler<dim> dof_handler;
    PvdSeries               series;
    bool                    recorded = false;

    dealii::Vector<double> u_cell_kind;
    dealii::Vector<double> mu_cell_kind;
    dealii::Vector<double> n_volume_points;
    /** Refined grids only (not kept in checkpoints, which refined grids do not write). */
    dealii::Vector<double> refinement_level;
    dealii::Vector<double> vertex_values; // du and mu, FE_DGQ(1)^(dim+1) on dof_handler
  };
} // namespace GelMPM

#endif
