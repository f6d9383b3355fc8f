// The threshold of SymmetricFactorization's default ordering ("fewest flops"): the nested
// dissection is analysed only where MUMPS's own ordering (AMF) estimates at least
// default_comparison_threshold flops per stored entry. On the 7-point Laplacian of a 20^3 grid
// (8,000 unknowns, far above the threshold) the nested dissection needs fewer flops than AMF, so
// the choice shows: the default must take the nested dissection's flops, and with the comparison
// switched off (an unreachable threshold) AMF's. On the 5-point Laplacian of a 40^2 grid (below the
// threshold) the default must keep AMF's flops. Set ORDERING_PRINT to print the figures.
#include <gelmpm/stability/symmetric_factorization.h>

#include <deal.II/base/mpi.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <limits>
#include <string>

using namespace dealii;
using GelMPM::SymmetricFactorization;

namespace
{
  /** The 2 dim + 1-point Laplacian of an m^dim grid (Dirichlet outside), shifted to stay definite.
   */
  void
  laplacian(const unsigned int dim, const unsigned int m, TrilinosWrappers::SparseMatrix &K)
  {
    const unsigned int n = std::pow(m, dim);
    // The neighbour of unknown i along axis d at offset s (+1 or -1), or n if outside.
    const auto neighbour = [&](const unsigned int i, const unsigned int d, const int s) {
      const unsigned int stride = std::pow(m, d), coordinate = (i / stride) % m;
      if ((s < 0 && coordinate == 0) || (s > 0 && coordinate + 1 == m))
        return n;
      return s > 0 ? i + stride : i - stride;
    };
    DynamicSparsityPattern dsp(n, n);
    for (unsigned int i = 0; i < n; ++i)
      {
        dsp.add(i, i);
        for (unsigned int d = 0; d < dim; ++d)
          for (const int s : {-1, 1})
            if (const unsigned int j = neighbour(i, d, s); j < n)
              dsp.add(i, j);
      }
    SparsityPattern sp;
    sp.copy_from(dsp);
    K.reinit(sp);
    for (unsigned int i = 0; i < n; ++i)
      {
        K.set(i, i, 2. * dim + 0.1);
        for (unsigned int d = 0; d < dim; ++d)
          for (const int s : {-1, 1})
            if (const unsigned int j = neighbour(i, d, s); j < n)
              K.set(i, j, -1.);
      }
    K.compress(VectorOperation::insert);
  }


  /** The stored entries of the lower triangle of @p K (what MUMPS is given). */
  double
  lower_entries(const TrilinosWrappers::SparseMatrix &K)
  {
    double count = 0;
    for (auto entry = K.begin(); entry != K.end(); ++entry)
      count += entry->column() <= entry->row();
    return count;
  }


  bool
  check(const std::string &name, const unsigned int dim, const unsigned int m)
  {
    TrilinosWrappers::SparseMatrix K;
    laplacian(dim, m, K);
    SymmetricFactorization nested, automatic, by_default, never;
    nested.set_ordering(SymmetricFactorization::Ordering::nested_dissection);
    automatic.set_ordering(SymmetricFactorization::Ordering::automatic);
    never.set_comparison_threshold(std::numeric_limits<double>::max());
    for (auto *f : {&nested, &automatic, &by_default, &never})
      f->factorize(K);
    const double per_entry = automatic.estimated_flops() / lower_entries(K);
    const bool   compares  = per_entry >= SymmetricFactorization::default_comparison_threshold;
    const double cheaper  = std::min(nested.factorization_flops(), automatic.factorization_flops());
    const double expected = compares ? cheaper : automatic.factorization_flops();
    const auto   same     = [](const double a, const double b) {
      return std::abs(a - b) <= 1e-12 * b;
    };
    if (std::getenv("ORDERING_PRINT"))
      std::cerr << name << ": n = " << K.m() << ", AMF " << automatic.factorization_flops()
                << " flops (" << per_entry << " per entry), nested dissection "
                << nested.factorization_flops() << ", default " << by_default.factorization_flops()
                << " (" << by_default.ordering_used() << "), never compared "
                << never.factorization_flops() << std::endl;
    std::cout << name << std::endl
              << "  above the threshold: " << (compares ? "yes" : "no") << std::endl
              << "  the default takes " << (compares ? "the cheaper" : "AMF's") << " flops: "
              << (same(by_default.factorization_flops(), expected) ? "yes" : "no  FAIL")
              << std::endl
              << "  the nested dissection the cheaper: "
              << (nested.factorization_flops() < automatic.factorization_flops() ? "yes" : "no")
              << std::endl
              << "  without the comparison, AMF's: "
              << (same(never.factorization_flops(), automatic.factorization_flops()) ? "yes"
                                                                                     : "no  FAIL")
              << std::endl;
    // 20^3 must keep the nested dissection the cheaper, or the default's choice would not show.
    if (dim == 3 && nested.factorization_flops() >= automatic.factorization_flops())
      return false;
    return same(by_default.factorization_flops(), expected) &&
           same(never.factorization_flops(), automatic.factorization_flops());
  }
} // namespace


int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bool                             ok = check("3D, 20^3", 3, 20);
  ok &= check("2D, 40^2", 2, 40);
  std::cout << (ok ? "threshold checks passed" : "THRESHOLD CHECKS FAILED") << std::endl;
  return ok ? 0 : 1;
}
