#ifndef gelmpm_scene_boundary_conditions_h
#define gelmpm_scene_boundary_conditions_h

#include <gelmpm/scene/expression.h>

#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/parsed_function.h>
#include <deal.II/base/types.h>

#include <memory>
#include <string>
#include <vector>

namespace GelMPM
{
  /**
   * @brief One named piece of the body's boundary and its conditions: the subsection
   * "Boundary conditions/<name>".
   *
   * A surface point belongs to the piece when the piece's "Selector", an expression in the point's
   * initial position and outward normal (x, y, nx, ny in 2D; x, y, z in 3D), is nonzero. For a
   * body from a mesh file the selector may instead be `boundary id <groups>`: the point belongs to
   * the piece when it lies on a boundary face of one of the listed physical groups of the mesh,
   * each given by its number (the boundary id) or its name in the file's $PhysicalNames.
   *
   * Displacement: `free` (traction "Traction" on the whole boundary), `fixed` (u = ū),
   * `normal` (u·N = ū·N: the paper's roller/symmetry condition; traction on the tangential part),
   * `tangential` (u·T = ū·T with T the in-plane tangent; traction on the normal part). Chemical
   * potential: `flux` (inward solvent volume flux "Flux" = ν i) or `prescribed` (μ = μ̄ from
   * "Chemical potential value", in units of k_BT). Prescribed values are imposed weakly by
   * Nitsche's method (paper eq. (32)).
   *
   * The values are deal.II ParsedFunctions of the point's initial position and of the time t in
   * units of tau_d; ū is the total displacement from the initial configuration.
   */
  template <int dim>
  class BoundaryPiece
  {
  public:
    enum class DisplacementCondition
    {
      free,
      fixed,
      normal,
      tangential
    };
    enum class ChemicalCondition
    {
      flux,
      prescribed
    };

    /** Declare the subsection "<name>" in the current section. */
    static void
    declare_parameters(dealii::ParameterHandler &prm, const std::string &name);

    /** Read it; @p path is "Boundary conditions/<name>" for messages. */
    void
    parse_parameters(dealii::ParameterHandler &prm, const std::string &name);

    /**
     * Whether a surface point at @p x (initial position) with outward @p normal belongs here;
     * @p boundary_id and @p group_name are those of the mesh face the point lies on (invalid and
     * empty for a body that is not a mesh), read only by a `boundary id` selector.
     */
    bool
    selects(const dealii::Point<dim>        &x,
            const dealii::Tensor<1, dim>    &normal,
            const dealii::types::boundary_id boundary_id = dealii::numbers::invalid_boundary_id,
            const std::string               &group_name  = "") const;

    /**
     * The physical groups (numbers or names) of a `boundary id` selector; empty for a selector
     * expression.
     */
    const std::vector<std::string> &
    boundary_groups() const;

    bool
    displacement_prescribed() const;
    bool
    chemical_potential_prescribed() const;

    const dealii::Function<dim> &
    displacement_value() const;
    const dealii::Function<dim> &
    traction() const;
    const dealii::Function<dim> &
    chemical_potential_value() const;
    const dealii::Function<dim> &
    flux() const;

    /** Set the time (in tau_d) of all functions of the piece. */
    void
    set_time(const double t);

    /**
     * Evaluate every function of the piece at @p points (initial positions) and @p times (in
     * tau_d): throw InputError naming the function if a value is not finite, or if a prescribed
     * chemical potential exceeds @p largest_mu, above which the gel has no swollen equilibrium.
     * Leaves the functions at time 0.
     */
    void
    check_values(const std::vector<dealii::Point<dim>> &points,
                 const std::vector<double>             &times,
                 const double                           largest_mu);

    std::string           name;
    DisplacementCondition displacement_condition = DisplacementCondition::free;
    ChemicalCondition     chemical_condition     = ChemicalCondition::flux;

  private:
    std::unique_ptr<PointNormalExpression>                  selector;
    std::vector<std::string>                                boundary_groups_;
    std::unique_ptr<dealii::Functions::ParsedFunction<dim>> displacement_value_;
    std::unique_ptr<dealii::Functions::ParsedFunction<dim>> traction_;
    std::unique_ptr<dealii::Functions::ParsedFunction<dim>> chemical_potential_value_;
    std::unique_ptr<dealii::Functions::ParsedFunction<dim>> flux_;
  };


  /**
   * @brief All boundary pieces of a scene ("Boundary conditions"), in the order of
   * "Boundary conditions/Pieces". A surface point belongs to the first piece that selects it, or
   * to none (then it is traction-free and impermeable).
   */
  template <int dim>
  class BoundaryConditions
  {
  public:
    static void
    declare_parameters(dealii::ParameterHandler &prm, const std::vector<std::string> &pieces);

    void
    parse_parameters(dealii::ParameterHandler &prm, const std::vector<std::string> &pieces);

    unsigned int
    n_pieces() const;
    BoundaryPiece<dim> &
    piece(const unsigned int i);
    const BoundaryPiece<dim> &
    piece(const unsigned int i) const;

    /**
     * Index of the first piece selecting the point, or -1 (@p boundary_id, @p group_name: see
     * BoundaryPiece::selects()).
     */
    int
    piece_of(const dealii::Point<dim>        &x,
             const dealii::Tensor<1, dim>    &normal,
             const dealii::types::boundary_id boundary_id = dealii::numbers::invalid_boundary_id,
             const std::string               &group_name  = "") const;

    /** Set the time (tau_d) of every piece's functions. */
    void
    set_time(const double t);

  private:
    std::vector<std::unique_ptr<BoundaryPiece<dim>>> pieces_;
  };


  /**
   * The indices in @p pieces (the scene's piece names) of the pieces that @p names lists, in
   * its order. Throws InputError naming @p entry for a name that is not a piece and for a
   * piece named twice.
   */
  std::vector<unsigned int>
  piece_indices(const std::vector<std::string> &names,
                const std::vector<std::string> &pieces,
                const std::string              &entry);


  /**
   * InputError naming @p entry unless @p names are usable subsection names: none empty, none
   * with a '/', none twice (@p what: "piece", "region").
   */
  void
  check_section_names(const std::vector<std::string> &names,
                      const std::string              &entry,
                      const std::string              &what);
} // namespace GelMPM

#endif
