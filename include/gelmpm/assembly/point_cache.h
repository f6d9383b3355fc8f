#ifndef gelmpm_assembly_point_cache_h
#define gelmpm_assembly_point_cache_h

#include <gelmpm/assembly/discretisation.h>
#include <gelmpm/material/flory_rehner_gel.h>
#include <gelmpm/particles/material_state.h>
#include <gelmpm/particles/property_layout.h>
#include <gelmpm/scene/boundary_conditions.h>
#include <gelmpm/scene/material_regions.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>
#include <deal.II/lac/vector.h>
#include <deal.II/particles/particle_handler.h>

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <tuple>
#include <vector>

namespace GelMPM
{
  /** The outer product a (x) b. */
  template <int dim>
  inline dealii::Tensor<2, dim>
  outer(const dealii::Tensor<1, dim> &a, const dealii::Tensor<1, dim> &b)
  {
    dealii::Tensor<2, dim> t;
    for (unsigned int i = 0; i < dim; ++i)
      for (unsigned int j = 0; j < dim; ++j)
        t[i][j] = a[i] * b[j];
    return t;
  }


  /**
   * @brief What a material point contributes to the step's system, cached for the step: its
   * kind and piece, its state at t_n, its boundary data and where its shape-function values lie
   * in the PointCache's arrays.
   */
  template <int dim>
  struct PointRecord
  {
    PointKind                  kind;
    int                        piece;
    double                     measure;     // V_n or A_n
    dealii::Tensor<1, dim>     normal;      // unit N_n (surface points)
    dealii::Point<dim>         x;           // the particle's location: x_n less the edge offset
    dealii::Tensor<1, dim>     edge_offset; // PropertyLayout::edge_offset
    dealii::Point<dim>         X0;          // X_0
    dealii::Tensor<1, dim>     u_n;         // x_n - X_0
    dealii::Tensor<1, dim>     du_last;     // x_n - x_{n-1}
    dealii::Tensor<2, dim>     F_p;         // F_n F_0
    unsigned int               region;      // the point's material region and
    const FloryRehnerGel<dim> *gel;         // its gel (material_state_of())
    double                     mobility;    // m_n in the weak form's units
    double                     mu_n;        // mu at the point, last converged step
    double                     dmu_last;    // mu_n - mu_{n-1}
    unsigned int               block;       // index into blocks
    unsigned int               u_offset;    // into u shape arrays
    unsigned int               mu_offset;   // into mu shape arrays
    dealii::Tensor<2, dim>     projector;   // Pi (zero unless u is prescribed)
    dealii::Tensor<1, dim>     u_bar;
    // The adjoint Nitsche term's solvent, (g (x) N) : dP/dmu A, at the start of the step.
    double                 adjoint_solvent_n = 0.;
    dealii::Tensor<1, dim> traction;
    double                 mu_bar = 0.;
    double                 flux   = 0.;
    bool                   assembled; // volume points and surface points of a piece
    // Axisymmetric scenes (doc/axisymmetric.md): r_n = x_n[0] > 0, and the hoop stretch
    // F_p,33 = lambda_0 r_n / R_0 of F_n F_0. Zero in Cartesian scenes.
    double radius = 0.;
    double hoop   = 0.;
    // The refinement level of the leaf the point lies in (0 on a uniform grid): the h of its
    // penalties (DiscreteSpaces::h_u(level)).
    unsigned int level = 0;
    // An impermeable obstacle's seal of the bath condition held over Newton iterations
    // (MixedSystem::freeze_switches()): 1 sealed, 0 open; -1 that of the iterate.
    signed char seal = -1;
    // The rigid obstacles in active contact with the point, held over Newton iterations
    // likewise: bit k for the rigid obstacle k; -1 that of the iterate.
    std::int64_t contact_held = -1;

    /** Whether the point belongs to an axisymmetric scene (its measure includes 2 pi r_n). */
    bool
    axisymmetric() const
    {
      return radius > 0.;
    }
  };


