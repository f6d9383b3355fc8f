// A Newton system of one unknown for the solver tests: the 1 x 1 pattern, the residual and its
// derivative set by the test's assemble(), the unknown counted as a displacement (|R_u| = |R|).
#ifndef gelmpm_tests_solvers_scalar_system_h
#define gelmpm_tests_solvers_scalar_system_h

#include <gelmpm/core/newton_system.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>

namespace GelMPMTests
{
  class ScalarSystem : public GelMPM::NewtonSystem
  {
  public:
    ScalarSystem()
    {
      dealii::DynamicSparsityPattern pattern(1, 1);
      pattern.add(0, 0);
      matrix_.reinit(pattern);
      residual_.reinit(1);
    }

    unsigned int
    n_u_dofs() const override
    {
      return 1;
    }

  protected:
    /** R = @p residual and, with @p with_matrix, dR/dx = @p derivative. */
    void
    set(const double residual, const double derivative, const bool with_matrix)
    {
      residual_(0) = residual;
      if (with_matrix)
        matrix_.set(0, 0, derivative);
      matrix_.compress(dealii::VectorOperation::insert);
    }
  };
} // namespace GelMPMTests

#endif
