#include <gelmpm/stability/matrix_entries.h>
#include <gelmpm/stability/symmetric_factorization.h>

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <dmumps_c.h>
#include <metis.h>
#include <smumps_c.h>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>
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

    /** MUMPS's double-precision arithmetic (DMUMPS). */
    struct DoubleArithmetic
    {
      using Struc = DMUMPS_STRUC_C;
      using Real  = double;
      static void
      run(Struc &mumps)
      {
        dmumps_c(&mumps);
      }
    };

    /** MUMPS's single-precision arithmetic (SMUMPS): half the factor's memory. */
    struct SingleArithmetic
    {
      using Struc = SMUMPS_STRUC_C;
      using Real  = float;
      static void
      run(Struc &mumps)
      {
        smumps_c(&mumps);
      }
    };

    /**
     * One MUMPS instance of @p Arithmetic: its control structure and, where its arithmetic is not
     * double, its copy of the matrix's entries.
     */
    template <class Arithmetic>
    struct MumpsInstance
    {
      typename Arithmetic::Struc             mumps = {};
      std::vector<typename Arithmetic::Real> converted_values;
      bool                                   initialized = false;

      /**
       * Start MUMPS on @p comm. On several ranks each passes the entries of the rows it owns
       * (ICNTL(18) = 3) and the right-hand side and solution live on rank 0 (ICNTL(20) =
       * ICNTL(21) = 0), from where solve() broadcasts the solution; on one rank the matrix is
       * passed whole.
       */
      void
      start(const MPI_Comm comm, const bool distributed)
      {
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

      /** Release MUMPS's data. */
      void
      finish()
      {
        if (initialized)
          {
            mumps.job = -2;
            Arithmetic::run(mumps);
            initialized = false;
          }
      }

      /** Point MUMPS at the lower triangle's triplets (1-based), converted to its arithmetic. */
      void
      set_entries(const unsigned int      n,
                  std::vector<MUMPS_INT> &rows,
                  std::vector<MUMPS_INT> &columns,
                  std::vector<double>    &values,
                  const bool              distributed)
      {
        typename Arithmetic::Real *a = nullptr;
        if constexpr (std::is_same_v<typename Arithmetic::Real, double>)
          a = values.data();
        else
          {
            converted_values.assign(values.begin(), values.end());
            a = converted_values.data();
          }
        mumps.n = n;
        if (distributed)
          {
            mumps.nnz_loc = values.size();
            mumps.irn_loc = rows.data();
            mumps.jcn_loc = columns.data();
            mumps.a_loc   = a;
          }
        else
          {
            mumps.nnz = values.size();
            mumps.irn = rows.data();
            mumps.jcn = columns.data();
            mumps.a   = a;
          }
      }

      void
      call(const int job)
      {
        mumps.job = job;
        Arithmetic::run(mumps);
        if (mumps.infog[0] < 0)
          throw std::runtime_error("MUMPS (job " + std::to_string(job) +
                                   ") failed with INFOG(1) = " + std::to_string(mumps.infog[0]) +
                                   ", INFOG(2) = " + std::to_string(mumps.infog[1]));
      }

      /** Solve in place, in MUMPS's arithmetic, on rank 0's @p x. */
      void
      solve(dealii::Vector<double> &x)
      {
        mumps.nrhs = 1;
        mumps.lrhs = mumps.n;
        if constexpr (std::is_same_v<typename Arithmetic::Real, double>)
          {
            mumps.rhs = x.begin();
            call(3);
          }
        else
          {
            std::vector<typename Arithmetic::Real> rhs(x.begin(), x.end());
            mumps.rhs = rhs.data();
            call(3);
            std::copy(rhs.begin(), rhs.end(), x.begin());
          }
      }
    };
  } // namespace


  struct SymmetricFactorization::Data
  {
    MumpsInstance<DoubleArithmetic> full;
    MumpsInstance<SingleArithmetic> reduced;
    Precision                       precision = Precision::double_precision;
    // The lower triangle gathered (1-based triplets), in double precision: the matrix of the
    // single-precision factorisation's iterative refinement.
    std::vector<MUMPS_INT> rows, columns;
    std::vector<double>    values;
    unsigned int           n = 0;
    // The pivot order (1-based) of the nested dissection, for the gathered entries.
    std::vector<MUMPS_INT> pivot_order;
    Ordering               ordering = Ordering::fewest_flops;
    double comparison_threshold     = SymmetricFactorization::default_comparison_threshold;
    // The dropping threshold of the block low-rank factorisation (0: full rank).
    double   compression  = 0.;
    MPI_Comm communicator = MPI_COMM_SELF;
    bool     distributed  = false;
    bool     started      = false;
    bool     factorized   = false;
    // Refinement steps of the last solve (single precision).
    unsigned int refinement_steps = 0;

    /** Call @p f with the MUMPS instance of the chosen precision. */
    template <class F>
    decltype(auto)
    with_mumps(F &&f)
    {
      return precision == Precision::single_precision ? f(reduced) : f(full);
    }

    template <class F>
    decltype(auto)
    with_mumps(F &&f) const
    {
      return precision == Precision::single_precision ? f(reduced) : f(full);
    }

    void
    start(const MPI_Comm comm)
    {
      communicator = comm;
      distributed  = dealii::Utilities::MPI::n_mpi_processes(comm) > 1;
      with_mumps([&](auto &m) {
        m.start(comm, distributed);
      });
      started = true;
    }

    /** The lower triangle of the leading @p n_rows x @p n_rows block of @p K, as triplets. */
    void
    gather(const dealii::TrilinosWrappers::SparseMatrix &K, const unsigned int n_rows)
    {
      rows.clear();
      columns.clear();
      values.clear();
      // Zeros too: the structure, not the values, decides what the analysis can be reused for.
      for_each_entry(K,
                     n_rows,
                     [this](const unsigned int row, const unsigned int column, const double value) {
                       if (column <= row)
                         {
                           rows.push_back(row + 1);
                           columns.push_back(column + 1);
                           values.push_back(value);
                         }
                     });
      n = n_rows;
      with_mumps([&](auto &m) {
        m.set_entries(n, rows, columns, values, distributed);
      });
    }

    /** MUMPS's own ordering for the next analysis (ICNTL(7) = 7). */
    void
    use_mumps_ordering()
    {
      with_mumps([](auto &m) {
        m.mumps.icntl[icntl(7)] = 7;
      });
    }

    /**
     * METIS's nested dissection of the gathered entries' graph as the ordering of the next
     * analysis (ICNTL(7) = 1, PERM_IN), computed once per gather().
     */
    void
    use_nested_dissection()
    {
      if (pivot_order.size() != n)
        compute_nested_dissection();
      with_mumps([this](auto &m) {
        m.mumps.perm_in         = pivot_order.data();
        m.mumps.icntl[icntl(7)] = 1;
      });
    }

    void
    compute_nested_dissection()
    {
      // The graph of the lower triangle's off-diagonal entries, both ways, in METIS's CSR.
      const idx_t        n = this->n;
      std::vector<idx_t> start(n + 1, 0);
      for (std::size_t e = 0; e < rows.size(); ++e)
        if (rows[e] != columns[e])
          {
            ++start[rows[e]];
            ++start[columns[e]];
          }
      for (idx_t i = 0; i < n; ++i)
        start[i + 1] += start[i];
      std::vector<idx_t> adjacency(start[n]), next(start.begin(), start.end() - 1);
      for (std::size_t e = 0; e < rows.size(); ++e)
        if (rows[e] != columns[e])
          {
            adjacency[next[rows[e] - 1]++]    = columns[e] - 1;
            adjacency[next[columns[e] - 1]++] = rows[e] - 1;
          }
      std::vector<idx_t> permutation(n), inverse(n);
      idx_t              options[METIS_NOPTIONS];
      METIS_SetDefaultOptions(options);
      idx_t n_vertices = n;
      if (n > 0 && METIS_NodeND(&n_vertices,
                                start.data(),
                                adjacency.data(),
                                nullptr,
                                options,
                                permutation.data(),
                                inverse.data()) != METIS_OK)
        throw std::runtime_error("METIS_NodeND failed to order a matrix of size " +
                                 std::to_string(n));
      // MUMPS's PERM_IN(i): the position of unknown i in the pivot order.
      pivot_order.resize(n);
      for (idx_t i = 0; i < n; ++i)
        pivot_order[i] = inverse[i] + 1;
    }

    /**
     * The analysis (ordering and symbolic factorisation) of the gathered entries. With
     * Ordering::fewest_flops both orderings are analysed and the one whose factorisation MUMPS
     * estimates cheaper (RINFOG(1)) is kept, where that factorisation repays the second analysis:
     * neither ordering wins on every body (a slender column favours MUMPS's, a compact cube the
     * nested dissection), but METIS and the second analysis cost about twice a 2D factorisation
     * (doc/performance.md, "The ordering of the direct solver").
     */
    void
    analyse()
    {
      pivot_order.clear();
      use_compression();
      if (distributed || ordering != Ordering::nested_dissection)
        use_mumps_ordering();
      else
        use_nested_dissection();
      call(1);
      if (distributed || ordering != Ordering::fewest_flops)
        return;
      // MUMPS's own first: where it loses (compact 3D bodies) the nested dissection's analysis is
      // the one kept and no third analysis is needed.
      const double mumps_flops = estimated_flops();
      if (mumps_flops < comparison_threshold * static_cast<double>(rows.size()))
        return;
      use_nested_dissection();
      call(1);
      if (mumps_flops <= estimated_flops())
        {
          use_mumps_ordering();
          call(1);
        }
    }

    /**
     * Block low-rank compression of the fronts (ICNTL(35) = 2: in the factorisation and the
     * solution) at the dropping threshold CNTL(7), which MUMPS reads at the analysis; the
     * contribution blocks are compressed too (ICNTL(37) = 1), since the full-rank fronts and
     * their contribution blocks, not the factors, set the peak memory of a 3D factorisation.
     */
    void
    use_compression()
    {
      with_mumps([this](auto &m) {
        m.mumps.icntl[icntl(35)] = compression > 0. ? 2 : 0;
        m.mumps.icntl[icntl(37)] = compression > 0. ? 1 : 0;
        m.mumps.cntl[6]          = compression; // CNTL(7)
      });
    }

    /** INFOG(@p i), 1-based. */
    MUMPS_INT
    infog(const int i) const
    {
      return with_mumps([i](const auto &m) {
        return m.mumps.infog[i - 1];
      });
    }

    /** RINFOG(@p i), 1-based. */
    double
    rinfog(const int i) const
    {
      return with_mumps([i](const auto &m) {
        return static_cast<double>(m.mumps.rinfog[i - 1]);
      });
    }

    double
    estimated_flops() const
    {
      return rinfog(1);
    }

    /** An entry of INFOG that counts entries, read through MUMPS's convention for large
     * values (negative: millions). */
    double
    infog_count(const int i) const
    {
      const MUMPS_INT value = infog(i);
      return value < 0 ? -1e6 * value : static_cast<double>(value);
    }

    void
    call(const int job)
    {
      with_mumps([job](auto &m) {
        m.call(job);
      });
    }

    /** Rank 0's @p x on every rank. */
    void
    broadcast(dealii::Vector<double> &x) const
    {
      if (distributed)
        {
          const int ierr = MPI_Bcast(x.begin(), x.size(), MPI_DOUBLE, 0, communicator);
          AssertThrowMPI(ierr);
        }
    }

    /** K x for the gathered lower triangle (on several ranks: this rank's rows), summed over the
     * ranks. */
    dealii::Vector<double>
    multiply(const dealii::Vector<double> &x) const
    {
      dealii::Vector<double> y(x.size());
      for (std::size_t e = 0; e < values.size(); ++e)
        {
          const unsigned int row = rows[e] - 1, column = columns[e] - 1;
          y(row) += values[e] * x(column);
          if (row != column)
            y(column) += values[e] * x(row);
        }
      if (distributed)
        {
          const int ierr =
            MPI_Allreduce(MPI_IN_PLACE, y.begin(), y.size(), MPI_DOUBLE, MPI_SUM, communicator);
          AssertThrowMPI(ierr);
        }
      return y;
    }

    /**
     * Solve K x = b (b in @p x on entry, rank 0's) with the single-precision factors, refined
     * in double precision (x += K~^{-1} (b - K x)) until the residual stops shrinking by half
     * or is within @p target of b. Throws RefinementFailure when it stops above @p target and
     * refinement_acceptance: the factors are then too inexact for this matrix (a condition
     * number near the reciprocal of single precision's 6e-8).
     */
    void
    solve_refined(dealii::Vector<double> &x, const double target)
    {
      broadcast(x);
      const dealii::Vector<double> b       = x;
      const double                 b_norm  = b.l2_norm();
      x                                    = 0.;
      dealii::Vector<double> residual      = b;
      double                 residual_norm = b_norm;
      refinement_steps                     = 0;
      while (residual_norm > target * b_norm)
        {
          // Scaled to unit norm, so that single precision neither underflows nor overflows.
          dealii::Vector<double> correction = residual;
          correction /= residual_norm;
          reduced.solve(correction);
          broadcast(correction);
          x.add(residual_norm, correction);
          ++refinement_steps;
          residual = b;
          residual -= multiply(x);
          const double last = residual_norm;
          residual_norm     = residual.l2_norm();
          if (!(residual_norm <= 0.5 * last) || refinement_steps == 30)
            break;
        }
      if (!(residual_norm <=
            std::max(target, SymmetricFactorization::refinement_acceptance) * b_norm))
        {
          std::ostringstream why;
          why.precision(2);
          why << "the single-precision factorisation's refinement stopped at a relative "
                 "residual of "
              << residual_norm / b_norm << " after " << refinement_steps << " steps";
          throw RefinementFailure(why.str());
        }
    }
  };


  SymmetricFactorization::SymmetricFactorization()
    : data(std::make_unique<Data>())
  {}


  SymmetricFactorization::~SymmetricFactorization()
  {
    if (data)
      {
        data->full.finish();
        data->reduced.finish();
      }
  }


  double
  SymmetricFactorization::estimated_memory(const dealii::TrilinosWrappers::SparseMatrix &K)
  {
    data->factorized = false;
    if (!data->started)
      data->start(K.get_mpi_communicator());
    data->gather(K, K.m());
    data->analyse();
    // INFOG(17): MB (10^6 bytes) for the in-core factorisation, all ranks.
    return 1e6 * data->infog(17);
  }


  void
  SymmetricFactorization::factorize(const dealii::TrilinosWrappers::SparseMatrix &K,
                                    const unsigned int                            leading)
  {
    data->factorized = false;
    if (!data->started)
      data->start(K.get_mpi_communicator());
    else if (data->communicator != K.get_mpi_communicator())
      throw std::logic_error("SymmetricFactorization::factorize() with a matrix on another "
                             "communicator than the first");
    data->gather(K, std::min<unsigned int>(leading, K.m()));
    data->analyse();
    data->call(2);
    data->factorized = true;
  }


  SymmetricFactorization::Ordering
  SymmetricFactorization::parse_ordering(const std::string &name)
  {
    if (name == "fewest flops")
      return Ordering::fewest_flops;
    if (name == "nested dissection")
      return Ordering::nested_dissection;
    if (name == "MUMPS")
      return Ordering::automatic;
    throw std::invalid_argument("unknown ordering '" + name +
                                "' (fewest flops, nested dissection or MUMPS)");
  }


  void
  SymmetricFactorization::set_ordering(const Ordering ordering)
  {
    data->ordering = ordering;
  }


  void
  SymmetricFactorization::set_comparison_threshold(const double flops_per_entry)
  {
    data->comparison_threshold = flops_per_entry;
  }


  double
  SymmetricFactorization::factorization_flops() const
  {
    return data->rinfog(3);
  }


  void
  SymmetricFactorization::set_compression(const double dropping_threshold)
  {
    if (!(dropping_threshold >= 0.) || dropping_threshold >= 1.)
      throw std::invalid_argument("the dropping threshold of a block low-rank factorisation "
                                  "lies in [0, 1)");
    data->compression = dropping_threshold;
  }


  double
  SymmetricFactorization::compression() const
  {
    return data->compression;
  }


  FactorStatistics
  SymmetricFactorization::statistics() const
  {
    if (!data->factorized)
      throw std::logic_error("SymmetricFactorization::statistics() before factorize()");
    FactorStatistics result;
    result.full_rank_flops   = data->rinfog(3);
    result.flops             = data->rinfog(14); // the compressed blocks' own
    result.full_rank_entries = data->infog_count(29);
    result.entries = data->compression > 0. ? data->infog_count(35) : result.full_rank_entries;
    result.memory  = 1e6 * data->infog(22); // MB on all ranks
    if (result.flops <= 0.)
      result.flops = result.full_rank_flops;
    return result;
  }


  double
  SymmetricFactorization::estimated_flops() const
  {
    return data->estimated_flops();
  }


  std::string
  SymmetricFactorization::ordering_used() const
  {
    // INFOG(7), MUMPS's numbering of its orderings (1: given, here the nested dissection).
    switch (data->infog(7))
      {
        case 0:
          return "AMD ordering";
        case 1:
          return "nested dissection";
        case 2:
          return "AMF ordering";
        case 3:
          return "SCOTCH ordering";
        case 4:
          return "PORD ordering";
        case 5:
          return "METIS ordering";
        case 6:
          return "QAMD ordering";
        default:
          return "ordering " + std::to_string(data->infog(7));
      }
  }


  void
  SymmetricFactorization::refactorize(const dealii::TrilinosWrappers::SparseMatrix &K)
  {
    if (!data->factorized)
      throw std::logic_error("SymmetricFactorization::refactorize() before factorize()");
    const std::size_t n_entries = data->values.size();
    data->gather(K, data->n);
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
    Inertia result;
    result.n_negative = data->infog(12);
    result.n_zero     = data->infog(28);
    result.n_positive = data->n - result.n_negative - result.n_zero;
    return result;
  }


  void
  SymmetricFactorization::solve(dealii::Vector<double> &x, const double refinement_target) const
  {
    if (!data->factorized)
      throw std::logic_error("SymmetricFactorization::solve() before factorize()");
    if (data->precision == Precision::single_precision)
      {
        data->solve_refined(x, std::max(refinement_target, refinement_tolerance));
        return;
      }
    data->full.solve(x);
    if (data->distributed)
      {
        const int ierr = MPI_Bcast(x.begin(), x.size(), MPI_DOUBLE, 0, data->communicator);
        AssertThrowMPI(ierr);
      }
  }


  unsigned int
  SymmetricFactorization::size() const
  {
    return data->n;
  }


  void
  SymmetricFactorization::set_precision(const Precision precision)
  {
    if (data->started && precision != data->precision)
      throw std::logic_error("SymmetricFactorization::set_precision() after the first analysis");
    data->precision = precision;
  }


  SymmetricFactorization::Precision
  SymmetricFactorization::precision() const
  {
    return data->precision;
  }


  unsigned int
  SymmetricFactorization::refinement_steps() const
  {
    return data->refinement_steps;
  }
} // namespace GelMPM
