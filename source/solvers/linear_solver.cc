#include <gelmpm/core/available_memory.h>
#include <gelmpm/core/collective.h>
#include <gelmpm/core/input_error.h>
#include <gelmpm/solvers/linear_solver.h>
#include <gelmpm/stability/matrix_entries.h>

#include <deal.II/base/mpi.h>

#include <Amesos.h>
#include <Epetra_CrsMatrix.h>
#include <Epetra_MpiComm.h>
#include <Epetra_Vector.h>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace GelMPM
{
  LinearSolver::LinearSolver() = default;


  LinearSolver::~LinearSolver() = default;


  void
  LinearSolver::declare_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Linear solver");
    prm.declare_entry("Solver",
                      "automatic",
                      dealii::Patterns::Selection("automatic|KLU|MUMPS|Krylov"),
                      "Solver for the Newton system: automatic (the default: MUMPS where MUMPS's "
                      "own estimate of its factorisation, from an analysis of the first tangent, "
                      "fits in 'Automatic memory share' of the memory available; MUMPS in "
                      "single precision (see 'Precision') where only half of it fits and the "
                      "tangent is symmetric; Krylov "
                      "otherwise, also on several MPI ranks. MUMPS was the faster at every size "
                      "measured, Krylov the smaller in 3D: doc/performance.md, 'Iterative "
                      "solver'), MUMPS (sparse direct, multifrontal, fast "
                      "with an optimised BLAS such as OpenBLAS; LDL^T for the "
                      "symmetric tangent of the symmetric Nitsche variant, LU otherwise), KLU "
                      "(LU, no BLAS; slower on the wide stencils of B-splines, "
                      "doc/performance.md), or Krylov: GMRES with multigrid on the "
                      "displacement block ('Displacement preconditioner') and a direct solve of an "
                      "approximate Schur complement of mu (on several MPI ranks distributed, with "
                      "the algebraic multigrid; doc/performance.md, 'Iterative solver'). With "
                      "'Stability' on, the analysis factorises the tangent itself unless "
                      "'Stability/Eigensolver' is iterative.");
    prm.declare_entry(
      "Automatic memory share",
      "0.5",
      dealii::Patterns::Double(0., 1.),
      "automatic: the share of the memory available when the first tangent is "
      "factorised (Linux's MemAvailable; on several MPI ranks the least of the "
      "ranks' machines) that MUMPS's estimate of its factorisation (LU: twice "
      "the LDL^T estimate; on several ranks all ranks' together) may take; "
      "beyond it the run solves by Krylov. The rest is for the points, the matrix and the output.");
    prm.declare_entry(
      "Ordering",
      "fewest flops",
      dealii::Patterns::Selection("fewest flops|nested dissection|MUMPS"),
      "MUMPS LDL^T (the symmetric Nitsche variant): the fill-reducing ordering of "
      "its analysis, made once per sparsity pattern. nested dissection: METIS's, "
      "computed here and handed to MUMPS. MUMPS: its own choice, approximate "
      "minimum fill in Debian's MUMPS (built without METIS). fewest flops (the "
      "default): both analysed, the one MUMPS estimates cheaper kept, where MUMPS's "
      "estimates at least 2000 flops per matrix entry (compact 3D bodies); below "
      "it, where the second analysis costs more than it can save (2D), MUMPS's. "
      "On a compact 3D body the nested dissection takes about half the flops, on "
      "a slender one about twice (doc/performance.md, 'The ordering of the direct "
      "solver'). On several MPI ranks MUMPS always orders by itself.");
    prm.declare_entry(
      "Compression",
      "0",
      dealii::Patterns::Double(0., 0.1),
      "MUMPS LDL^T (the symmetric Nitsche variant): the dropping threshold of a block "
      "low-rank factorisation (MUMPS's BLR; blocks of the fronts and of their contribution "
      "blocks replaced by low-rank products that drop less than this, relative to the "
      "tangent's norm). 0 (the default): full rank. The solves are then approximate and "
      "Newton takes the more iterations the larger the threshold; the factors and the "
      "operations shrink the more the larger the 3D body (doc/performance.md, 'Compressed "
      "factorisations'). The inertia is that of a matrix within about the threshold of the "
      "tangent: the stability analysis's signature is unchanged unless an eigenvalue lies "
      "that close to zero.");
    prm.declare_entry(
      "Precision",
      "double",
      dealii::Patterns::Selection("double|single"),
      "MUMPS LDL^T (the symmetric Nitsche variant): the arithmetic of the factors. single: "
      "MUMPS's single precision (half the factors' memory, faster dense kernels), each solve "
      "refined in double precision against the tangent to a relative residual of 1e-13; where "
      "the refinement stalls above 1e-9 (condition numbers near 1/6e-8: doc/conditioning.md) "
      "the run factorises in double from then on and says so. The inertia of the stability "
      "analysis is then that of the single-precision factors: the same unless an eigenvalue "
      "lies within about 1e-7 of the tangent's norm of zero (doc/performance.md, 'Single "
      "precision').");
    prm.declare_entry("Krylov tolerance",
                      "1e-8",
                      dealii::Patterns::Double(1e-14, 0.1),
                      "Krylov: the reduction of the residual each linear solve must reach. "
                      "Newton converges to its own tolerance as long as this is well below the "
                      "contraction of its iterations.");
    prm.declare_entry("Krylov iterations",
                      "500",
                      dealii::Patterns::Integer(1),
                      "Krylov: the most iterations of one solve; a solve that needs more fails, "
                      "and the time step is retried shorter.");
    prm.declare_entry("Krylov restart",
                      "200",
                      dealii::Patterns::Integer(1),
                      "Krylov: the GMRES restart length (memory: this many vectors), at "
                      "least 10: shorter ones stall on the indefinite u-mu systems.");
    prm.declare_entry(
      "Displacement preconditioner",
      "geometric",
      dealii::Patterns::Selection("algebraic|geometric"),
      "Krylov: the multigrid cycle that approximates the inverse of the "
      "displacement block K_uu. geometric: on the nested B-spline grids of cell "
      "size 2h, 4h, ... (while the cell counts are even), Galerkin coarse "
      "operators, overlapping Schwarz smoothing on cell blocks, the coarsest "
      "level factorised (BSplineMultigrid); algebraic where the grid has no "
      "coarser level, on a locally refined grid and on several MPI ranks. "
      "algebraic: smoothed aggregation "
      "(Trilinos ML) with the rigid-body modes. doc/performance.md, 'Iterative solver', has the "
      "iteration counts of both.");
    prm.declare_entry("Schur complement",
                      "LSC",
                      dealii::Patterns::Selection("LSC|diagonal"),
                      "Krylov: the approximation of the Schur complement S = C - B A^{-1} B^T' "
                      "of mu (A = K_uu, B = K_mu,u, B^T' = K_u,mu, C = K_mu,mu), with a weight "
                      "W ~ A and L_C = C - B W^{-1} B^T' (sparse, factorised). diagonal: "
                      "S ~ L_C with W = |diag(A)|; its count grows with refinement in the "
                      "undrained limit (dt -> 0; with A exact 35, 54, 77 iterations per solve "
                      "on the three §4.1 grids of doc/performance.md). LSC (the default): the "
                      "least-squares commutator, S^{-1} ~ L_C^{-1} (C - B W^{-1} A W^{-1} B^T') "
                      "L_C^{-1} with W the block diagonal of A ('LSC block threshold'): the "
                      "commutator's approximation of B A^{-1} B^T' for C -> 0, C^{-1} where C "
                      "dominates (large dt). Undrained 9.6, 10.7, 13.2 on those grids, the same "
                      "or fewer elsewhere, at one more solve with L_C and one product with K "
                      "per iteration. On several MPI ranks: diagonal.");
    prm.declare_entry("LSC block threshold",
                      "0.7",
                      dealii::Patterns::Double(0., 1.),
                      "Krylov, LSC: the weight W is the block diagonal of A over the groups of "
                      "displacement unknowns that A couples strongly, |a_ij| > threshold "
                      "sqrt(|a_ii a_jj|) (in practice the normal components of the functions "
                      "that the Nitsche penalty ties together on an immersed boundary), "
                      "|diag(A)| elsewhere. 1: W = |diag(A)| everywhere, whose commutator fails "
                      "at those boundaries (undrained 20, 26, 36 on the grids above).");
    prm.declare_entry("Multigrid smoother",
                      "cell blocks",
                      dealii::Patterns::Selection("cell blocks|point Gauss-Seidel"),
                      "Krylov, geometric: cell blocks (per cell with material, the unknowns of "
                      "the functions nonzero on it, solved together, multiplicative) or point "
                      "symmetric Gauss-Seidel, which leaves the error that the Nitsche penalty "
                      "couples across boundary cells (BSplineMultigrid).");
    prm.declare_entry("Multigrid smoothing steps",
                      "1",
                      dealii::Patterns::Integer(1, 20),
                      "Krylov, geometric: the forward-backward smoother sweeps before and after "
                      "each coarse correction.");
    prm.declare_entry("Multigrid coarse size",
                      "5000",
                      dealii::Patterns::Integer(1),
                      "Krylov, geometric: coarsening stops at the first level with at most this "
                      "many unknowns, which is factorised (UMFPACK); a coarsest level that is "
                      "larger (the grid has no coarser level) is approximated by algebraic "
                      "multigrid.");
    prm.declare_entry("Multigrid cycle",
                      "V",
                      dealii::Patterns::Selection("V|W"),
                      "Krylov, geometric: V- or W-cycle.");
    prm.leave_subsection();
  }


  void
  LinearSolver::parse_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Linear solver");
    const std::string solver = prm.get("Solver");
    automatic                = solver == "automatic";
    decided                  = !automatic;
    choice.clear();
    // automatic starts as MUMPS and may turn to Krylov at the first factorisation (decide()).
    solver_type  = solver == "MUMPS" || automatic ? "Amesos_Mumps"
                   : solver == "KLU"              ? "Amesos_Klu"
                                                  : "Krylov";
    memory_share = prm.get_double("Automatic memory share");
    ordering     = SymmetricFactorization::parse_ordering(prm.get("Ordering"));
    compression  = prm.get_double("Compression");
    precision    = prm.get("Precision") == "single"
                     ? SymmetricFactorization::Precision::single_precision
                     : SymmetricFactorization::Precision::double_precision;
    require(precision == SymmetricFactorization::Precision::double_precision || solver == "MUMPS" ||
              automatic,
            "Linear solver/Precision",
            "is single with Solver = " + solver + ", which factorises nothing by MUMPS",
            "set Solver = MUMPS (or automatic), or Precision = double");
    require(compression == 0. || solver == "MUMPS" || automatic,
            "Linear solver/Compression",
            "is " + prm.get("Compression") + " with Solver = " + solver +
              ", which factorises nothing by MUMPS",
            "set Solver = MUMPS (or automatic), or Compression = 0");
    krylov_settings.relative_tolerance = prm.get_double("Krylov tolerance");
    krylov_settings.max_iterations     = prm.get_integer("Krylov iterations");
    krylov_settings.restart            = prm.get_integer("Krylov restart");
    require(krylov_settings.restart >= smallest_krylov_restart,
            "Linear solver/Krylov restart",
            "is " + std::to_string(krylov_settings.restart) + ", below " +
              std::to_string(smallest_krylov_restart) +
              ": GMRES restarted this often stalls on the indefinite u-mu systems (restart 1 "
              "left 99.98 % of the residual after 500 iterations on the free-swelling test "
              "scene; restart 2 took 300 s for 1234 steps, 423 attempts failing, on the "
              "constrained-swelling one, which restart 5 runs in 20 steps)",
            "give at least " + std::to_string(smallest_krylov_restart) +
              " (the default 200; the memory is this many vectors)");
    krylov_settings.geometric = prm.get("Displacement preconditioner") == "geometric";
    krylov_settings.schur     = prm.get("Schur complement") == "LSC"
                                  ? BlockKrylov::SchurApproximation::lsc
                                  : BlockKrylov::SchurApproximation::diagonal;
    krylov_settings.multigrid.smoothing_steps    = prm.get_integer("Multigrid smoothing steps");
    krylov_settings.multigrid.direct_coarse_size = prm.get_integer("Multigrid coarse size");
    krylov_settings.multigrid.w_cycle            = prm.get("Multigrid cycle") == "W";
    krylov_settings.multigrid.cell_blocks        = prm.get("Multigrid smoother") == "cell blocks";
    prm.leave_subsection();
  }


  void
  LinearSolver::set_symmetric(const bool symmetric_matrices)
  {
    require(symmetric_matrices || precision == SymmetricFactorization::Precision::double_precision,
            "Linear solver/Precision",
            "single factorises MUMPS's LDL^T, which only the symmetric tangent of "
            "Nitsche/Variant = symmetric has (the skew-symmetric variant's is factorised as LU)",
            "set Nitsche/Variant = symmetric, or Precision = double");
    require(symmetric_matrices || compression == 0.,
            "Linear solver/Compression",
            "compresses MUMPS's LDL^T, which only the symmetric tangent of Nitsche/Variant = "
            "symmetric has (the skew-symmetric variant's is factorised as LU)",
            "set Nitsche/Variant = symmetric, or Compression = 0");
    new_pattern();
    symmetric = symmetric_matrices;
  }


  bool
  LinearSolver::uses_ldlt() const
  {
    return symmetric && solver_type == "Amesos_Mumps";
  }


  bool
  LinearSolver::iterative() const
  {
    return solver_type == "Krylov";
  }


  bool
  LinearSolver::may_iterate() const
  {
    return iterative() || !decided;
  }


  void
  LinearSolver::decide(const dealii::TrilinosWrappers::SparseMatrix &K) const
  {
    decided = true;
    // The analysis alone (ordering and symbolic factorisation) is cheap against the numeric
    // factorisation; its estimate covers LDL^T, and LU keeps both triangles. On several ranks it
    // is the estimate of all ranks together, and the memory is the least any rank's machine has
    // available: exact when the ranks share one machine, on the safe side across machines, and
    // the same decision on every rank.
    SymmetricFactorization analysis;
    analysis.set_ordering(ordering);
    const MPI_Comm     comm      = K.get_mpi_communicator();
    const double       estimate  = (symmetric ? 1. : 2.) * analysis.estimated_memory(K);
    const double       available = dealii::Utilities::MPI::min(available_memory(), comm);
    const double       limit     = memory_share * available;
    std::ostringstream why;
    why.precision(3);
    why << "the factorisation's estimate " << estimate / 1e6 << " MB against " << limit / 1e6
        << " MB (" << memory_share << " of " << available / 1e6 << " MB available)";
    // Single-precision factors take half the memory, and solve as the double ones do wherever
    // their refinement converges (doc/performance.md, 'Single precision').
    const bool single_fits = symmetric && estimate / 2. <= limit;
    if (available > 0. && estimate > limit && single_fits)
      {
        precision = SymmetricFactorization::Precision::single_precision;
        choice    = "MUMPS in single precision: " + why.str() + "; half of it fits";
      }
    else if (available > 0. && estimate > limit)
      {
        solver_type = "Krylov";
        choice      = "Krylov: " + why.str();
      }
    else
      choice = "MUMPS: " + why.str();
  }


  std::string
  LinearSolver::automatic_choice() const
  {
    return choice;
  }


  void
  LinearSolver::set_block_structure(const unsigned int                     n_u,
                                    const unsigned int                     dim,
                                    const std::vector<double>             &u_dof_points,
                                    const std::vector<NestedBSplineLevel> &levels)
  {
    // The same unknowns at the same places keep the preconditioner for modified Newton.
    if (krylov.set_structure(n_u, dim, u_dof_points, levels))
      factorized = false;
  }


  bool
  LinearSolver::geometric_multigrid() const
  {
    return krylov_settings.geometric;
  }


  std::string
  LinearSolver::krylov_preconditioner() const
  {
    return krylov.displacement_preconditioner();
  }


  std::pair<unsigned long, unsigned long>
  LinearSolver::krylov_iterations() const
  {
    return {n_krylov_iterations, n_krylov_solves};
  }


  void
  LinearSolver::new_pattern() const
  {
    factorisation.reset();
    problem.reset();
    ldlt.reset();
    analysed_matrix = nullptr;
    factorized      = false;
  }


  void
  LinearSolver::factorize(const dealii::TrilinosWrappers::SparseMatrix &K) const
  {
    // Until it returns: every failure below throws.
    call_failed = true;
    if (!decided)
      decide(K);
    const Epetra_CrsMatrix &matrix = K.trilinos_matrix();
    factorized                     = false;
    if (iterative())
      {
        krylov.setup(K, krylov_settings);
        ++symbolic_count;
      }
    else if (uses_ldlt())
      {
        try
          {
            if (!ldlt || analysed_matrix != &matrix)
              {
                ldlt = std::make_unique<SymmetricFactorization>();
                ldlt->set_ordering(ordering);
                ldlt->set_compression(compression);
                ldlt->set_precision(precision);
                ldlt->factorize(K);
                analysed_matrix = &matrix;
                ++symbolic_count;
              }
            else
              ldlt->refactorize(K);
            add_factor_statistics(ldlt->statistics());
          }
        catch (const std::exception &e)
          {
            new_pattern();
            throw std::runtime_error(std::string("the direct solver (MUMPS LDL^T) failed on the "
                                                 "Newton system: ") +
                                     e.what());
          }
      }
    else
      {
        int error = 0;
        if (!factorisation || problem->GetMatrix() != &matrix)
          {
            // A new sparsity pattern (or a new matrix object): analyse it once; the Newton
            // iterations of a step then only refactorise numerically.
            problem = std::make_unique<Epetra_LinearProblem>();
            problem->SetOperator(const_cast<Epetra_CrsMatrix *>(&matrix));
            Amesos factory;
            factorisation.reset(factory.Create(solver_type, *problem));
            if (!factorisation)
              throw std::runtime_error("the direct solver " + solver_type + " is not available");
            error = factorisation->SymbolicFactorization();
            ++symbolic_count;
          }
        if (error == 0)
          error = factorisation->NumericFactorization();
        if (error != 0)
          {
            new_pattern();
            throw std::runtime_error("the direct solver (" + solver_type +
                                     ") failed on the Newton system (Amesos error " +
                                     std::to_string(error) + ")");
          }
      }
    factorized_matrix           = &K;
    factorized                  = true;
    factorized_dt               = 0.;
    n_solves_with_factorization = 0;
    call_failed                 = false;
    ++numeric_count;
    if (keep_values)
      {
        factorized_entries.clear();
        for_each_entry(K,
                       K.m(),
                       [this](const unsigned int row,
                              const unsigned int column,
                              const double       value) {
                         factorized_entries.rows.push_back(row);
                         factorized_entries.columns.push_back(column);
                         factorized_entries.values.push_back(value);
                       });
      }
  }


  void
  LinearSolver::keep_factorized_values(const bool keep)
  {
    keep_values = keep;
  }


  const SparseEntries &
  LinearSolver::entries_of_factorization() const
  {
    static const SparseEntries none;
    return factorized ? factorized_entries : none;
  }


  void
  LinearSolver::solve(dealii::Vector<double>       &x,
                      const dealii::Vector<double> &b,
                      const double                  refinement_target) const
  {
    // Until it returns: every failure below throws.
    call_failed = true;
    if (!factorized)
      throw std::logic_error("LinearSolver::solve() without a factorisation");
    if (iterative())
      {
        n_krylov_iterations += krylov.solve(x, b);
        ++n_krylov_solves;
      }
    else if (ldlt)
      solve_ldlt(x, b, refinement_target);
    else
      {
        const Epetra_RowMatrix &matrix = *problem->GetMatrix();
        int                     error  = 0;
        if (matrix.Comm().NumProc() == 1)
          {
            Epetra_Vector x_view(View, matrix.OperatorDomainMap(), x.begin());
            Epetra_Vector b_view(View, matrix.OperatorRangeMap(), const_cast<double *>(b.begin()));
            problem->SetLHS(&x_view);
            problem->SetRHS(&b_view);
            error = factorisation->Solve();
          }
        else
          {
            // The Newton vectors are whole on every rank; Amesos takes the owned entries and
            // the solution is made whole again by summing the ranks' owned parts.
            const Epetra_Map &range  = matrix.OperatorRangeMap();
            const Epetra_Map &domain = matrix.OperatorDomainMap();
            Epetra_Vector     b_owned(range), x_owned(domain);
            for (int i = 0; i < range.NumMyElements(); ++i)
              b_owned[i] = b(range.GID64(i));
            problem->SetLHS(&x_owned);
            problem->SetRHS(&b_owned);
            error = factorisation->Solve();
            x.reinit(b.size());
            for (int i = 0; i < domain.NumMyElements(); ++i)
              x(domain.GID64(i)) = x_owned[i];
            Collective::sum_in_place(dynamic_cast<const Epetra_MpiComm &>(matrix.Comm()).Comm(),
                                     x.begin(),
                                     x.size());
          }
        // The vectors die with this call: no dangling vectors in the kept problem.
        problem->SetLHS(nullptr);
        problem->SetRHS(nullptr);
        if (error != 0)
          {
            new_pattern();
            throw std::runtime_error("the direct solver (" + solver_type +
                                     ") failed on the Newton system (Amesos error " +
                                     std::to_string(error) + ")");
          }
      }
    for (const double v : x)
      if (!std::isfinite(v))
        throw std::runtime_error("the direct solver (" + name() +
                                 ") returned a non-finite solution (singular tangent)");
    ++n_solves_with_factorization;
    call_failed = false;
  }


  void
  LinearSolver::solve(const dealii::TrilinosWrappers::SparseMatrix &K,
                      dealii::Vector<double>                       &x,
                      const dealii::Vector<double>                 &b) const
  {
    factorize(K);
    solve(x, b);
  }


  bool
  LinearSolver::has_factorization() const
  {
    return factorized;
  }


  double
  LinearSolver::factorized_step() const
  {
    return factorized_dt;
  }


  void
  LinearSolver::note_factorized_step(const double dt) const
  {
    factorized_dt = dt;
  }


  unsigned int
  LinearSolver::solves_with_factorization() const
  {
    return n_solves_with_factorization;
  }


  bool
  LinearSolver::last_call_failed() const
  {
    return call_failed;
  }


  const SymmetricFactorization *
  LinearSolver::symmetric_factorization() const
  {
    // Single-precision factors cannot serve the stability analysis: near an onset the tangent
    // is nearly singular, beyond their refinement (the Schur eigenvalues' shift-invert solves
    // stalled at a relative residual of 0.69 on the column of paper §4.3).
    return factorized && precision == SymmetricFactorization::Precision::double_precision
             ? ldlt.get()
             : nullptr;
  }


  unsigned int
  LinearSolver::n_symbolic_factorisations() const
  {
    return symbolic_count;
  }


  unsigned int
  LinearSolver::n_numeric_factorisations() const
  {
    return numeric_count;
  }


  void
  LinearSolver::solve_ldlt(dealii::Vector<double>       &x,
                           const dealii::Vector<double> &b,
                           const double                  refinement_target) const
  {
    x = b;
    try
      {
        ldlt->solve(x, refinement_target);
        refinement_steps += ldlt->refinement_steps();
      }
    catch (const RefinementFailure &failure)
      {
        // The single-precision factors are too inexact for this tangent: double from now on.
        precision_fallback  = failure.what();
        precision           = SymmetricFactorization::Precision::double_precision;
        const auto  &K      = *factorized_matrix;
        const double dt     = factorized_dt;
        const auto   solves = n_solves_with_factorization;
        new_pattern();
        factorize(K);
        // The same tangent, in double precision: its step and reuses stay.
        factorized_dt               = dt;
        n_solves_with_factorization = solves;
        x                           = b;
        ldlt->solve(x);
      }
  }


  std::string
  LinearSolver::precision_report() const
  {
    if (precision == SymmetricFactorization::Precision::single_precision)
      return "single precision, " + std::to_string(refinement_steps) + " refinement steps";
    if (!precision_fallback.empty())
      return "double precision after " + precision_fallback;
    return "";
  }


  void
  LinearSolver::add_factor_statistics(const FactorStatistics &factor) const
  {
    factor_totals.flops += factor.flops;
    factor_totals.full_rank_flops += factor.full_rank_flops;
    factor_totals.entries = std::max(factor_totals.entries, factor.entries);
    factor_totals.full_rank_entries =
      std::max(factor_totals.full_rank_entries, factor.full_rank_entries);
    factor_totals.memory = std::max(factor_totals.memory, factor.memory);
  }


  FactorStatistics
  LinearSolver::factor_statistics() const
  {
    return factor_totals;
  }


  std::string
  LinearSolver::compression_report() const
  {
    if (compression == 0. || factor_totals.full_rank_flops == 0.)
      return "";
    std::ostringstream report;
    report.precision(3);
    report << "block low-rank at " << compression << ": "
           << 100. * factor_totals.flops / factor_totals.full_rank_flops
           << " % of the full-rank operations, the largest factors "
           << 100. * factor_totals.entries / factor_totals.full_rank_entries
           << " % of their full-rank entries";
    return report.str();
  }


  std::string
  LinearSolver::name() const
  {
    std::string used = uses_ldlt()   ? "MUMPS LDL^T"
                       : iterative() ? "GMRES with AMG and Schur"
                                     : solver_type;
    if (uses_ldlt() && ldlt)
      {
        std::ostringstream flops;
        flops.precision(3);
        flops << ", " << ldlt->factorization_flops() << " flops the last";
        used += ", " + ldlt->ordering_used() + flops.str();
        if (compression > 0.)
          used += ", " + compression_report();
        if (!precision_report().empty())
          used += ", " + precision_report();
      }
    return automatic ? "automatic: " + used + (choice.empty() ? "" : "; " + choice) : used;
  }
} // namespace GelMPM
