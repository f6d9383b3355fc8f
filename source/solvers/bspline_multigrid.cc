#include <gelmpm/solvers/bspline_multigrid.h>
#include <gelmpm/stability/matrix_entries.h>

#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/multigrid/mg_matrix.h>

#include <stdexcept>

namespace GelMPM
{
  class BSplineMultigrid::Transfer : public dealii::MGTransferBase<dealii::Vector<double>>
  {
  public:
    explicit Transfer(
      const std::vector<std::unique_ptr<dealii::TrilinosWrappers::SparseMatrix>> &prolongations)
      : prolongations(prolongations)
    {}

    void
    prolongate(const unsigned int            to_level,
               dealii::Vector<double>       &dst,
               const dealii::Vector<double> &src) const override
    {
      prolongations[to_level - 1]->vmult(dst, src);
    }

    void
    restrict_and_add(const unsigned int            from_level,
                     dealii::Vector<double>       &dst,
                     const dealii::Vector<double> &src) const override
    {
      prolongations[from_level - 1]->Tvmult_add(dst, src);
    }

  private:
    const std::vector<std::unique_ptr<dealii::TrilinosWrappers::SparseMatrix>> &prolongations;
  };


  class BSplineMultigrid::CoarseSolve : public dealii::MGCoarseGridBase<dealii::Vector<double>>
  {
  public:
    explicit CoarseSolve(const BSplineMultigrid &multigrid)
      : multigrid(multigrid)
    {}

    void
    operator()(const unsigned int,
               dealii::Vector<double>       &dst,
               const dealii::Vector<double> &src) const override
    {
      if (multigrid.direct)
        multigrid.coarse_direct.vmult(dst, src);
      else
        multigrid.coarse_amg.preconditioner().vmult(dst, src);
    }

  private:
    const BSplineMultigrid &multigrid;
  };


  namespace
  {
    /** The prolongation of @p level times the identity on @p dim interleaved components. */
    std::unique_ptr<dealii::TrilinosWrappers::SparseMatrix>
    vector_prolongation(const NestedBSplineLevel &level, const unsigned int dim)
    {
      const unsigned int             n_rows = dim * level.n_rows;
      const unsigned int             n_cols = dim * level.control_points.size();
      const SparseEntries           &P      = level.prolongation;
      dealii::DynamicSparsityPattern pattern(n_rows, n_cols);
      for (std::size_t k = 0; k < P.size(); ++k)
        for (unsigned int c = 0; c < dim; ++c)
          pattern.add(dim * P.rows[k] + c, dim * P.columns[k] + c);
      auto matrix = std::make_unique<dealii::TrilinosWrappers::SparseMatrix>();
      matrix->reinit(pattern);
      for (std::size_t k = 0; k < P.size(); ++k)
        for (unsigned int c = 0; c < dim; ++c)
          matrix->set(dim * P.rows[k] + c, dim * P.columns[k] + c, P.values[k]);
      matrix->compress(dealii::VectorOperation::insert);
      return matrix;
    }
  } // namespace


  BSplineMultigrid::BSplineMultigrid() = default;


  BSplineMultigrid::~BSplineMultigrid() = default;


  void
  BSplineMultigrid::setup(const dealii::TrilinosWrappers::SparseMatrix &K,
                          const unsigned int                            n_u,
                          const unsigned int                            dim,
                          const std::vector<NestedBSplineLevel>        &levels,
                          const Settings                               &settings)
  {
    clear();
    if (levels.size() > 0 && dim * levels[0].n_rows != n_u)
      throw std::logic_error("BSplineMultigrid: the levels are not those of these unknowns");
    // Coarsen until a level is small enough to factorise: below it, more levels would only
    // replace an exact solve by an approximate one.
    unsigned int n_coarse = 0;
    if (n_u > settings.direct_coarse_size)
      while (n_coarse < levels.size())
        if (dim * levels[n_coarse++].control_points.size() <= settings.direct_coarse_size)
          break;
    const unsigned int finest = n_coarse;
    matrices.resize(0, finest);
    copy_leading_block(K, n_u, matrices[finest]);
    prolongations.resize(finest);
    for (unsigned int k = 0; k < n_coarse; ++k)
      {
        const unsigned int fine = finest - k;
        prolongations[fine - 1] = vector_prolongation(levels[k], dim);
        dealii::TrilinosWrappers::SparseMatrix AP;
        matrices[fine].mmult(AP, *prolongations[fine - 1]);
        prolongations[fine - 1]->Tmmult(matrices[fine - 1], AP);
      }

    const dealii::TrilinosWrappers::SparseMatrix &A0 = matrices[0];
    direct                                           = A0.m() <= settings.direct_coarse_size;
    if (direct)
      {
        dealii::DynamicSparsityPattern pattern(A0.m(), A0.n());
        for_each_entry(A0, A0.m(), [&](const unsigned int i, const unsigned int j, const double) {
          pattern.add(i, j);
        });
        coarse_pattern.copy_from(pattern);
        coarse_matrix.reinit(coarse_pattern);
        for_each_entry(A0, A0.m(), [&](const unsigned int i, const unsigned int j, const double v) {
          coarse_matrix.set(i, j, v);
        });
        try
          {
            coarse_direct.initialize(coarse_matrix);
          }
        catch (const std::exception &e)
          {
            throw std::runtime_error(std::string("the coarsest level of the displacement "
                                                 "multigrid is singular: ") +
                                     e.what());
          }
      }
    else if (n_coarse > 0)
      coarse_amg.setup(A0, A0.m(), dim, levels[n_coarse - 1].greville_points);
    else
      throw std::logic_error("BSplineMultigrid: no coarse level for a matrix too large to "
                             "factorise");

    level_matrices = std::make_unique<dealii::mg::Matrix<dealii::Vector<double>>>(matrices);
    transfer       = std::make_unique<Transfer>(prolongations);
    coarse         = std::make_unique<CoarseSolve>(*this);
    if (settings.cell_blocks)
      smoother = block_smoother(levels, dim, settings);
    else
      {
        auto relaxation = std::make_unique<Smoother>(settings.smoothing_steps, false, false, false);
        relaxation->initialize(matrices,
                               dealii::TrilinosWrappers::PreconditionSSOR::AdditionalData());
        smoother = std::move(relaxation);
      }
    multigrid = std::make_unique<dealii::Multigrid<dealii::Vector<double>>>(
      *level_matrices,
      *coarse,
      *transfer,
      *smoother,
      *smoother,
      0,
      finest,
      settings.w_cycle ? dealii::Multigrid<dealii::Vector<double>>::w_cycle
                       : dealii::Multigrid<dealii::Vector<double>>::v_cycle);
    for (unsigned int l = 0; l <= finest; ++l)
      multigrid->defect[l].reinit(matrices[l].m());
  }


