#include <gelmpm/core/collective.h>

#include <deal.II/base/array_view.h>

#include <exception>

namespace GelMPM
{
  namespace Collective
  {
    std::string
    first_failure(const MPI_Comm comm, const std::string &failure)
    {
      if (!is_parallel(comm))
        return failure;
      const unsigned int n_ranks = dealii::Utilities::MPI::n_mpi_processes(comm);
      const unsigned int rank    = dealii::Utilities::MPI::this_mpi_process(comm);
      const unsigned int first =
        dealii::Utilities::MPI::min(failure.empty() ? n_ranks : rank, comm);
      if (first == n_ranks)
        return std::string();
      return dealii::Utilities::MPI::broadcast(comm, failure, first);
    }


    void
    on_root(const MPI_Comm comm, const std::function<void()> &work)
    {
      if (!is_parallel(comm))
        return work();
      std::string        failure;
      std::exception_ptr error;
      if (dealii::Utilities::MPI::this_mpi_process(comm) == 0)
        try
          {
            work();
          }
        catch (const std::exception &e)
          {
            failure = e.what();
            error   = std::current_exception();
          }
      const std::string message = first_failure(comm, failure);
      if (error)
        std::rethrow_exception(error);
      if (!message.empty())
        throw std::runtime_error(message);
    }


    bool
    is_parallel(const MPI_Comm comm)
    {
      return dealii::Utilities::MPI::n_mpi_processes(comm) > 1;
    }


    void
    sum_in_place(const MPI_Comm comm, double *values, const std::size_t n)
    {
      if (!is_parallel(comm) || n == 0)
        return;
      const int ierr = MPI_Allreduce(MPI_IN_PLACE, values, n, MPI_DOUBLE, MPI_SUM, comm);
      AssertThrowMPI(ierr);
    }


    void
    sum_in_place(const MPI_Comm comm, std::vector<double> &values)
    {
      sum_in_place(comm, values.data(), values.size());
    }
  } // namespace Collective
} // namespace GelMPM
