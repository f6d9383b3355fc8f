#ifndef gelmpm_assembly_self_contact_h
#define gelmpm_assembly_self_contact_h

#include <gelmpm/assembly/point_assembler.h>
#include <gelmpm/assembly/self_contact_settings.h>
#include <gelmpm/geometry/pair_gap.h>

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <algorithm>
#include <array>
#include <vector>

namespace GelMPM
{
  namespace internal
  {
    /** Sort a pair's unknowns and drop repetitions (its cells may share functions). */
    inline void
    sort_unique(std::vector<dealii::types::global_dof_index> &dofs)
    {
      std::sort(dofs.begin(), dofs.end());
      dofs.erase(std::unique(dofs.begin(), dofs.end()), dofs.end());
    }

    /** The place of @p global among the sorted @p dofs. */
    inline unsigned int
    local_index(const std::vector<dealii::types::global_dof_index> &dofs,
                const dealii::types::global_dof_index               global)
    {
      return std::lower_bound(dofs.begin(), dofs.end(), global) - dofs.begin();
    }
  } // namespace internal


  /**
   * Per piece of @p conditions, whether its surface points take part in the self-contact of
   * @p settings ('Pieces', or every piece with a free displacement); throws InputError for a
   * name that is no piece or a piece whose displacement is prescribed.
   */
  template <int dim>
  std::vector<bool>
  self_contact_pieces(const SelfContactSettings     &settings,
                      const BoundaryConditions<dim> &conditions);


  /**
   * @brief Contact of the gel's boundary with itself ('Contact/Self contact'), a pair term: the
   * surface points of the chosen free pieces against the current surface of the same body: point
   * to the tangent plane of the nearest facing surface point (3D, and 2D by default), or in 2D
   * (plane strain and axisymmetric, 'Other face = segments') point to segment; frictionless, by
   * a penalty or by Nitsche's method.
   *
   * Segments: at every MixedSystem::setup() (add_cell_couplings(), the points at x_n) the chosen
   * points are ordered into polylines along the surface (SurfaceGeometry::order_along_surface()
   * on their initial positions and normals, as the observables order them), and each point is
   * paired with the segments that, at x_n, lie within 'Search distance' in front of it or up to
   * 'Largest depth' behind, face it (its normal against theirs) and whose ends lie farther than
   * 'Minimum arc length' from it along the surface (points of different curves always). The pairs
   * are fixed over the step; they couple the point's cell with the cells of the segment's two ends,
   * which may be no neighbours, so the term declares those pairs of cells (the sparsity pattern
   * holds them and is kept while they stay).
   *
   * For each Newton iterate (assemble_beyond_blocks()) a point is active against its pair whose
   * segment it lies behind, g < 0 with its projection on the segment (0 <= xi <= 1), the deepest
   * one if several: the active set of the iterate, as for the obstacles. Its energy is
   * W = A_s beta_s g^2 / 2 (beta_s = gamma_s G / h_u), R_u[w] = dW/dx . w at the three points and
   * K its exact second derivative (the segment's turning included), symmetric. Each contact is
   * seen from both sides (the points of each face against the segments of the other).
   *
   * By Nitsche's method ('Method = nitsche') a point is active where
   * beta_s g - sigma_n < 0, sigma_n = n . t its own normal traction t = P_n N_n against the
   * segment's normal n, and adds, weighted by one half (each contact is seen from both faces),
   * R = A_s [(beta_s g - sigma_n) dg - theta g dsigma_n] with theta the Nitsche variant's
   * symmetry: for theta = 1 the first derivative of A_s (beta_s g^2 / 2 - g sigma_n), and K its
   * exact derivative (nitsche_pair()).
   *
   * Its per-point assemble() adds nothing: what it adds goes beyond the blocks. Not in a scene's
   * list when the subsection is off.
   *
   * Tangent planes (3D, and 2D with 'Other face = tangent planes', find_point_pairs()): a
   * point's pairs are the surface points within 'Search distance'
   * whose normals are turned from its own by more than 120 degrees and whose tangent planes (at
   * x_n, with the unit normal N_n, fixed over the step) it lies in front of or at most 'Largest
   * depth' behind; it is active against the nearest of them (along the tangent plane, within the
   * spacing of that point) whose plane it lies behind, g = (x_s - x_a) . N_a < 0
   * (point_plane_gap()).
   *
   * On several MPI ranks the chosen surface points of every rank are gathered at each setup
   * (Sample: what a pair needs of a point, its unknowns and shape values included), in the order
   * of their particle ids, so that every rank finds the same pairs, active sets and statistics
   * from the whole Newton vector it holds; a pair is assembled (and its cells coupled) by the rank
   * that holds its point. The faces' copies of functions ('Separate faces') are found on one rank
   * only: Scene refuses them on several.
   */
  template <int dim>
  class SelfContactAssembler final : public SurfaceTermAssembler<dim>
  {
  public:
    using SurfaceTermAssembler<dim>::SurfaceTermAssembler;