  /**
   * The points of one displacement cell (of one leaf of it on a refined grid: the piece of
   * ExtendedBSplineSpace): one block of assembly.
   */
  struct PointBlock
  {
    unsigned int u_cell, mu_cell;
    unsigned int first, end;
    /** The pieces of u_cell and mu_cell the points lie in (0 on a uniform grid). */
    unsigned int u_piece = 0, mu_piece = 0;
    /** The refinement level of the u leaf (0 on a uniform grid). */
    unsigned int level = 0;
    /**
     * Where faces are separated (PointCache::separate_faces()): the index of the block's own
     * list of u DoFs, in which copies replace some of the cell's functions; -1: the cell's.
     */
    int own_u_dofs = -1;
  };


  template <int dim>
  class FaceSeparation;

  /**
   * @brief A weak copy tied to its face's own functions: the copy's coefficient is pulled
   * towards the Lagrange extrapolation, eq. (54), of the functions of the nearest interior cell
   * of its face (the versions that face uses), by the energy kappa/2 |u_copy - sum_j E_j u_j|^2
   * per component. A face that holds only the tail of a function (its part below a quarter of the
   * function's weight) would otherwise get an unknown of almost no stiffness, which Newton moves
   * arbitrarily far (doc/method.md, "Two faces on one grid"); the tie vanishes for fields that are
   * polynomials of the degree on the face, as the extension of cut cells does.
   */
  struct CopyTie
  {
    /** The copy's u DoF and a cell whose points use it. */
    unsigned int copy, cell;
    /** The donor cell and its functions' DoFs (the face's versions) with their weights E_j. */
    unsigned int                                 donor_cell;
    std::vector<std::pair<unsigned int, double>> donors;
    /** kappa: G times the function's weight sum V_n |N| over h^2 (its stiffness's scale). */
    double stiffness;
  };


  /**
   * @brief The per-step cache of material-point data (doc/architecture.md, "A per-step cache of
   * material-point data"): every point's record grouped by cell into blocks, and the values and
   * gradients of the extended shape functions at every point, in flat arrays.
   *
   * gather() is the sequence of named steps that builds it at the start of a step:
   * classify_cells() (the cells with volume points, and the extended spaces on them),
   * unpack_point(), cell_of_point(), group_points() and evaluate_shape_functions(). Points sit
   * at x_n throughout a step, so nothing here changes over its Newton iterations but the
   * boundary data of the records (MixedSystem::set_boundary_values()).
   *
   * On several ranks each rank caches its own points; the classification and the holder of
   * every active cell are the same on every rank (one all-reduce).
   */
  template <int dim>
  class PointCache
  {
  public:
    using particle_iterator = typename dealii::Particles::ParticleHandler<dim>::particle_iterator;

    PointCache(const MaterialRegions<dim>    &materials,
               const BoundaryConditions<dim> &boundary_conditions,
               DiscreteSpaces<dim>           &spaces,
               const MPI_Comm                 communicator);

    ~PointCache();

    /**
     * Gather the points of @p particle_handler: classify the cells and rebuild the extended
     * spaces, unpack and group the points, evaluate the shape functions. Throws
     * std::runtime_error (on every rank) if a point has left the background grid or a surface
     * point is next to no active cell.
     */
    void
    gather(dealii::Particles::ParticleHandler<dim> &particle_handler);

    /** The records, grouped by block. */
    const std::vector<PointRecord<dim>> &
    points() const
    {
      return points_;
    }

    /** The records, for the boundary data of a step. */
    std::vector<PointRecord<dim>> &
    points()
    {
      return points_;
    }

    /** The ranks over which the points are distributed. */
    MPI_Comm
    get_communicator() const
    {
      return communicator;
    }

    /** The particle of record @p p (to update it at the end of the step). */
    particle_iterator
    particle(const unsigned int p) const
    {
      return particles_[p];
    }

    const std::vector<PointBlock> &
    blocks() const
    {
      return blocks_;
    }

    const double *
    u_values_at(const PointRecord<dim> &r) const
    {
      return &u_values[r.u_offset];
    }

    const dealii::Tensor<1, dim> *
    u_gradients_at(const PointRecord<dim> &r) const
    {
      return &u_gradients[r.u_offset];
    }

    const double *
    mu_values_at(const PointRecord<dim> &r) const
    {
      return &mu_values[r.mu_offset];
    }

    const dealii::Tensor<1, dim> *
    mu_gradients_at(const PointRecord<dim> &r) const
    {
      return &mu_gradients[r.mu_offset];
    }

