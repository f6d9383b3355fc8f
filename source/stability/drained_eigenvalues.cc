#include <gelmpm/core/collective.h>
#include <gelmpm/stability/drained_eigenvalues.h>

#include <AnasaziBasicEigenproblem.hpp>
#include <AnasaziEpetraAdapter.hpp>
#include <AnasaziLOBPCGSolMgr.hpp>
#include <Epetra_CrsMatrix.h>
#include <Epetra_InvOperator.h>
#include <Epetra_MultiVector.h>
#include <Teuchos_ParameterList.hpp>
#include <Teuchos_RCP.hpp>
#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>
#include <stdexcept>

namespace GelMPM
{
  DrainedEigenvalues
  smallest_drained_eigenvalues(const DisplacementBlockAMG                &block,
                               const unsigned int                         n_eigenvalues,
                               const bool                                 want_vectors,
                               const double                               tolerance,
                               const unsigned int                         max_iterations,
                               const std::vector<dealii::Vector<double>> &start)
  {
    using MV = Epetra_MultiVector;
    using OP = Epetra_Operator;

    const Epetra_CrsMatrix &A    = block.matrix().trilinos_matrix();
    const MPI_Comm          comm = block.matrix().get_mpi_communicator();
    const int               n    = A.NumGlobalRows();
    // Two more vectors than wanted: the last wanted pair converges at the rate set by the gap to
    // the first one outside the block, not to its neighbour.
    const int block_size = static_cast<int>(n_eigenvalues) + 2;
    if (n_eigenvalues == 0 || 3 * block_size > n)
      throw std::runtime_error("the displacement block (" + std::to_string(n) +
                               " unknowns) is too small for " + std::to_string(n_eigenvalues) +
                               " eigenvalues by LOBPCG");
    const double norm = A.NormInf();

    // Start vectors: the given ones, then smooth deterministic fields (reproducible results).
    auto x0 = Teuchos::rcp(new MV(A.RowMap(), block_size));
    for (int j = 0; j < block_size; ++j)
      for (int i = 0; i < A.NumMyRows(); ++i)
        (*x0)[j][i] =
          j < static_cast<int>(start.size()) && start[j].size() == static_cast<unsigned>(n)
            ? start[j](A.GRID(i))
            : 1. + 0.1 * std::sin(1. + A.GRID(i) * (1. + 0.37 * j));

    // ML's operator applies its approximate inverse with ApplyInverse(); Anasazi calls Apply().
    auto preconditioner = Teuchos::rcp(new Epetra_InvOperator(
      const_cast<OP *>(&static_cast<const OP &>(block.preconditioner().trilinos_operator()))));
    auto problem        = Teuchos::rcp(
      new Anasazi::BasicEigenproblem<double, MV, OP>(Teuchos::rcpFromRef<const OP>(A), x0));
    problem->setHermitian(true);
    problem->setNEV(n_eigenvalues);
    problem->setPrec(preconditioner);
    if (!problem->setProblem())
      throw std::runtime_error("Anasazi rejected the eigenproblem of the displacement block");

    Teuchos::ParameterList parameters;
    parameters.set("Which", std::string("SR"));
    parameters.set("Block Size", block_size);
    parameters.set("Maximum Iterations", static_cast<int>(max_iterations));
    parameters.set("Convergence Tolerance", tolerance * norm);
    parameters.set("Relative Convergence Tolerance", false);
    parameters.set("Use Locking", true);
    parameters.set("Locking Tolerance", 0.1 * tolerance * norm);
    parameters.set("Relative Locking Tolerance", false);
    parameters.set("Full Ortho", true);
    parameters.set("Verbosity", static_cast<int>(Anasazi::Errors));
    Anasazi::LOBPCGSolMgr<double, MV, OP> solver(problem, parameters);
    const Anasazi::ReturnType             outcome = solver.solve();

    DrainedEigenvalues result;
    result.iterations    = solver.getNumIters();
    const auto &solution = problem->getSolution();
    if (outcome != Anasazi::Converged || solution.numVecs < static_cast<int>(n_eigenvalues))
      {
        std::ostringstream why;
        why << "LOBPCG found " << solution.numVecs << " of the " << n_eigenvalues
            << " smallest eigenvalues of K_uu to the residual " << tolerance << " ||K_uu|| in "
            << result.iterations << " iterations";
        throw std::runtime_error(why.str());
      }

    std::vector<unsigned int> order(solution.numVecs);
    std::iota(order.begin(), order.end(), 0u);
    std::sort(order.begin(), order.end(), [&](const unsigned int a, const unsigned int b) {
      return solution.Evals[a].realpart < solution.Evals[b].realpart;
    });
    order.resize(n_eigenvalues);
    Epetra_Vector Av(A.RowMap());
    for (const unsigned int k : order)
      {
        const double         lambda = solution.Evals[k].realpart;
        const Epetra_Vector &v      = *(*solution.Evecs)(static_cast<int>(k));
        A.Multiply(false, v, Av);
        double residual = 0., v_norm = 0.;
        for (int i = 0; i < A.NumMyRows(); ++i)
          {
            residual += (Av[i] - lambda * v[i]) * (Av[i] - lambda * v[i]);
            v_norm += v[i] * v[i];
          }
        // On several ranks each holds its rows of A and of v.
        std::vector<double> sums = {residual, v_norm};
        Collective::sum_in_place(comm, sums);
        residual = sums[0];
        v_norm   = sums[1];
        result.values.push_back(lambda);
        result.residuals.push_back(std::sqrt(residual / v_norm) / norm);
        if (want_vectors)
          {
            dealii::Vector<double> vector(n);
            for (int i = 0; i < A.NumMyRows(); ++i)
              vector(A.GRID(i)) = v[i] / std::sqrt(v_norm);
            Collective::sum_in_place(comm, vector.begin(), vector.size());
            result.vectors.push_back(std::move(vector));
          }
      }
    return result;
  }
} // namespace GelMPM
