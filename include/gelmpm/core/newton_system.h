#ifndef gelmpm_core_newton_system_h
#define gelmpm_core_newton_system_h

#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/vector.h>

namespace GelMPM
{
  /**
   * @brief What Newton's method needs of one discretised time step of the mixed u–mu problem:
   * the interface that solve_newton() and TimeLoop drive.
   *
   * The unknowns are ordered displacement block first (n_u_dofs() of them), then chemical
   * potential; the residual norms are those of the two blocks, which the Newton convergence
   * test scales separately (NewtonSettings). The material point system (MixedSystem) and the
   * body-fitted peer (FemMixedSystem) implement it, so that one Newton and one time loop serve
   * both, and comparisons between them measure the discretisations alone.
   *
   * It lives in `core` because the systems (assembly, fem) and the solvers that drive them depend
   * on core, not on each other.
   */
  class NewtonSystem
  {
  public:
    virtual ~NewtonSystem() = default;

    /**
     * Assemble the residual (and, if @p with_matrix, the tangent) at the unknowns @p solution
     * for the physical time step @p dt. Throws NonPhysicalState when the state leaves the
     * physical range; without the matrix it assembles the residual alone.
     */
    virtual void
    assemble(const dealii::Vector<double> &solution, const double dt, const bool with_matrix) = 0;

    /** The number of displacement unknowns, which come first. */
    virtual unsigned int
    n_u_dofs() const = 0;

    /**
     * Hold the switches of the residual that jump with the unknowns (an impermeable obstacle
     * that seals the bath condition where it touches) at their values at the state @p solution
     * until release_switches(), so that the residual is continuous in the unknowns meanwhile.
     * Returns how many differ from the values the last assembly used (the iterate's own switches
     * before the first freeze: none then); with @p hold false it only counts them and keeps the
     * switches as they are. Semi-smooth Newton can cycle across such a jump (a
     * point at a contact edge sealed at one iterate and open at the next); with the switches
     * held it converges, and solve_newton() freezes them again at the converged state until
     * none changes. The default: a system without such switches.
     */
    virtual unsigned int
    freeze_switches(const dealii::Vector<double> &solution, const bool hold = true)
    {
      (void)solution;
      (void)hold;
      return 0;
    }

    /** Let the switches follow the iterate again (after freeze_switches()). */
    virtual void
    release_switches()
    {}

    /** The tangent assembled last. */
    const dealii::TrilinosWrappers::SparseMatrix &
    matrix() const
    {
      return matrix_;
    }

    /** The residual assembled last. */
    const dealii::Vector<double> &
    residual() const
    {
      return residual_;
    }

    /** Euclidean norm of the displacement block of the residual. */
    double
    residual_norm_u() const;

    /** Euclidean norm of the chemical-potential block of the residual. */
    double
    residual_norm_mu() const;

  protected:
    dealii::TrilinosWrappers::SparseMatrix matrix_;
    dealii::Vector<double>                 residual_;
  };
} // namespace GelMPM

#endif
