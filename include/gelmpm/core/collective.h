#ifndef gelmpm_core_collective_h
#define gelmpm_core_collective_h

#include <deal.II/base/mpi.h>

#include <functional>
#include <string>
#include <vector>

namespace GelMPM
{
  /**
   * @brief Decisions that every MPI rank of a run must take together.
   *
   * A rank that finds a fault in its own material points (a point beyond the grid, a state with
   * J <= 1) cannot simply throw: the other ranks would go on to the next collective call and
   * wait for it for ever. Each such check therefore ends in agree_on_failure(), which every rank
   * calls, and which throws the same exception on all of them, with the message of the lowest
   * rank that failed.
   */
  namespace Collective
  {
    /**
     * The message of the lowest rank of @p comm whose @p failure is not empty, on every rank;
     * empty if no rank failed. On one rank: @p failure.
     */
    std::string
    first_failure(const MPI_Comm comm, const std::string &failure);

    /** Throw Exception(first_failure(...)) on every rank if some rank failed. */
    template <typename Exception>
    void
    agree_on_failure(const MPI_Comm comm, const std::string &failure)
    {
      const std::string message = first_failure(comm, failure);
      if (!message.empty())
        throw Exception(message);
    }

    /**
     * Run @p work on rank 0 of @p comm (file system work: directories, files that one rank
     * writes) and let the other ranks wait for it. If it throws, rank 0 rethrows its exception
     * and the others throw std::runtime_error with its message, so that all leave together.
     */
    void
    on_root(const MPI_Comm comm, const std::function<void()> &work);

    /** Whether @p comm has more than one rank. */
    bool
    is_parallel(const MPI_Comm comm);

    /** Sum @p values element-wise over the ranks of @p comm, in place (nothing on one rank). */
    void
    sum_in_place(const MPI_Comm comm, double *values, const std::size_t n);

    /** Sum @p values element-wise over the ranks of @p comm, in place (nothing on one rank). */
    void
    sum_in_place(const MPI_Comm comm, std::vector<double> &values);
  } // namespace Collective
} // namespace GelMPM

#endif
