#ifndef gelmpm_assembly_point_assembler_h
#define gelmpm_assembly_point_assembler_h

#include <gelmpm/assembly/discretisation.h>
#include <gelmpm/assembly/nitsche_settings.h>
#include <gelmpm/assembly/point_cache.h>
#include <gelmpm/scene/boundary_conditions.h>

#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <cstdlib>
#include <string>
#include <utility>
#include <vector>

namespace GelMPM
{
  /**
   * @brief The work space of one block of assembly (step-44's scratch data): the block's
   * coefficients of the Newton iterate and the fields at the point being assembled, which every
   * term of the weak form reads.
   *
   * Local numbering of a block: the dim * n_u displacement unknowns (component fastest), then
   * the n_mu chemical-potential unknowns (from mu0() on).
   */
  template <int dim>
  struct AssemblyScratch
  {
    // Local coefficients of the cell and the point state.
    std::vector<dealii::Tensor<1, dim>> du;
    std::vector<double>                 mu;
    const double                       *N   = nullptr;
    const dealii::Tensor<1, dim>       *G   = nullptr;
    const double                       *M   = nullptr;
    const dealii::Tensor<1, dim>       *GM  = nullptr;
    unsigned int                        n_u = 0, n_mu = 0;
    dealii::Tensor<2, dim>              delta_F;
    dealii::Tensor<1, dim>              du_at_point;
    double                              mu_at_point = 0.;
    dealii::Tensor<1, dim>              grad_mu;
    // Work arrays for the tangent.
    std::vector<dealii::Tensor<3, dim>> A_dot_G;      // [c][i][J][k] = sum_L A_iJkL G_c[L]
    std::vector<double>                 h;            // [dim c + i] = (dF^{-T} G_c)_i
    std::vector<double>                 SG;           // [dim c + J] = V (S G_c)_J
    std::vector<double>                 s_row;        // [c] = G_a . V S G_c, one a at a time
    dealii::FullMatrix<double>          volume_lower; // the volume points' sum, lower triangle
    /**
     * The volume points' tangent factors of one block, gathered point by point and contracted
     * once per block by BLAS (VolumeTermAssembler::add_block_tangent()). Column-major; the arrays
     * indexed by point have the leading dimension capacity, those indexed by function n_u or n_mu.
     */
    struct VolumeTangentBatch
    {
      unsigned int n_points = 0, capacity = 0;
      // [p + capacity (n_u i + a)] = h_p,a[i], and times V a_p, V b_p.
      std::vector<double> h, ah, bh;
      // [a + n_u (dim p + J)] = G_p,a[J] and V (S_p G_p,a)_J.
      std::vector<double> G, SG;
      // [p + capacity b] = -V (k_BT/nu) Delta J M_p,b.
      std::vector<double> qM;
      // [b + n_mu (dim p + J)] = GM_p,b[J] and -V dt m GM_p,b[J].
      std::vector<double> GM, wGM;
      // The products: Vb h h, Va h h, s, K_u,mu, K_mu,mu.
      std::vector<double> hbh, hah, s, mu_u, mu_mu;
    } batch;
    // The displacement Nitsche tangent's vectors per function (add_displacement_nitsche()).
    std::vector<double> nitsche_work;
    /**
     * The displacement Nitsche tangents of one block's surface points as factors, contracted
     * once per block by BLAS (add_displacement_nitsche_block()). Each point adds columns of
     * length dim n_u (index dim a + k) to Y and their combinations C_p Y to Z: the entries of
     * the kind x_(a,k) y_(c,m) to the straight pair, those of the kind x_(a,m) y_(c,k) to the
     * crossed pair.
     */
    struct NitscheTangentBatch
    {
      bool                open       = false;
      bool                symmetric  = true; // every point's tangent symmetric (symmetric variant)
      unsigned int        n_straight = 0, n_crossed = 0; // columns
      std::vector<double> Y, Z, Yx, Zx;
      std::vector<double> straight, crossed; // the products, dim n_u x dim n_u
    } nitsche_batch;
    // Axisymmetric points: A : B(c, k) per test function (axisymmetric_terms.cc), kept here so
    // that no point allocates.
    std::vector<dealii::Tensor<2, 3>> hoop_products;