    /** Use @p settings ('Contact/Self contact'); the chosen pieces are resolved here. */
    void
    set_settings(const SelfContactSettings &settings);

    void
    assemble(const PointRecord<dim> &,
             const double,
             const bool,
             AssemblyScratch<dim> &,
             AssemblyCopy &) const override
    {}

    /** The step's pairs (found here) and the pairs of cells they couple. */
    void
    add_cell_couplings(const PointCache<dim>                              &cache,
                       std::vector<std::pair<unsigned int, unsigned int>> &pairs) const override;

    /** One local system per active point, on the unknowns of its cell and its segment's. */
    void
    assemble_beyond_blocks(const PointCache<dim>        &cache,
                           const dealii::Vector<double> &solution,
                           const double                  dt,
                           const bool                    with_matrix,
                           std::vector<AssemblyCopy>    &copies) const override;

    /** What statistics.csv reports of the self-contact of an iterate. */
    struct State
    {
      /** Points in active contact (each face's points count). */
      unsigned int points = 0;
      /** The sum of the pairs' normal forces, sum A_s beta_s |g| (the force on each face);
       * under Nitsche's method sum A_s (sigma_n - beta_s g) / 2. */
      double force = 0.;
      /** Half the sum of the active points' A_s: the area (2D: length) in contact, both faces
       * being seen. */
      double area = 0.;
      /** The largest penetration -g of an active point (0 if none; Nitsche's active points
       * may lie in front of the segment, g > 0). */
      double penetration = 0.;
      /** The initial position of that point (which pore or piece touches). */
      dealii::Point<dim> deepest_X0;
    };

    /** The self-contact of @p solution with the step's pairs (@p cache of the last setup). */
    State
    state(const PointCache<dim> &cache, const dealii::Vector<double> &solution) const;

    /**
     * Hold each point's active pair (or none) at its value at @p solution (with @p hold false
     * only compare): the switches of semi-smooth Newton, which can otherwise cycle where a point
     * slides off the end of its segment (MixedSystem::freeze_switches()). How many changed
     * against those held.
     */
    unsigned int
    hold_active_pairs(const PointCache<dim>        &cache,
                      const dealii::Vector<double> &solution,
                      const bool                    hold) const;

    /** Let the active pairs follow the iterate again. */
    void
    release_active_pairs() const
    {
      held_.clear();
    }

    /**
     * The surface points that lie behind the surface at @p solution (the end of the step,
     * searched anew) without an active pair among the step's: they passed through a face the
     * step's pairs did not see. A step that leaves some is retaken shorter
     * (MaterialPointModel::refusal()).
     */
    unsigned int
    unseen_contacts(const PointCache<dim> &cache, const dealii::Vector<double> &solution) const;

    /** The number of pairs of the step. */
    unsigned int
    n_pairs() const;

  private:
    /** What the pairs need of a surface point of the chosen pieces at the step's setup. */
    struct Sample
    {
      /** The particle's id: the order of the samples on every partition. */
      double id = 0.;
      /** X_0 and N_0 A_0 (the polylines' order), x_n (with the edge offset), unit N_n. */
      dealii::Point<dim>     X0, x;
      dealii::Tensor<1, dim> normal_area_0, normal;
      /** A_n, beta_s and the spacing of the surface points there (spacing()). */
      double measure = 0., penalty = 0., spacing = 0.;
      /** The u cell of its block, its u functions (DoF indices) and their values there. */
      unsigned int              u_cell = 0;
      std::vector<unsigned int> dofs;
      std::vector<double>       N;
      /** Whether this rank holds the point (and assembles its pairs). */
      bool here = true;
      /** Its index in PointCache::points() on the rank that holds it. */
      unsigned int record = 0;
    };

    /** A point and a segment (the samples of its ends, in the polyline's order); 3D: a point
     * and the point whose tangent plane it touches (b = a). */
    struct Pair
    {
      unsigned int point, a, b;
    };