  std::unique_ptr<dealii::MGSmootherBase<dealii::Vector<double>>>
  BSplineMultigrid::block_smoother(const std::vector<NestedBSplineLevel> &levels,
                                   const unsigned int                     dim,
                                   const Settings                        &settings)
  {
    const unsigned int finest = matrices.max_level();
    block_patterns.resize(0, finest);
    block_matrices.resize(0, finest);
    block_data.resize(0, finest);
    for (unsigned int l = 0; l <= finest; ++l)
      {
        const auto                    &A = matrices[l];
        dealii::DynamicSparsityPattern pattern(A.m(), A.n());
        for_each_entry(A, A.m(), [&](const unsigned int i, const unsigned int j, const double) {
          pattern.add(i, j);
        });
        block_patterns[l].copy_from(pattern);
        block_matrices[l].reinit(block_patterns[l]);
        for_each_entry(A, A.m(), [&](const unsigned int i, const unsigned int j, const double v) {
          block_matrices[l].set(i, j, v);
        });
        // The coarsest level is solved, not smoothed: one trivial block each.
        const std::vector<std::vector<unsigned int>> none;
        const auto                    &blocks   = l > 0 ? levels[finest - l].row_blocks : none;
        const unsigned int             n_blocks = l > 0 ? blocks.size() : A.m();
        dealii::DynamicSparsityPattern block_list(n_blocks, A.m());
        for (unsigned int b = 0; b < n_blocks; ++b)
          if (l > 0)
            for (const unsigned int f : blocks[b])
              for (unsigned int c = 0; c < dim; ++c)
                block_list.add(b, dim * f + c);
          else
            block_list.add(b, b);
        block_data[l].block_list.copy_from(block_list);
        block_data[l].relaxation = 1.;
        block_data[l].inversion  = dealii::PreconditionBlockBase<double>::householder;
      }
    auto relaxation =
      std::make_unique<BlockSmoother>(settings.smoothing_steps, false, false, false);
    relaxation->initialize(block_matrices, block_data);
    return relaxation;
  }


  void
  BSplineMultigrid::clear()
  {
    // The cycle refers to the smoother, transfer and matrices: it goes first.
    multigrid.reset();
    smoother.reset();
    coarse.reset();
    transfer.reset();
    level_matrices.reset();
    coarse_amg.clear();
    coarse_matrix.clear();
    block_data.resize(0, 0);
    block_matrices.resize(0, 0);
    block_patterns.resize(0, 0);
    prolongations.clear();
    matrices.resize(0, 0);
    matrices[0].clear();
  }


  void
  BSplineMultigrid::vmult(dealii::Vector<double> &dst, const dealii::Vector<double> &src) const
  {
    const unsigned int finest = matrices.max_level();
    // The cycle adds the restricted residuals to the coarse defects: they start from zero, as
    // deal.II's PreconditionMG leaves them.
    for (unsigned int l = 0; l < finest; ++l)
      multigrid->defect[l] = 0.;
    multigrid->defect[finest] = src;
    multigrid->cycle();
    dst = multigrid->solution[finest];
  }


  std::vector<unsigned int>
  BSplineMultigrid::level_sizes() const
  {
    std::vector<unsigned int> sizes;
    for (unsigned int l = matrices.max_level() + 1; l-- > 0;)
      sizes.push_back(matrices[l].m());
    return sizes;
  }


  bool
  BSplineMultigrid::direct_coarse_solve() const
  {
    return direct;
  }
} // namespace GelMPM