    /** The first chemical-potential row of the block. */
    unsigned int
    mu0() const
    {
      return dim * n_u;
    }

    /** The coefficients of @p solution on @p block's unknowns (du, mu, n_u, n_mu). */
    void
    gather_block_coefficients(const PointBlock             &block,
                              const PointCache<dim>        &cache,
                              const DiscreteSpaces<dim>    &spaces,
                              const dealii::Vector<double> &solution);

    /**
     * The point's shape functions (from @p cache) and the fields at it (du, Delta F = I +
     * grad_n du, mu, grad_n mu) from the block's coefficients.
     */
    void
    evaluate_point_fields(const PointRecord<dim> &point, const PointCache<dim> &cache);
  };


  /**
   * @brief What a block of assembly adds to the global system (step-44's copy data): its local
   * residual and tangent on its unknowns, or the message of a non-physical state.
   */
  struct AssemblyCopy
  {
    dealii::FullMatrix<double>                   matrix;
    dealii::Vector<double>                       residual;
    std::vector<dealii::types::global_dof_index> dofs;
    bool                                         failed = false;
    std::string                                  failure;
  };


  /**
   * @brief How the terms form their tangents: in closed form from the structure of A_n and, in
   * 3D, gathered and contracted once per block (the defaults), or the former assemblies, kept as
   * the references the defaults are tested against (doc/performance.md, "Assembly at its flop
   * limit"). Each environment variable (any value) sets its option at construction, to time both
   * with one binary. MixedSystem holds one, its terms read it.
   */
  struct TangentOptions
  {
    /** Contract the volume points' tangent with the entries of A_n
     * (GELMPM_GENERIC_VOLUME_TANGENT). */
    bool generic_volume = std::getenv("GELMPM_GENERIC_VOLUME_TANGENT") != nullptr;
    /** Sum the volume points' tangent point by point (GELMPM_POINTWISE_VOLUME_TANGENT). */
    bool pointwise_volume = std::getenv("GELMPM_POINTWISE_VOLUME_TANGENT") != nullptr;
    /** Take the displacement Nitsche tangent's third-derivative term by a central difference of
     * A_n (add_displacement_nitsche_reference(); GELMPM_REFERENCE_NITSCHE_TANGENT). */
    bool reference_nitsche = std::getenv("GELMPM_REFERENCE_NITSCHE_TANGENT") != nullptr;

    /**
     * Whether the tangents of a block's volume points and of its displacement Nitsche terms are
     * gathered and contracted once per block by BLAS (VolumeTermAssembler::add_block_tangent(),
     * add_displacement_nitsche_block()): in 3D, unless a volume option asks for the former sum.
     */
    template <int dim>
    bool
    batched() const
    {
      return dim == 3 && !generic_volume && !pointwise_volume;
    }
  };


  /**
   * @brief One term of the weak form (after Lethe's assemblers, one class per term): at each
   * material point it applies to, adds the term's residual and, with @p with_matrix, its tangent
   * to the block's local system in @p copy, from the fields in @p scratch (evaluated at the
   * point).
   *
   * MixedSystem holds the scene's terms as one list (assemblers(), built once per scene with
   * the terms the scene needs) and, for each block of assembly (one background cell and its
   * points): calls start_block() of every term, assemble() of the volume terms at each volume
   * point and of the surface terms at each surface point of a piece, then finish_block() of
   * every term, all in the list's order. That order is the order of the floating-point sums: a
   * new term goes to the end of the list, so that the results of the others stay bit for bit.
   * A surface term decides itself from the point's piece whether it applies there.
   *
   * A term that couples the unknowns of two cells that are not neighbours (a pair term: a
   * surface point against the surface of another part of the body) declares the pairs of cells
   * in add_cell_couplings(); the sparsity pattern then holds the entries between their unknowns,
   * which it writes in assemble_beyond_blocks().
   */
  template <int dim>
  class PointAssembler
  {
  public:
    virtual ~PointAssembler() = default;

    /** Whether the term is assembled at the volume points (else at the surface points of a
     * piece). */
    virtual bool
    at_volume_points() const = 0;

