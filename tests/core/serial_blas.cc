// SerialBlasScope (include/gelmpm/core/serial_blas.h): inside the scope the BLAS runs on one
// thread, after it the thread count is what it was. Where the BLAS is OpenBLAS (the project's
// set-up installs libopenblas0-pthread) its count is first set to 2 through OpenBLAS's own
// openblas_set_num_threads (the tests run with OPENBLAS_NUM_THREADS=1), so that the scope has
// something to change and to restore; nested scopes restore in order. With another BLAS the scope
// does nothing and the count reads 1 throughout. A product computed inside the scope equals the
// one outside (dgemm through deal.II's FullMatrix::mmult, which calls the BLAS). The run's
// default (use_one_thread_unless_set) leaves a count the environment sets and else sets one.
#include <gelmpm/core/serial_blas.h>

#include <deal.II/lac/full_matrix.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <dlfcn.h>
#include <iostream>

int
main()
{
  using GelMPM::SerialBlasScope;
  std::cout << std::boolalpha;
  const auto set = reinterpret_cast<void (*)(int)>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads"));
  const int  before = SerialBlasScope::controls_threads() ? 2 : 1;
  if (SerialBlasScope::controls_threads() && set != nullptr)
    set(2);
  std::cout << "the count before the scope: " << (SerialBlasScope::threads() == before) << '\n';

  dealii::FullMatrix<double> a(64, 64), b(64, 64), outside(64, 64), inside(64, 64);
  for (unsigned int i = 0; i < 64; ++i)
    for (unsigned int j = 0; j < 64; ++j)
      {
        a(i, j) = 1. / (1. + i + 2. * j);
        b(i, j) = (i == j ? 2. : 0.) + 1e-3 * (i + j);
      }
  a.mmult(outside, b);
  {
    const SerialBlasScope scope;
    std::cout << "one thread inside the scope: " << (SerialBlasScope::threads() == 1) << '\n';
    {
      const SerialBlasScope nested;
      std::cout << "one thread inside a nested scope: " << (SerialBlasScope::threads() == 1)
                << '\n';
    }
    std::cout << "still one after the nested scope: " << (SerialBlasScope::threads() == 1) << '\n';
    a.mmult(inside, b);
  }
  std::cout << "the count restored after the scope: " << (SerialBlasScope::threads() == before)
            << '\n';
  double difference = 0.;
  for (unsigned int i = 0; i < 64; ++i)
    for (unsigned int j = 0; j < 64; ++j)
      difference = std::max(difference, std::abs(inside(i, j) - outside(i, j)));
  // The same kernel on fewer threads sums in the same order per entry; allow round-off.
  std::cout << "the product inside equals the one outside to 1e-14: " << (difference < 1e-14)
            << '\n';

  // The run's default: one thread unless the environment sets the count.
  if (SerialBlasScope::controls_threads() && set != nullptr)
    set(2);
  setenv("OMP_NUM_THREADS", "2", 1);
  unsetenv("OPENBLAS_NUM_THREADS");
  unsetenv("GOTO_NUM_THREADS");
  const bool with_environment = SerialBlasScope::use_one_thread_unless_set();
  std::cout << "a count set in the environment is left: "
            << (!with_environment && SerialBlasScope::threads() == before) << '\n';
  unsetenv("OMP_NUM_THREADS");
  const bool without = SerialBlasScope::use_one_thread_unless_set();
  std::cout << "without one, one thread: "
            << (without == SerialBlasScope::controls_threads() && SerialBlasScope::threads() == 1)
            << '\n';
  return 0;
}
