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

    /** The coefficients of @p solution on @p block's cells (du, mu, n_u, n_mu). */
    void
    gather_block_coefficients(const PointBlock             &block,
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
   * @brief One term of the weak form at one material point (after Lethe's assemblers, one class
   * per term): adds the term's residual and, with @p with_matrix, its tangent to the block's
   * local system in @p copy, from the fields in @p scratch (evaluated at @p point).
   *
   * MixedSystem calls VolumeTermAssembler at the volume points and its list of surface terms,
   * in a fixed order, at the surface points of a piece: traction, displacement Nitsche, plane
   * contact, chemical-potential Nitsche, solvent flux. Each decides itself whether it applies
   * at a point (from its piece). The order is that of the sums: a new term goes to the end of
   * the list, so that the results of the others stay bit for bit.
   */
  template <int dim>
  class PointAssembler
  {
  public:
    virtual ~PointAssembler() = default;

    virtual void
    assemble(const PointRecord<dim> &point,
             const double            dt,
             const bool              with_matrix,
             AssemblyScratch<dim>   &scratch,
             AssemblyCopy           &copy) const = 0;
  };


  /**
   * @brief A term at the surface points of a boundary piece: what such terms read besides the
   * point and its fields, the piece's conditions, the Nitsche settings and the spaces (the grid
   * spacings h_u and h_mu of the penalties).
   */
  template <int dim>
  class SurfaceTermAssembler : public PointAssembler<dim>
  {
  public:
    SurfaceTermAssembler(const BoundaryConditions<dim> &boundary_conditions,
                         const NitscheSettings         &nitsche,
                         const DiscreteSpaces<dim>     &spaces)
      : boundary_conditions(boundary_conditions)
      , nitsche(nitsche)
      , spaces(spaces)
    {}

    /**
     * Whether the terms that call add_displacement_nitsche() (the prescribed displacements and
     * Nitsche contact) take its tangent's third-derivative term by a central difference
     * (@p reference true: add_displacement_nitsche_reference(), the former assembly, kept as the
     * reference) instead of in closed form (the default). The environment variable
     * GELMPM_REFERENCE_NITSCHE_TANGENT (any value) sets it at construction, to time both with
     * one binary (doc/performance.md, "Assembly at its flop limit").
     */
    void
    set_reference_nitsche_tangent(const bool reference)
    {
      reference_nitsche_tangent = reference;
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
    bool reference_nitsche_tangent = std::getenv("GELMPM_REFERENCE_NITSCHE_TANGENT") != nullptr;
  };
} // namespace GelMPM

#endif