    /**
     * Before the points of a block (the block's coefficients are in @p scratch), of at most
     * @p n_points points: prepare what the term gathers over the block. Nothing by default.
     */
    virtual void
    start_block(AssemblyScratch<dim> & /*scratch*/,
                const unsigned int /*n_points*/,
                const bool /*with_matrix*/) const
    {}

    virtual void
    assemble(const PointRecord<dim> &point,
             const double            dt,
             const bool              with_matrix,
             AssemblyScratch<dim>   &scratch,
             AssemblyCopy           &copy) const = 0;

    /**
     * After the points of a block: add what the term gathered over them to @p copy. Nothing by
     * default.
     */
    virtual void
    finish_block(AssemblyScratch<dim> & /*scratch*/,
                 AssemblyCopy & /*copy*/,
                 const bool /*with_matrix*/) const
    {}

    /**
     * The couplings beyond the blocks: append to @p pairs each pair (a, b) of background cells
     * (PointBlock::u_cell of two blocks of @p cache, cells with volume points) whose unknowns
     * this term couples although no block holds both, so that the sparsity pattern holds the
     * entries between all unknowns of a and all of b, both ways. Every unknown of a block
     * already couples with every other one of it, so a term that adds only to its point's
     * block declares nothing (the default).
     *
     * Asked at every MixedSystem::setup() (once per step, after the cache is gathered from the
     * points at x_n), on each rank for the pairs its own points make: the pattern is built anew
     * when the pairs of all terms (sorted, without repetitions) differ from those it was built
     * for, so that a pair term whose pairs do not change over steps keeps the linear solver's
     * analysis. The term writes the entries of a pair itself, in assemble_beyond_blocks(); a
     * block's AssemblyCopy holds the unknowns of its own cell only.
     */
    virtual void
    add_cell_couplings(const PointCache<dim> & /*cache*/,
                       std::vector<std::pair<unsigned int, unsigned int>> & /*pairs*/) const
    {}

    /**
     * The entries of a pair term (those between the cells of add_cell_couplings()): append to
     * @p copies local systems, each on the unknowns it lists in AssemblyCopy::dofs (sorted, no
     * repetitions), for the Newton iterate @p solution of the points of @p cache. MixedSystem
     * adds them after the blocks, in the order of the terms and of @p copies, so the sums stay
     * deterministic. Nothing by default.
     */
    virtual void
    assemble_beyond_blocks(const PointCache<dim> & /*cache*/,
                           const dealii::Vector<double> & /*solution*/,
                           const double /*dt*/,
                           const bool /*with_matrix*/,
                           std::vector<AssemblyCopy> & /*copies*/) const
    {}
  };


  /**
   * @brief A term at the surface points of a boundary piece: what such terms read besides the
   * point and its fields, the piece's conditions, the Nitsche settings, the spaces (the grid
   * spacings h_u and h_mu of the penalties) and how tangents are formed.
   */
  template <int dim>
  class SurfaceTermAssembler : public PointAssembler<dim>
  {
  public:
    SurfaceTermAssembler(const BoundaryConditions<dim> &boundary_conditions,
                         const NitscheSettings         &nitsche,
                         const DiscreteSpaces<dim>     &spaces,
                         const TangentOptions          &tangent)
      : boundary_conditions(boundary_conditions)
      , nitsche(nitsche)
      , spaces(spaces)
      , tangent(tangent)
    {}

    bool
    at_volume_points() const override
    {
      return false;
    }

  protected:
    /** The piece of the surface point @p point. */
    const BoundaryPiece<dim> &
    piece(const PointRecord<dim> &point) const
    {
      return boundary_conditions.piece(point.piece);
    }

    const BoundaryConditions<dim> &boundary_conditions;
    const NitscheSettings         &nitsche;
    const DiscreteSpaces<dim>     &spaces;
    /** The terms that call add_displacement_nitsche() (the prescribed displacements and
     * Nitsche contact) read TangentOptions::reference_nitsche and batched(). */
    const TangentOptions &tangent;
  };
} // namespace GelMPM

#endif