    /** The samples of the chosen points of @p cache, of every rank. */
    std::vector<Sample>
    gather_samples(const PointCache<dim> &cache) const;

    /** The ties of the weak copies (CopyTie), at @p solution. */
    void
    assemble_copy_ties(const PointCache<dim>        &cache,
                       const dealii::Vector<double> &solution,
                       const bool                    with_matrix,
                       std::vector<AssemblyCopy>    &copies) const;

    /**
     * The pairs of the samples at x_n, or (with @p solution) at the end of the step, where a
     * point counts however far behind the surface it lies.
     */
    std::vector<Pair>
    find_pairs(const dealii::Vector<double> *solution = nullptr) const;

    /**
     * 2D with 'Other face = segments', find_pairs(): each point with the segments of the surface
     * polylines as the class describes.
     */
    std::vector<Pair>
    find_segment_pairs(const dealii::Vector<double> *solution) const;

    /**
     * 3D, or 2D with 'Other face = tangent planes', find_pairs(): each point with the points within
     * 'Search distance' whose tangent planes face it and that it lies in front of or at most
     * 'Largest depth' behind; not those of its own face closer than 'Minimum arc length' in the
     * initial configuration.
     */
    std::vector<Pair>
    find_point_pairs(const dealii::Vector<double> *solution) const;

    /** Whether the other face is the tangent planes of its points (3D, or 'Other face'). */
    bool
    tangent_planes() const;

    /** The spacing of the surface points at @p r: A_n^(1/(dim-1)), in an axisymmetric scene of
     * the meridian's A_n / (2 pi r_n). */
    double
    spacing(const PointRecord<dim> &r) const;

    /** The gap of @p pair at @p solution (at x_n without it). */
    PairGap<dim>
    pair_gap(const Pair &pair, const dealii::Vector<double> *solution) const;

    /**
     * Whether the point of @p pair projects onto its surface (with the gap @p gap): 2D onto the
     * segment (to 1e-9 of its length), 3D (and 2D with tangent planes) within the spacing of
     * the paired point.
     */
    bool
    projects_onto(const Pair &pair, const PairGap<dim> &gap) const;

    /** The current position x_n + du of sample @p p for @p solution. */
    dealii::Point<dim>
    current_position(const unsigned int p, const dealii::Vector<double> &solution) const;

    /**
     * Per pair, its gap at @p solution; the indices of the active pairs, one per point. With
     * @p tractions (Nitsche's method) the active set is Nitsche's, beta_s g - sigma_n < 0, else
     * the penalty's, g < 0 (also "behind the surface" for unseen_contacts()).
     */
    std::vector<int>
    active_pairs(const dealii::Vector<double>              &solution,
                 std::vector<PairGap<dim>>                 &gaps,
                 const bool                                 use_held  = true,
                 const std::vector<dealii::Tensor<1, dim>> &tractions = {}) const;

    /**
     * Under Nitsche's method, per sample, the traction t = P_n N_n at @p solution of the points
     * with pairs that this rank holds (zero elsewhere); empty under the penalty.
     */
    std::vector<dealii::Tensor<1, dim>>
    tractions(const PointCache<dim> &cache, const dealii::Vector<double> &solution) const;

    /** The penalty's local system of the active pair @p pair with the gap @p gap. */
    AssemblyCopy
    penalty_pair(const Pair &pair, const PairGap<dim> &gap, const bool with_matrix) const;

    /**
     * Nitsche's local system of the active pair @p pair with the gap @p gap at @p solution: on
     * the displacement and chemical-potential unknowns of the point's block and the
     * displacement unknowns of the segment's ends.
     */
    AssemblyCopy
    nitsche_pair(const PointCache<dim>        &cache,
                 const dealii::Vector<double> &solution,
                 const Pair                   &pair,
                 const PairGap<dim>           &gap,
                 const bool                    with_matrix) const;

    /** beta_s at the point @p r. */
    double
    penalty(const PointRecord<dim> &r) const;

    SelfContactSettings settings;
    /** Per piece, whether its points take part. */
    std::vector<bool> chosen;
    /** The chosen surface points of every rank at the step's setup, by id. */
    mutable std::vector<Sample> samples_;
    /** The pairs of the step, sorted by point (found at setup, where the couplings are asked:
     * they are the couplings). */
    mutable std::vector<Pair> pairs_;
    /** Per point with pairs (in their order), the active pair held, -1 none; empty: not held. */
    mutable std::vector<int> held_;
  };
} // namespace GelMPM

#endif
