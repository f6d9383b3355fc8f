#include <gelmpm/stability/matrix_entries.h>
#include <gelmpm/stability/symmetric_factorization.h>

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <dmumps_c.h>
#include <stdexcept>
#include <string>
#include <vector>

namespace GelMPM
{
  namespace
  {
    // MUMPS documents its controls with Fortran (1-based) indices.
    constexpr int
    icntl(const int i)
    {
      return i - 1;
    }
  } // namespace


  struct SymmetricFactorization::Data
  {
    DMUMPS_STRUC_C         mumps;
    std::vector<MUMPS_INT> rows, columns;
    std::vector<double>    values;
    MPI_Comm               communicator = MPI_COMM_SELF;
    bool                   distributed  = false;
    bool                   initialized  = false;
    bool                   factorized   = false;

    /**
     * Start MUMPS on the communicator of the matrix. On several ranks each passes the entries of
     * the rows it owns (ICNTL(18) = 3) and the right-hand side and solution live on rank 0
     * (ICNTL(20) = ICNTL(21) = 0), from where solve() broadcasts the solution; on one rank the
     * matrix is passed whole, as before the distribution existed.
     */
    void
    start(const MPI_Comm comm)
    {
      communicator       = comm;
      distributed        = dealii::Utilities::MPI::n_mpi_processes(comm) > 1;
      mumps.comm_fortran = static_cast<MUMPS_INT>(MPI_Comm_c2f(comm));
      mumps.par          = 1; // the host takes part in the factorisation
      mumps.sym          = 2; // general symmetric (indefinite): LDL^T
      call(-1);
      initialized = true;
      // Silence MUMPS; errors are reported through INFOG.
      mumps.icntl[icntl(1)]  = -1;
      mumps.icntl[icntl(2)]  = -1;
      mumps.icntl[icntl(3)]  = -1;
      mumps.icntl[icntl(4)]  = 0;
      mumps.icntl[icntl(13)] = 1; // sequential root: the negative-pivot count covers it
      mumps.icntl[icntl(24)] = 1; // detect null pivots (INFOG(28))
      if (distributed)
        mumps.icntl[icntl(18)] = 3;
    }

    /** The lower triangle of the leading @p n x @p n block of @p K, as MUMPS's triplets. */
    void
    gather(const dealii::TrilinosWrappers::SparseMatrix &K, const unsigned int n)
    {
      rows.clear();
      columns.clear();
      values.clear();
      // Zeros too: the structure, not the values, decides what the analysis can be reused for.
      for_each_entry(K,
                     n,
                     [this](const unsigned int row, const unsigned int column, const double value) {
                       if (column <= row)
                         {
                           rows.push_back(row + 1);
                           columns.push_back(column + 1);
                           values.push_back(value);
                         }
                     });
      mumps.n = n;
      if (distributed)
        {
          mumps.nnz_loc = values.size();
          mumps.irn_loc = rows.data();
          mumps.jcn_loc = columns.data();
          mumps.a_loc   = values.data();
        }
      else
        {
          mumps.nnz = values.size();
          mumps.irn = rows.data();
          mumps.jcn = columns.data();
          mumps.a   = values.data();
        }
    }

    void
    call(const int job)
    {
      mumps.job = job;
      dmumps_c(&mumps);
      if (mumps.infog[0] < 0)
        throw std::runtime_error("MUMPS (job " + std::to_string(job) +
                                 ") failed with INFOG(1) = " + std::to_string(mumps.infog[0]) +
                                 ", INFOG(2) = " + std::to_string(mumps.infog[1]));
    }
  };


  SymmetricFactorization::SymmetricFactorization()
    : data(std::make_unique<Data>())
  {}


  SymmetricFactorization::~SymmetricFactorization()
  {
    if (data && data->initialized)
      {
        data->mumps.job = -2;
        dmumps_c(&data->mumps);
      }
  }


  double
  SymmetricFactorization::estimated_memory(const dealii::TrilinosWrappers::SparseMatrix &K)
  {
    data->factorized = false;
    if (!data->initialized)
      data->start(K.get_mpi_communicator());
    data->gather(K, K.m());
    data->call(1);
    // INFOG(17): MB (10^6 bytes) for the in-core factorisation, all ranks.
    return 1e6 * data->mumps.infog[16];
  }


  void
  SymmetricFactorization::factorize(const dealii::TrilinosWrappers::SparseMatrix &K,
                                    const unsigned int                            leading)
  {
    data->factorized = false;
    if (!data->initialized)
      data->start(K.get_mpi_communicator());
    else if (data->communicator != K.get_mpi_communicator())
      throw std::logic_error("SymmetricFactorization::factorize() with a matrix on another "
                             "communicator than the first");
    data->gather(K, std::min<unsigned int>(leading, K.m()));
    data->call(4); // analysis + factorisation
    data->factorized = true;
  }


  void
  SymmetricFactorization::refactorize(const dealii::TrilinosWrappers::SparseMatrix &K)
  {
    if (!data->factorized)
      throw std::logic_error("SymmetricFactorization::refactorize() before factorize()");
    const std::size_t n_entries = data->values.size();
    data->gather(K, data->mumps.n);
    if (data->values.size() != n_entries)
      throw std::logic_error("SymmetricFactorization::refactorize() with another sparsity pattern");
    data->factorized = false;
    data->call(2); // factorisation with the kept analysis
    data->factorized = true;
  }


  Inertia
  SymmetricFactorization::inertia() const
  {
    if (!data->factorized)
      throw std::logic_error("SymmetricFactorization::inertia() before factorize()");
    const auto &m = data->mumps;
    Inertia     result;
    result.n_negative = m.infog[11]; // INFOG(12)
    result.n_zero     = m.infog[27]; // INFOG(28)
    result.n_positive = m.n - result.n_negative - result.n_zero;
    return result;
  }


  void
  SymmetricFactorization::solve(dealii::Vector<double> &x) const
  {
    if (!data->factorized)
      throw std::logic_error("SymmetricFactorization::solve() before factorize()");
    auto &m = data->mumps;
    m.nrhs  = 1;
    m.lrhs  = m.n;
    m.rhs   = x.begin();
    data->call(3);
    if (data->distributed)
      {
        const int ierr = MPI_Bcast(x.begin(), x.size(), MPI_DOUBLE, 0, data->communicator);
        AssertThrowMPI(ierr);
      }
  }


  unsigned int
  SymmetricFactorization::size() const
  {
    return data->mumps.n;
  }
} // namespace GelMPM