    /** Which displacement cells hold volume points in this step. */
    const std::vector<bool> &
    classification() const
    {
      return classification_;
    }

    /**
     * Refined grids: which leaf cells of the displacement hierarchy hold volume points in this
     * step (empty on the uniform grid). The unknowns follow them as well as classification().
     */
    const std::vector<bool> &
    leaf_classification() const
    {
      return leaf_classification_;
    }

    /** Whether leaf_classification() differs from the one of the sparsity pattern. */
    bool
    leaf_classification_changed() const
    {
      return leaf_classification_ != pattern_leaf_classification_;
    }

    /** The sparsity pattern now follows leaf_classification(). */
    void
    pattern_follows_leaves()
    {
      pattern_leaf_classification_ = leaf_classification_;
    }

    /** The rank that holds the volume points of each active cell (invalid for the others). */
    const std::vector<unsigned int> &
    cell_holder() const
    {
      return cell_holder_;
    }

    /** Displacement cells that hold volume points in this step. */
    unsigned int
    n_active_cells() const
    {
      return n_active_cells_;
    }

    /**
     * The u DoFs whose extended functions are nonzero at the points of @p block, in the order of
     * the cell's (and of the shape arrays); where faces are separated, with the copies the
     * block's points use in place of some of them.
     */
    const std::vector<unsigned int> &
    u_dofs(const PointBlock &block) const
    {
      return block.own_u_dofs < 0 ? spaces.u().cell_dofs(block.u_cell, block.u_piece)
                                  : own_u_dofs_[block.own_u_dofs];
    }

    /**
     * Separate the faces of the material from the next gather() on ('Contact/Self contact/
     * Separate faces', FaceSeparation, doc/method.md, "Two faces on one grid"); @p pieces flags
     * the boundary pieces whose surface points take part (empty or none: off, the default), and
     * faces closer than @p along_surface along the surface stay together. One MPI rank.
     */
    void
    separate_faces(std::vector<bool> pieces, const double along_surface = 0.);

    /** The ties of this step's weak copies (FaceSeparation::ties()); none without copies. */
    const std::vector<CopyTie> &
    copy_ties() const;

    /** Copies of displacement functions made by separate_faces() this step. */
    unsigned int
    n_function_copies() const
    {
      return spaces.u_copies().size();
    }

    /** Whether the separation of this step differs from the one of the sparsity pattern. */
    bool
    separation_changed() const
    {
      return separation_ != pattern_separation_;
    }

    /** The sparsity pattern now follows the separation. */
    void
    pattern_follows_separation()
    {
      pattern_separation_ = separation_;
    }

    /**
     * The unknowns (u interleaved, then mu), sorted, of every piece of @p u_cell and of the
     * copies its blocks use: those a pair term couples with a cell.
     */
    void
    unknowns_of_cell(const unsigned int                            u_cell,
                     std::vector<dealii::types::global_dof_index> &dofs) const;
    /** The mu DoFs whose extended functions are nonzero at the points of @p block. */
    const std::vector<unsigned int> &
    mu_dofs(const PointBlock &block) const
    {
      return spaces.mu().cell_dofs(block.mu_cell, block.mu_piece);
    }

    /**
     * The block that points in piece @p u_piece of @p u_cell would form (their unknowns through
     * u_dofs() and mu_dofs()), whether or not any point is there now.
     */
    PointBlock
    block_for(const unsigned int u_cell, const unsigned int u_piece) const
    {
      return new_block(u_cell, u_piece, 0);
    }

    /** The unknowns (u interleaved, then mu), sorted, that the points of @p block couple. */
    void
    unknowns_of_block(const PointBlock                             &block,
                      std::vector<dealii::types::global_dof_index> &dofs) const;

    /** The fields at a point for the unknowns of a Newton iterate. */
    struct Fields
    {
      /** The displacement increment du. */
      dealii::Tensor<1, dim> du;
      /** Delta F = I + grad_n du. */
      dealii::Tensor<2, dim> delta_F;
      double                 mu;
    };

    /** du, Delta F and mu at the point @p r for the unknowns @p solution. */
    Fields
    fields_at(const PointRecord<dim> &r, const dealii::Vector<double> &solution) const;

  private:
    /**
     * Classify the cells of the step from the cells that hold volume points and rebuild the
     * extended spaces; throws std::runtime_error if a point has left the background grid.
     */
    void
    classify_cells(const dealii::Particles::ParticleHandler<dim> &particle_handler);

    /** The record of @p particle with the state its properties hold (no cell, no offsets yet). */
    PointRecord<dim>
    unpack_point(const dealii::Particles::ParticleAccessor<dim> &particle) const;

    /**
     * The displacement cell whose block the point @p r joins; throws std::runtime_error for a
     * surface point next to no active cell.
     */
    unsigned int
    cell_of_point(const PointRecord<dim> &r) const;

    /**
     * The displacement cell and its piece (leaf) whose functions the point @p r is evaluated
     * with: cell_of_point() and the leaf that holds the point; on a refined grid a surface point
     * in a leaf without volume points takes the nearest leaf with volume points instead.
     */
    std::pair<unsigned int, unsigned int>
    cell_and_piece_of_point(const PointRecord<dim> &r) const;

    /**
     * The cell and piece of the leaf half a leaf inwards from surface point @p r (in piece
     * @p piece of @p cell) along its normal, if that leaf holds volume points.
     */
    std::optional<std::pair<unsigned int, unsigned int>>
    material_leaf_inwards(const PointRecord<dim> &r,
                          const unsigned int      cell,
                          const unsigned int      piece) const;

    /**
     * The cell and piece of the leaf with volume points nearest to @p r among the pieces of
     * @p cell and its neighbours; @p cell and @p piece if there is none.
     */
    std::pair<unsigned int, unsigned int>
    nearest_material_leaf(const PointRecord<dim> &r,
                          const unsigned int      cell,
                          const unsigned int      piece) const;

    /**
     * Order the records @p unsorted (of the particles @p its) by their @p cells, @p pieces and
     * @p sides (if not empty: 0 the cell's functions, s > 0 the list own_u_dofs_[side_lists_
     * (cell, piece, s)]) into the blocks of assembly, and give each its offsets into the shape
     * arrays (which are sized here).
     */
    void
    group_points(const std::vector<PointRecord<dim>>  &unsorted,
                 const std::vector<particle_iterator> &its,
                 const std::vector<unsigned int>      &cells,
                 const std::vector<unsigned int>      &pieces,
                 const std::vector<unsigned int>      &sides = {});

    /**
     * On the blocks of the first grouping, the copies of the functions that separated faces
     * share (FaceSeparation): sets them in the spaces and returns, per unsorted point, its side
     * (0: no copy; own_u_dofs_ and side_lists_ hold the others' lists).
     */
    std::vector<unsigned int>
    separate_supports();

    /** The block of the points of piece @p u_piece of @p u_cell, from point @p first on. */
    PointBlock
    new_block(const unsigned int u_cell,
              const unsigned int u_piece,
              const unsigned int first) const;

    /** The values and gradients of the extended shape functions at every point. */
    void
    evaluate_shape_functions();

    const MaterialRegions<dim>    &materials;
    const BoundaryConditions<dim> &boundary_conditions;
    DiscreteSpaces<dim>           &spaces;
    const MPI_Comm                 communicator;

    std::vector<PointRecord<dim>>       points_;
    std::vector<particle_iterator>      particles_;
    std::vector<PointBlock>             blocks_;
    std::vector<double>                 u_values, mu_values;
    std::vector<dealii::Tensor<1, dim>> u_gradients, mu_gradients;
    unsigned int                        n_active_cells_ = 0;
    std::vector<bool>                   classification_;
    std::vector<bool>                   leaf_classification_, pattern_leaf_classification_;
    std::vector<unsigned int>           cell_holder_;
    // Separated faces (null: off), the blocks' own lists of u DoFs, the list of each (cell,
    // piece, side), the sorted points' unsorted indices, and the step's separation (the copies and
    // the blocks' lists, flattened) against the sparsity pattern's.
    std::unique_ptr<FaceSeparation<dim>>                                separation;
    std::vector<std::vector<unsigned int>>                              own_u_dofs_;
    std::map<std::tuple<unsigned int, unsigned int, unsigned int>, int> side_lists_;
    std::vector<unsigned int>                                           order_;
    std::vector<unsigned int> separation_, pattern_separation_;
  };
} // namespace GelMPM

#endif
